#ifndef KSE_MESSAGING_BLACKBOARD_H
#define KSE_MESSAGING_BLACKBOARD_H

#include <atomic>
#include <chrono>
#include <cstddef>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <vector>

#include <google/protobuf/message.h>

#include "kse/messaging/Clock.h"
#include "kse/messaging/Kind.h"
#include "kse/messaging/MessageHub.h"
#include "kse/messaging/SpinLock.h"

namespace kse::messaging {

template <class T>
class Reader;

/// One entry of a Data history.
template <class T>
struct Stamped {
  TimePoint time;
  std::shared_ptr<const T> message;
};

/// The messages one scope sees (the statechart root and every AND region own one), as Monas'
/// Narukom blackboards did: a snapshot. A message published by others waits in the
/// blackboard's inbox and becomes visible to its readers only when ProcessMessages() runs on
/// it; a message published through this blackboard is visible here at once. Messages are keyed
/// by topic and protobuf full type name; each blackboard keeps its own signal queues, so two
/// blackboards each see a signal once. Thread-safe.
///
/// A blackboard also keeps the wake-up times its TimeoutActions asked for, so the engine that
/// owns it knows when to re-evaluate (see statechart_engine::SetTimeout).
///
/// Every statechart has one and every AND region another, and most never hold a message: a
/// blackboard is 32 bytes (its hub, its name, a pointer; a name over 15 characters is copied to
/// the heap) until its first subscription, publish, bound reader or wake-up makes what it holds.
class Blackboard {
 public:
  using MessagePtr = std::shared_ptr<const google::protobuf::Message>;

  /// Most recent entries kept per Data key.
  static constexpr std::size_t kDataHistoryLimit = 100;
  /// Unread signals kept per Signal key; when full the oldest unread one is dropped.
  static constexpr std::size_t kSignalQueueLimit = 1000;

  explicit Blackboard(MessageHub& hub, const std::string& name = {});
  ~Blackboard();
  Blackboard(const Blackboard&) = delete;
  Blackboard& operator=(const Blackboard&) = delete;

  /// Receive the messages published on a topic from now on (plus the topic's current State
  /// messages), into the inbox. Idempotent.
  void Subscribe(const std::string& topic);
  bool IsSubscribed(const std::string& topic) const;

  /// Makes what arrived since the last call visible to the readers: State messages replace
  /// the previous ones, Signals join their queues, Data entries their histories. The
  /// `process_messages` action of a transition and every `TimeoutCheck` guard call it; an
  /// activity calls it at the start of Execute() to see the latest messages.
  void ProcessMessages();
  /// Messages waiting in the inbox.
  std::size_t PendingMessages() const;

  /// The last State message of that topic and type, or nullptr.
  template <class T>
  std::shared_ptr<const T> ReadState(const std::string& topic) {
    std::shared_ptr<const T> out;
    ReadStateTo(topic, TypeName<T>(), &Take<T>, &out);
    return out;
  }

  /// The oldest unread Signal of that topic and type, consumed by this read; nullptr when none.
  template <class T>
  std::shared_ptr<const T> ReadSignal(const std::string& topic) {
    std::shared_ptr<const T> out;
    ReadSignalTo(topic, TypeName<T>(), &Take<T>, &out);
    return out;
  }

  /// The newest Data entry of that topic and type, or nullptr.
  template <class T>
  std::shared_ptr<const T> ReadData(const std::string& topic) {
    std::shared_ptr<const T> out;
    ReadDataTo(topic, TypeName<T>(), &Take<T>, &out);
    return out;
  }

  /// Every Data entry of that topic and type stamped at or after `since`, oldest first.
  template <class T>
  std::vector<Stamped<T>> ReadDataHistory(const std::string& topic, TimePoint since) {
    std::vector<Stamped<T>> out;
    for (auto& entry : ReadDataHistoryMessages(topic, TypeName<T>(), since)) {
      if (auto typed = std::dynamic_pointer_cast<const T>(entry.message)) {
        out.push_back(Stamped<T>{entry.time, std::move(typed)});
      }
    }
    return out;
  }

