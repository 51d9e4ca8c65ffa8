#ifndef KSE_MESSAGING_MESSAGE_HUB_H
#define KSE_MESSAGING_MESSAGE_HUB_H

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "kse/messaging/Clock.h"
#include "kse/messaging/Kind.h"

namespace google::protobuf {
class Message;
}

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

  /// Registers a function called (on the publishing thread) after every publish. Listeners must
  /// be quick and must not add or remove listeners. Returns an id for RemoveListener.
  ListenerId AddListener(Listener listener);
  /// Removes a listener; once it returns, the listener is not running and will not be called.
  void RemoveListener(ListenerId id);

  const Clock& GetClock() const noexcept { return clock_; }

  /// Number of blackboards subscribed to a topic.
  std::size_t SubscriberCount(const std::string& topic) const;
  /// Number of messages published so far.
  std::size_t PublishedCount() const;

 private:
  friend class Blackboard;
  struct Retained {
    std::shared_ptr<const google::protobuf::Message> message;
    TimePoint time;
    const Blackboard* origin;  // never handed back to the blackboard that published it
  };

  void Attach(Blackboard* board, const std::string& topic);
  void Detach(Blackboard* board);

  const Clock& clock_;

  mutable std::mutex mutex_;  // subscribers_, retained_, published_
  std::map<std::string, std::vector<Blackboard*>> subscribers_;
  std::map<std::string, std::map<std::string, Retained>> retained_;  // topic -> type -> state
  std::size_t published_ = 0;

  std::mutex listeners_mutex_;
  std::vector<std::pair<ListenerId, Listener>> listeners_;
  ListenerId next_listener_ = 1;
};

}  // namespace kse::messaging

#endif
