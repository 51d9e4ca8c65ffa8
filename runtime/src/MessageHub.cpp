#include "kse/messaging/MessageHub.h"

#include <algorithm>
#include <utility>

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>

#include "SameString.h"
#include "kse/messaging/Blackboard.h"

namespace kse::messaging {

// A process has a handful of topics and each robot publishes on them every cycle: a scan of a
// short vector by tag, no string built per publish.
struct MessageHub::Topic {
  struct Retained {
    std::string type_name;
    std::shared_ptr<const google::protobuf::Message> message;
    TimePoint time;
    const Blackboard* origin;  // never handed back to the blackboard that published it
  };

  // Where a message of one type goes: the slot of its key in each subscriber, as
  // Blackboard::Deliver() answered it, so that the next message of the type is queued there
  // without the key being looked up again in every board. Made at the type's first publish
  // after the subscribers last changed (a slot lives as long as its board, and a board leaves
  // the hub before it goes).
  struct Route {
    std::string type_name;
    std::vector<Blackboard::Slot*> slots;  // subscribers[i]'s, or null while not yet known
  };

  explicit Topic(const std::string& topic) : name(topic), tag(topic) {}

  void SubscribersChanged() { routes.clear(); }

  std::string name;
  detail::Tag tag;
  std::vector<Blackboard*> subscribers;
  std::vector<Retained> retained;  // the last State message of each type
  std::vector<Route> routes;
};

MessageHub::MessageHub(const Clock& clock) : clock_(clock) {}

MessageHub::~MessageHub() = default;

MessageHub::Topic* MessageHub::FindTopic(const std::string& topic) const {
  const detail::Tag tag(topic);
  for (const auto& entry : topics_) {
    if (entry->tag == tag && detail::SameString(entry->name, topic)) return entry.get();
  }
  return nullptr;
}

MessageHub::Topic& MessageHub::TopicFor(const std::string& topic) {
  if (Topic* found = FindTopic(topic)) return *found;
  auto entry = std::make_unique<Topic>(topic);
  topics_.push_back(std::move(entry));
  return *topics_.back();
}

void MessageHub::Publish(const std::string& topic, Kind kind,
                         std::shared_ptr<const google::protobuf::Message> message,
                         const Blackboard* origin) {
  if (!message) {
    return;
  }
  const std::string& type_name = message->GetDescriptor()->full_name();
  Publish(topic, type_name, kind, std::move(message), origin);
}

void MessageHub::Deliver(Topic& entry, const std::string& topic, const std::string& type_name, Kind kind,
                         const std::shared_ptr<const google::protobuf::Message>& message, TimePoint now,
                         const Blackboard* origin) {
  Topic::Route* route = nullptr;
  for (Topic::Route& r : entry.routes) {
    if (detail::SameString(r.type_name, type_name)) {
      route = &r;
      break;
    }
  }
  if (route == nullptr) {
    entry.routes.push_back(Topic::Route{type_name, std::vector<Blackboard::Slot*>(entry.subscribers.size())});
    route = &entry.routes.back();
  }
  for (std::size_t i = 0; i < entry.subscribers.size(); ++i) {
    Blackboard* board = entry.subscribers[i];
    if (board == origin) continue;
    if (Blackboard::Slot* slot = route->slots[i]) {
      Blackboard::DeliverAt(slot, kind, message, now);
    } else {
      route->slots[i] = board->Deliver(topic, type_name, kind, message, now);
    }
  }
}

void MessageHub::Publish(const std::string& topic, const std::string& type_name, Kind kind,
                         std::shared_ptr<const google::protobuf::Message> message,
                         const Blackboard* origin) {
  {
    std::lock_guard<SpinLock> lock(mutex_);
    const TimePoint now = clock_.Now();
    ++published_;
    Topic* entry = kind == Kind::State ? &TopicFor(topic) : FindTopic(topic);
    if (entry != nullptr) {
      if (!entry->subscribers.empty()) Deliver(*entry, topic, type_name, kind, message, now, origin);
      if (kind == Kind::State) {
        // Kept last, so that the message moves in rather than being shared once more.
        auto retained = std::find_if(entry->retained.begin(), entry->retained.end(),
                                     [&](const Topic::Retained& r) { return detail::SameString(r.type_name, type_name); });
        if (retained == entry->retained.end()) {
          entry->retained.push_back(Topic::Retained{type_name, std::move(message), now, origin});
        } else {
          retained->message = std::move(message);
          retained->time = now;
          retained->origin = origin;
        }
      }
    }
  }
  if (!has_listeners_.load(std::memory_order_acquire)) {
    return;
  }
  std::lock_guard<std::mutex> lock(listeners_mutex_);
  for (auto& entry : listeners_) {
    entry.second();
  }
}

MessageHub::ListenerId MessageHub::AddListener(Listener listener) {
  std::lock_guard<std::mutex> lock(listeners_mutex_);
  const ListenerId id = next_listener_++;
  listeners_.emplace_back(id, std::move(listener));
  has_listeners_.store(true, std::memory_order_release);
  return id;
}

void MessageHub::RemoveListener(ListenerId id) {
  std::lock_guard<std::mutex> lock(listeners_mutex_);
  listeners_.erase(std::remove_if(listeners_.begin(), listeners_.end(),
                                  [id](const auto& entry) { return entry.first == id; }),
                   listeners_.end());
  has_listeners_.store(!listeners_.empty(), std::memory_order_release);
}

std::vector<MessageHub::KeptState> MessageHub::KeptStates() const {
  std::vector<KeptState> kept;
  std::lock_guard<SpinLock> lock(mutex_);
  for (const auto& topic : topics_) {
    for (const auto& retained : topic->retained) {
      kept.push_back(KeptState{topic->name, retained.type_name, retained.message, retained.time});
    }
  }
  return kept;
}

std::size_t MessageHub::SubscriberCount(const std::string& topic) const {
  std::lock_guard<SpinLock> lock(mutex_);
  const Topic* entry = FindTopic(topic);
  return entry == nullptr ? 0 : entry->subscribers.size();
}

std::size_t MessageHub::PublishedCount() const {
  std::lock_guard<SpinLock> lock(mutex_);
  return published_;
}

void MessageHub::Attach(Blackboard* board, const std::string& topic) {
  std::lock_guard<SpinLock> lock(mutex_);
  Topic& entry = TopicFor(topic);
  auto& boards = entry.subscribers;
  if (std::find(boards.begin(), boards.end(), board) != boards.end()) {
    return;
  }
  boards.push_back(board);
  entry.SubscribersChanged();
  for (const Topic::Retained& retained : entry.retained) {
    if (retained.origin != board) {
      board->Deliver(topic, retained.type_name, Kind::State, retained.message, retained.time);
    }
  }
}

void MessageHub::Detach(Blackboard* board) {
  std::lock_guard<SpinLock> lock(mutex_);
  for (auto& entry : topics_) {
    auto& boards = entry->subscribers;
    const auto kept = std::remove(boards.begin(), boards.end(), board);
    if (kept != boards.end()) {
      boards.erase(kept, boards.end());
      entry->SubscribersChanged();
    }
  }
}

}  // namespace kse::messaging
