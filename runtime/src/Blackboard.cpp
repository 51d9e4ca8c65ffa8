#include "kse/messaging/Blackboard.h"

#include <deque>
#include <map>
#include <set>
#include <utility>

namespace kse::messaging {

struct Blackboard::Contents {
  std::set<std::string> topics;
  std::map<std::string, Entry> states;
  std::map<std::string, std::deque<MessagePtr>> signals;
  std::map<std::string, std::deque<Entry>> data;
  // The inbox: what arrived since the last ProcessMessages(), bounded as the visible part is
  // (a State message replaces the one waiting before it).
  std::map<std::string, Entry> inbox_states;
  std::map<std::string, std::deque<MessagePtr>> inbox_signals;
  std::map<std::string, std::deque<Entry>> inbox_data;
  std::size_t inbox_size = 0;
  std::multiset<TimePoint> wakeups;
};

Blackboard::Blackboard(MessageHub& hub, std::string name) : hub_(hub), name_(std::move(name)) {}

Blackboard::~Blackboard() {
  // Only a subscription puts a blackboard into the hub.
  if (contents_ && !contents_->topics.empty()) hub_.Detach(this);
}

Blackboard::Contents& Blackboard::Made() {
  if (!contents_) contents_ = std::make_unique<Contents>();
  return *contents_;
}

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
    if (!Made().topics.insert(topic).second) {
      return;
    }
  }
  // Not under mutex_: the hub delivers retained state into this blackboard (hub, then board lock).
  hub_.Attach(this, topic);
}

bool Blackboard::IsSubscribed(const std::string& topic) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return contents_ && contents_->topics.count(topic) != 0;
}

void Blackboard::Deliver(const std::string& topic, Kind kind, const MessagePtr& message,
                         TimePoint time) {
  std::string key = Key(topic, message->GetTypeName());
  std::lock_guard<std::mutex> lock(mutex_);
  Queue(std::move(key), kind, message, time);
}

void Blackboard::Queue(std::string key, Kind kind, const MessagePtr& message, TimePoint time) {
  Contents& c = Made();
  switch (kind) {
    case Kind::State: {
      auto [it, added] = c.inbox_states.insert_or_assign(std::move(key), Entry{message, time});
      (void)it;
      c.inbox_size += added ? 1 : 0;
      break;
    }
    case Kind::Signal: {
      auto& queue = c.inbox_signals[std::move(key)];
      if (queue.size() >= kSignalQueueLimit) {
        queue.pop_front();
        --c.inbox_size;
      }
      queue.push_back(message);
      ++c.inbox_size;
      break;
    }
    case Kind::Data: {
      auto& history = c.inbox_data[std::move(key)];
      if (history.size() >= kDataHistoryLimit) {
        history.pop_front();
        --c.inbox_size;
      }
      history.push_back(Entry{message, time});
      ++c.inbox_size;
      break;
    }
  }
}

void Blackboard::Apply(std::string key, Kind kind, const MessagePtr& message, TimePoint time) {
  Contents& c = Made();
  switch (kind) {
    case Kind::State:
      c.states[std::move(key)] = Entry{message, time};
      break;
    case Kind::Signal: {
      auto& queue = c.signals[std::move(key)];
      if (queue.size() >= kSignalQueueLimit) {
        queue.pop_front();
      }
      queue.push_back(message);
      break;
    }
    case Kind::Data: {
      auto& history = c.data[std::move(key)];
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
  if (!contents_ || contents_->inbox_size == 0) {
    return;
  }
  Contents& c = *contents_;
  for (auto& [key, entry] : c.inbox_states) {
    c.states[key] = std::move(entry);
  }
  for (auto& [key, queue] : c.inbox_signals) {
    for (auto& message : queue) {
      Apply(key, Kind::Signal, message, TimePoint());
    }
  }
  for (auto& [key, history] : c.inbox_data) {
    for (auto& entry : history) {
      Apply(key, Kind::Data, entry.message, entry.time);
    }
  }
  c.inbox_states.clear();
  c.inbox_signals.clear();
  c.inbox_data.clear();
  c.inbox_size = 0;
}

std::size_t Blackboard::PendingMessages() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return contents_ ? contents_->inbox_size : 0;
}

Blackboard::MessagePtr Blackboard::ReadStateMessage(const std::string& topic,
                                                    const std::string& type_name) const {
  const std::string key = Key(topic, type_name);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!contents_) return nullptr;
  auto it = contents_->states.find(key);
  return it == contents_->states.end() ? nullptr : it->second.message;
}

Blackboard::MessagePtr Blackboard::ReadSignalMessage(const std::string& topic,
                                                     const std::string& type_name) {
  const std::string key = Key(topic, type_name);
  std::lock_guard<std::mutex> lock(mutex_);
  if (!contents_) return nullptr;
  auto it = contents_->signals.find(key);
  if (it == contents_->signals.end() || it->second.empty()) {
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
  if (!contents_) return nullptr;
  auto it = contents_->data.find(key);
  if (it == contents_->data.end() || it->second.empty()) {
    return nullptr;
  }
  return it->second.back().message;
}

std::vector<Stamped<google::protobuf::Message>> Blackboard::ReadDataHistoryMessages(
    const std::string& topic, const std::string& type_name, TimePoint since) const {
  const std::string key = Key(topic, type_name);
  std::vector<Stamped<google::protobuf::Message>> out;
  std::lock_guard<std::mutex> lock(mutex_);
  if (!contents_) return out;
  auto it = contents_->data.find(key);
  if (it == contents_->data.end()) {
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
  if (!contents_) return 0;
  auto it = contents_->signals.find(key);
  return it == contents_->signals.end() ? 0 : it->second.size();
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
  Made().wakeups.insert(time);
}

std::optional<TimePoint> Blackboard::NextWakeup() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!contents_ || contents_->wakeups.empty()) {
    return std::nullopt;
  }
  return *contents_->wakeups.begin();
}

bool Blackboard::TakeDueWakeups(TimePoint now) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!contents_) return false;
  auto& wakeups = contents_->wakeups;
  auto end = wakeups.upper_bound(now);
  if (end == wakeups.begin()) {
    return false;
  }
  wakeups.erase(wakeups.begin(), end);
  return true;
}

}  // namespace kse::messaging