  /// Publishes a copy of the message: visible on this blackboard at once, delivered through
  /// the hub to the inboxes of the other blackboards subscribed to the topic.
  template <class T>
  void Publish(const std::string& topic, Kind kind, const T& message) {
    if constexpr (std::is_final_v<T> && !std::is_abstract_v<T>) {
      // A generated message class (final): the copy and its count in one allocation, copied
      // by the class's own code rather than through reflection.
      PublishMessage(topic, kind, std::make_shared<T>(message));
    } else {
      PublishCopy(topic, kind, message);
    }
  }

  /// Asks the owning engine to re-evaluate at that time (each call is one wake-up: a timer
  /// restarted before it expired still wakes the engine at its first time too, as Monas'
  /// timeout workers did).
  void ScheduleWakeup(TimePoint time);
  /// The earliest wake-up not yet taken, if any.
  std::optional<TimePoint> NextWakeup() const;
  /// Removes the wake-ups due at `now`; true when there was one.
  bool TakeDueWakeups(TimePoint now);

  // -- untyped access (what the templates use) --------------------------------------------
  MessagePtr ReadStateMessage(const std::string& topic, const std::string& type_name) const;
  MessagePtr ReadSignalMessage(const std::string& topic, const std::string& type_name);
  MessagePtr ReadDataMessage(const std::string& topic, const std::string& type_name) const;
  std::vector<Stamped<google::protobuf::Message>> ReadDataHistoryMessages(
      const std::string& topic, const std::string& type_name, TimePoint since) const;
  void PublishMessage(const std::string& topic, Kind kind, MessagePtr message);
  /// The same for a message of a generated class (they are final), whose type name is then
  /// looked up once per class instead of through the message's descriptor on every publish.
  template <class T, std::enable_if_t<std::is_final_v<T> &&
                                          std::is_base_of_v<google::protobuf::Message, T>,
                                      int> = 0>
  void PublishMessage(const std::string& topic, Kind kind, std::shared_ptr<T> message) {
    if (!message) {
      return;
    }
    PublishNamed(topic, TypeName<std::remove_cv_t<T>>(), kind, std::move(message));
  }
  void PublishCopy(const std::string& topic, Kind kind, const google::protobuf::Message& message);

  /// Number of unread signals of that topic and type.
  std::size_t PendingSignals(const std::string& topic, const std::string& type_name) const;

  MessageHub& Hub() const noexcept { return *hub_; }
  std::string Name() const;
  TimePoint Now() const { return hub_->GetClock().Now(); }

  template <class T>
  static const std::string& TypeName() {
    // Asked on every read: looked up once per class (through a once-flag on each call otherwise).
    return MessageHub::TypeNameOf<T>();
  }

 private:
  friend class MessageHub;
  template <class T>
  friend class Reader;
  // A typed read hands the message it found, under the lock, to a function of its type: one
  // reference taken, no dynamic_cast when the message is of that very class.
  using Sink = void (*)(const MessagePtr& found, void* out);
  template <class T>
  static void Take(const MessagePtr& found, void* out) {
    auto& typed = *static_cast<std::shared_ptr<const T>*>(out);
    if (typeid(*found) == typeid(T)) {
      typed = std::shared_ptr<const T>(found, static_cast<const T*>(found.get()));
    } else {
      typed = std::dynamic_pointer_cast<const T>(found);
    }
  }
  void ReadStateTo(const std::string& topic, const std::string& type_name, Sink sink, void* out) const;
  void ReadSignalTo(const std::string& topic, const std::string& type_name, Sink sink, void* out);
  void ReadDataTo(const std::string& topic, const std::string& type_name, Sink sink, void* out) const;

  void PublishNamed(const std::string& topic, const std::string& type_name, Kind kind, MessagePtr message);

  struct Slot;
  // What the blackboard holds: topics, messages, the inbox, wake-ups, and the lock that guards
  // them. Made by the first subscription, publish, bound reader or wake-up.
  struct Contents;
  // What a Reader does: its key's slot, made now if no message has come yet (a slot, once
  // made, lives as long as the blackboard), then reads there without looking the key up.
  Slot* SlotOf(const std::string& topic, const std::string& type_name);
  static void ReadStateAt(Contents* contents, Slot* slot, Sink sink, void* out);
  static void ReadSignalAt(Contents* contents, Slot* slot, Sink sink, void* out);
  static void ReadDataAt(Contents* contents, Slot* slot, Sink sink, void* out);

