#include "kse/messaging/Blackboard.h"

#include <utility>

namespace kse::messaging {

Blackboard::Blackboard(MessageHub& hub, std::string name) : hub_(hub), name_(std::move(name)) {}

Blackboard::~Blackboard() { hub_.Detach(this); }

std::string Blackboard::Key(const std::string& topic, const std::string& type_name) {
  std::string key;
  key.reserve(topic.size() + 1 + type_name.size());
  key.append(topic).push_back('\x1f');
  key.append(type_name);
  return key;
}

void Blackboard::Subscribe(const std::string& topic) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!topics_.insert(topic).second) {
      return;
    }
  }
  // Not under mutex_: the hub delivers retained state into this blackboard (hub, then board lock).
  hub_.Attach(this, topic);
}

bool Blackboard::IsSubscribed(const std::string& topic) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return topics_.count(topic) != 0;
}

void Blackboard::Deliver(const std::string& topic, Kind kind, const MessagePtr& message,
                         TimePoint time) {
  std::string key = Key(topic, message->GetTypeName());
  std::lock_guard<std::mutex> lock(mutex_);
  Queue(std::move(key), kind, message, time);
}

void Blackboard::Queue(std::string key, Kind kind, const MessagePtr& message, TimePoint time) {
  switch (kind) {
    case Kind::State: {
      auto [it, added] = inbox_states_.insert_or_assign(std::move(key), Entry{message, time});
      (void)it;
      inbox_size_ += added ? 1 : 0;
      break;
    }
    case Kind::Signal: {
      auto& queue = inbox_signals_[std::move(key)];
      if (queue.size() >= kSignalQueueLimit) {
        queue.pop_front();
        --inbox_size_;
      }
      queue.push_back(message);
      ++inbox_size_;
      break;
    }
    case Kind::Data: {
      auto& history = inbox_data_[std::move(key)];
      if (history.size() >= kDataHistoryLimit) {
        history.pop_front();
        --inbox_size_;
      }
      history.push_back(Entry{message, time});
      ++inbox_size_;
      break;
    }
  }
}

void Blackboard::Apply(std::string key, Kind kind, const MessagePtr& message, TimePoint time) {
  switch (kind) {
    case Kind::State:
      states_[std::move(key)] = Entry{message, time};
      break;
    case Kind::Signal: {
      auto& queue = signals_[std::move(key)];
      if (queue.size() >= kSignalQueueLimit) {
        queue.pop_front();
      }
      queue.push_back(message);
      break;
    }
    case Kind::Data: {
      auto& history = data_[std::move(key)];
      if (history.size() >= kDataHistoryLimit) {
        history.pop_front();
      }
      history.push_back(Entry{message, time});
      break;
    }
  }
}

void Blackboard::ProcessMessages() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (inbox_size_ == 0) {
    return;
  }
  for (auto& [key, entry] : inbox_states_) {
    states_[key] = std::move(entry);
  }
  for (auto& [key, queue] : inbox_signals_) {
    for (auto& message : queue) {
      Apply(key, Kind::Signal, message, TimePoint());
    }
  }
  for (auto& [key, history] : inbox_data_) {
    for (auto& entry : history) {
      Apply(key, Kind::Data, entry.message, entry.time);
    }
  }
  inbox_states_.clear();
  inbox_signals_.clear();
  inbox_data_.clear();
  inbox_size_ = 0;
}

std::size_t Blackboard::PendingMessages() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return inbox_size_;
}

Blackboard::MessagePtr Blackboard::ReadStateMessage(const std::string& topic,
                                                    const std::string& type_name) const {
  const std::string key = Key(topic, type_name);
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = states_.find(key);
  return it == states_.end() ? nullptr : it->second.message;
}

Blackboard::MessagePtr Blackboard::ReadSignalMessage(const std::string& topic,
                                                     const std::string& type_name) {
  const std::string key = Key(topic, type_name);
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = signals_.find(key);
  if (it == signals_.end() || it->second.empty()) {
    return nullptr;
  }
  MessagePtr message = std::move(it->second.front());
  it->second.pop_front();
  return message;
}

Blackboard::MessagePtr Blackboard::ReadDataMessage(const std::string& topic,
                                                   const std::string& type_name) const {
  const std::string key = Key(topic, type_name);
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = data_.find(key);
  if (it == data_.end() || it->second.empty()) {
    return nullptr;
  }
  return it->second.back().message;
}

std::vector<Stamped<google::protobuf::Message>> Blackboard::ReadDataHistoryMessages(
    const std::string& topic, const std::string& type_name, TimePoint since) const {
  const std::string key = Key(topic, type_name);
  std::vector<Stamped<google::protobuf::Message>> out;
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = data_.find(key);
  if (it == data_.end()) {
    return out;
  }
  for (const Entry& entry : it->second) {
    if (entry.time >= since) {
      out.push_back(Stamped<google::protobuf::Message>{entry.time, entry.message});
    }
  }
  return out;
}

std::size_t Blackboard::PendingSignals(const std::string& topic,
                                       const std::string& type_name) const {
  const std::string key = Key(topic, type_name);
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = signals_.find(key);
  return it == signals_.end() ? 0 : it->second.size();
}

void Blackboard::PublishMessage(const std::string& topic, Kind kind, MessagePtr message) {
  if (!message) {
    return;
  }
  {
    std::string key = Key(topic, message->GetTypeName());
    std::lock_guard<std::mutex> lock(mutex_);
    Apply(std::move(key), kind, message, Now());
  }
  hub_.Publish(topic, kind, std::move(message), this);
}

void Blackboard::PublishCopy(const std::string& topic, Kind kind,
                             const google::protobuf::Message& message) {
  std::shared_ptr<google::protobuf::Message> copy(message.New());
  copy->CopyFrom(message);
  PublishMessage(topic, kind, std::move(copy));
}

void Blackboard::ScheduleWakeup(TimePoint time) {
  std::lock_guard<std::mutex> lock(mutex_);
  wakeups_.insert(time);
}

std::optional<TimePoint> Blackboard::NextWakeup() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (wakeups_.empty()) {
    return std::nullopt;
  }
  return *wakeups_.begin();
}

bool Blackboard::TakeDueWakeups(TimePoint now) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto end = wakeups_.upper_bound(now);
  if (end == wakeups_.begin()) {
    return false;
  }
  wakeups_.erase(wakeups_.begin(), end);
  return true;
}

}  // namespace kse::messaging
