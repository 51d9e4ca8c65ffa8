#ifndef KSE_MESSAGING_BLACKBOARD_H
#define KSE_MESSAGING_BLACKBOARD_H

#include <chrono>
#include <cstddef>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <google/protobuf/message.h>

#include "kse/messaging/Clock.h"
#include "kse/messaging/Kind.h"
#include "kse/messaging/MessageHub.h"

namespace kse::messaging {

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
class Blackboard {
 public:
  using MessagePtr = std::shared_ptr<const google::protobuf::Message>;

  /// Most recent entries kept per Data key.
  static constexpr std::size_t kDataHistoryLimit = 100;
  /// Unread signals kept per Signal key; when full the oldest unread one is dropped.
  static constexpr std::size_t kSignalQueueLimit = 1000;

  explicit Blackboard(MessageHub& hub, std::string name = {});
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
    return std::dynamic_pointer_cast<const T>(ReadStateMessage(topic, TypeName<T>()));
  }

  /// The oldest unread Signal of that topic and type, consumed by this read; nullptr when none.
  template <class T>
  std::shared_ptr<const T> ReadSignal(const std::string& topic) {
    return std::dynamic_pointer_cast<const T>(ReadSignalMessage(topic, TypeName<T>()));
  }

  /// The newest Data entry of that topic and type, or nullptr.
  template <class T>
  std::shared_ptr<const T> ReadData(const std::string& topic) {
    return std::dynamic_pointer_cast<const T>(ReadDataMessage(topic, TypeName<T>()));
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
    PublishCopy(topic, kind, message);
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
  void PublishCopy(const std::string& topic, Kind kind, const google::protobuf::Message& message);

  /// Number of unread signals of that topic and type.
  std::size_t PendingSignals(const std::string& topic, const std::string& type_name) const;

  MessageHub& Hub() const noexcept { return hub_; }
  const std::string& Name() const noexcept { return name_; }
  TimePoint Now() const { return hub_.GetClock().Now(); }

  template <class T>
  static const std::string& TypeName() {
    return T::descriptor()->full_name();
  }

 private:
  friend class MessageHub;
  void Deliver(const std::string& topic, Kind kind, const MessagePtr& message, TimePoint time);
  static std::string Key(const std::string& topic, const std::string& type_name);

  struct Entry {
    MessagePtr message;
    TimePoint time;
  };
  // What the blackboard holds: topics, messages, the inbox, wake-ups. Most blackboards of a
  // process (a statechart's root, its regions) never hold a message, so it is made by the
  // first subscription, publish or wake-up, not with the blackboard.
  struct Contents;
  // Callers hold mutex_.
  Contents& Made();
  void Apply(std::string key, Kind kind, const MessagePtr& message, TimePoint time);
  void Queue(std::string key, Kind kind, const MessagePtr& message, TimePoint time);

  MessageHub& hub_;
  const std::string name_;

  mutable std::mutex mutex_;
  std::unique_ptr<Contents> contents_;  // null until needed
};

}  // namespace kse::messaging

#endif
