#include "kse/messaging/MessageHub.h"

#include <algorithm>
#include <utility>

#include <google/protobuf/message.h>

#include "kse/messaging/Blackboard.h"

namespace kse::messaging {

MessageHub::MessageHub(const Clock& clock) : clock_(clock) {}

MessageHub::~MessageHub() = default;

void MessageHub::Publish(const std::string& topic, Kind kind,
                         std::shared_ptr<const google::protobuf::Message> message,
                         const Blackboard* origin) {
  if (!message) {
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const TimePoint now = clock_.Now();
    ++published_;
    if (kind == Kind::State) {
      retained_[topic][message->GetTypeName()] = Retained{message, now, origin};
    }
    auto it = subscribers_.find(topic);
    if (it != subscribers_.end()) {
      for (Blackboard* board : it->second) {
        if (board != origin) {
          board->Deliver(topic, kind, message, now);
        }
      }
    }
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
  return id;
}

void MessageHub::RemoveListener(ListenerId id) {
  std::lock_guard<std::mutex> lock(listeners_mutex_);
  listeners_.erase(std::remove_if(listeners_.begin(), listeners_.end(),
                                  [id](const auto& entry) { return entry.first == id; }),
                   listeners_.end());
}

std::size_t MessageHub::SubscriberCount(const std::string& topic) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = subscribers_.find(topic);
  return it == subscribers_.end() ? 0 : it->second.size();
}

std::size_t MessageHub::PublishedCount() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return published_;
}

void MessageHub::Attach(Blackboard* board, const std::string& topic) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto& boards = subscribers_[topic];
  if (std::find(boards.begin(), boards.end(), board) != boards.end()) {
    return;
  }
  boards.push_back(board);
  auto it = retained_.find(topic);
  if (it != retained_.end()) {
    for (const auto& entry : it->second) {
      if (entry.second.origin != board) {
        board->Deliver(topic, Kind::State, entry.second.message, entry.second.time);
      }
    }
  }
}

void MessageHub::Detach(Blackboard* board) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = subscribers_.begin(); it != subscribers_.end();) {
    auto& boards = it->second;
    boards.erase(std::remove(boards.begin(), boards.end(), board), boards.end());
    it = boards.empty() ? subscribers_.erase(it) : std::next(it);
  }
}

}  // namespace kse::messaging