  // What the hub calls for each subscriber; Deliver() answers the key's slot, which the hub
  // keeps to deliver the next message of that topic and type with DeliverAt() (no lookup).
  Slot* Deliver(const std::string& topic, const std::string& type_name, Kind kind,
                const MessagePtr& message, TimePoint time);
  static void DeliverAt(Slot* slot, Kind kind, const MessagePtr& message, TimePoint time);

  struct Entry {
    MessagePtr message;
    TimePoint time;
  };
  // The contents, made now if they are not yet (by whichever thread comes first).
  Contents& Made();
  // The contents if made, else null: what a blackboard without them answers needs none.
  Contents* Peek() const noexcept { return contents_.load(std::memory_order_acquire); }
  // Callers hold the contents' lock.
  static Slot* Find(const Contents& contents, const std::string& topic, const std::string& type_name);
  static Slot& SlotFor(Contents& contents, const std::string& topic, const std::string& type_name);
  static void Apply(Slot& slot, Kind kind, const MessagePtr& message, TimePoint time);
  static void Queue(Contents& contents, Slot& slot, Kind kind, const MessagePtr& message, TimePoint time);

  MessageHub* hub_;
  std::atomic<Contents*> contents_{nullptr};  // owned; set once, never replaced
  // The name, in place when it fits (chart names and most state names do); a longer one is
  // copied to the heap, its address and length kept in the same bytes.
  static constexpr std::size_t kShortName = 15;
  static constexpr unsigned char kLongName = 0xFF;
  char name_[kShortName] = {};
  unsigned char name_size_ = 0;  // kLongName: name_ holds the copy's address and length
};

/// What an unbound Reader throws (std::logic_error naming the type).
[[noreturn]] void ThrowUnbound(const std::string& type_name);

/// A typed read of one topic on one blackboard, its key looked up once, at Bind(): what a
/// generated guard keeps for each message it reads (bound in UserInit()), so that Eval() goes
/// straight to the message. It reads exactly what the blackboard's ReadState<T>(topic),
/// ReadSignal<T>(topic) and ReadData<T>(topic) would: the same snapshot, under the same lock,
/// a shared_ptr the caller may keep. Valid as long as the blackboard; not thread-safe itself
/// (Bind it before others read through it).
template <class T>
class Reader {
 public:
  Reader() = default;
  Reader(Blackboard& blackboard, const std::string& topic) { Bind(blackboard, topic); }

  void Bind(Blackboard& blackboard, const std::string& topic) {
    slot_ = blackboard.SlotOf(topic, Blackboard::TypeName<T>());
    contents_ = blackboard.Peek();  // made by SlotOf
  }
  bool IsBound() const noexcept { return slot_ != nullptr; }

  /// As Blackboard::ReadState<T>(topic).
  std::shared_ptr<const T> ReadState() const {
    std::shared_ptr<const T> out;
    Blackboard::ReadStateAt(contents_, Bound(), &Blackboard::Take<T>, &out);
    return out;
  }
  /// As Blackboard::ReadSignal<T>(topic): consumes the signal.
  std::shared_ptr<const T> ReadSignal() const {
    std::shared_ptr<const T> out;
    Blackboard::ReadSignalAt(contents_, Bound(), &Blackboard::Take<T>, &out);
    return out;
  }
  /// As Blackboard::ReadData<T>(topic).
  std::shared_ptr<const T> ReadData() const {
    std::shared_ptr<const T> out;
    Blackboard::ReadDataAt(contents_, Bound(), &Blackboard::Take<T>, &out);
    return out;
  }

 private:
  Blackboard::Slot* Bound() const {
    if (slot_ == nullptr) ThrowUnbound(Blackboard::TypeName<T>());
    return slot_;
  }

  // Straight to the key's slot and the lock that guards it: no step through the blackboard.
  Blackboard::Contents* contents_ = nullptr;
  Blackboard::Slot* slot_ = nullptr;
};

}  // namespace kse::messaging

#endif
