#ifndef KSE_MESSAGING_MESSAGE_HUB_H
#define KSE_MESSAGING_MESSAGE_HUB_H

#include <atomic>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <vector>

#include <google/protobuf/message.h>

#include "kse/messaging/Clock.h"
#include "kse/messaging/Kind.h"
#include "kse/messaging/SpinLock.h"

namespace kse::messaging {

class Blackboard;

/// Publish/subscribe on named topics (Narukom's role in Monas). Thread-safe: any thread may
/// publish while engines read their blackboards.
///
/// A published message is delivered, stamped with the hub's clock, to the inbox of every
/// blackboard subscribed to its topic (it becomes visible there at the blackboard's next
/// ProcessMessages()). The hub also keeps the last State message per topic and type, so a
/// blackboard that subscribes late still starts with the current state.
/// Blackboards must not outlive their hub.
class MessageHub {
 public:
  using Listener = std::function<void()>;
  using ListenerId = std::size_t;

  explicit MessageHub(const Clock& clock = SteadyClock::Instance());
  ~MessageHub();
  MessageHub(const MessageHub&) = delete;
  MessageHub& operator=(const MessageHub&) = delete;

  /// Delivers a message to the subscribers of a topic (but `origin`, the blackboard that
  /// published it and already shows it), then calls every listener. A null message is ignored.
  void Publish(const std::string& topic, Kind kind,
               std::shared_ptr<const google::protobuf::Message> message,
               const Blackboard* origin = nullptr);

  /// The same for a message of a generated class (they are final), whose type name is then
  /// looked up once per class instead of through the message's descriptor on every publish.
  template <class T, std::enable_if_t<std::is_final_v<T> &&
                                          std::is_base_of_v<google::protobuf::Message, T>,
                                      int> = 0>
  void Publish(const std::string& topic, Kind kind, std::shared_ptr<const T> message,
               const Blackboard* origin = nullptr) {
    if (!message) {
      return;
    }
    Publish(topic, TypeNameOf<T>(), kind, std::move(message), origin);
  }

  /// The protobuf full name of a generated message class, looked up once.
  template <class T>
  static const std::string& TypeNameOf() {
    static const std::string& name = T::descriptor()->full_name();
    return name;
  }

  /// Registers a function called (on the publishing thread) after every publish. Listeners must
  /// be quick and must not add or remove listeners. Returns an id for RemoveListener.
  ListenerId AddListener(Listener listener);
  /// Removes a listener; once it returns, the listener is not running and will not be called.
  void RemoveListener(ListenerId id);

  const Clock& GetClock() const noexcept { return clock_; }

  /// A State message the hub keeps: the last one of its type on its topic.
  struct KeptState {
    std::string topic;
    std::string type_name;
    std::shared_ptr<const google::protobuf::Message> message;
    TimePoint time;  // when it was published
  };
  /// The State messages kept (what a blackboard subscribing now starts with), topics in the
  /// order they were first used. For a monitor that shows them; not for a robot's loop.
  std::vector<KeptState> KeptStates() const;

  /// Number of blackboards subscribed to a topic.
  std::size_t SubscriberCount(const std::string& topic) const;
  /// Number of messages published so far.
  std::size_t PublishedCount() const;

 private:
  friend class Blackboard;
  // Everything the hub keeps for one topic: its subscribers and its last State messages.
  struct Topic;

  /// Publish with the message's type name already known (a blackboard has looked it up).
  void Publish(const std::string& topic, const std::string& type_name, Kind kind,
               std::shared_ptr<const google::protobuf::Message> message, const Blackboard* origin);
  // Callers hold mutex_.
  Topic* FindTopic(const std::string& topic) const;
  Topic& TopicFor(const std::string& topic);
  // To every subscriber of the topic but the origin.
  void Deliver(Topic& entry, const std::string& topic, const std::string& type_name, Kind kind,
               const std::shared_ptr<const google::protobuf::Message>& message, TimePoint now,
               const Blackboard* origin);

  void Attach(Blackboard* board, const std::string& topic);
  void Detach(Blackboard* board);

  const Clock& clock_;

  mutable SpinLock mutex_;  // topics_, published_
  std::vector<std::unique_ptr<Topic>> topics_;
  std::size_t published_ = 0;

  std::mutex listeners_mutex_;
  std::vector<std::pair<ListenerId, Listener>> listeners_;
  // Whether there are listeners, read without the lock: a publish with none (the engine does
  // not listen) does not take listeners_mutex_.
  std::atomic<bool> has_listeners_{false};
  ListenerId next_listener_ = 1;
};

}  // namespace kse::messaging

#endif
