#include "kse/messaging/Blackboard.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <utility>

#include "SameString.h"
#include "kse/messaging/SpinLock.h"

namespace kse::messaging {

namespace {

// A full signal queue or data history lets go of its oldest message at every new one, a message
// put there a hundred or a thousand messages ago and long out of the caches: dropping the
// reference waited for memory. So when one goes, the next to go is asked for: its count (which a
// make_shared message has just before itself) and its start.
void WarmUp(const std::shared_ptr<const google::protobuf::Message>& message) noexcept {
  const char* start = reinterpret_cast<const char*>(message.get());
  __builtin_prefetch(start - 16);
  __builtin_prefetch(start);
}

template <class Entry>
auto WarmUp(const Entry& entry) noexcept -> decltype(entry.message, void()) {
  WarmUp(entry.message);
}

// A queue of messages (a signal queue, a data history, their inboxes) that keeps its storage:
// a blackboard passes the same few keys' messages through it on every cycle of a robot, and a
// std::deque allocates and frees a block of nodes as it goes. Capacity is a power of two.
template <class T>
class Ring {
 public:
  std::size_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  T& front() noexcept { return items_[head_]; }
  T& back() noexcept { return items_[(head_ + size_ - 1) & (items_.size() - 1)]; }
  const T& operator[](std::size_t i) const noexcept { return items_[(head_ + i) & (items_.size() - 1)]; }

  void push_back(T item) {
    if (size_ == items_.size()) Grow();
    items_[(head_ + size_) & (items_.size() - 1)] = std::move(item);
    ++size_;
  }
  /// The oldest item, moved out.
  T take_front() noexcept {
    T item = std::move(items_[head_]);
    items_[head_] = T();
    head_ = (head_ + 1) & (items_.size() - 1);
    --size_;
    if (size_ > 0) WarmUp(items_[head_]);
    return item;
  }
  void pop_front() noexcept { (void)take_front(); }

 private:
  void Grow() {
    std::vector<T> items(items_.empty() ? 4 : 2 * items_.size());
    for (std::size_t i = 0; i < size_; ++i) items[i] = std::move(items_[(head_ + i) & (items_.size() - 1)]);
    items_.swap(items);
    head_ = 0;
  }

  std::vector<T> items_;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

// A key (topic and type name) as a lookup compares it: the strings' first bytes in whole words,
// zeros after their ends, their lengths, and a mix of all of them compared first. Keys whose
// words and lengths match are the same key when both strings fit in the words (every topic and
// type name so far), with no string read.
struct Key {
  static constexpr std::size_t kTopicWords = 2;
  static constexpr std::size_t kTypeWords = 3;

  Key(const std::string& topic_name, const std::string& type_name) noexcept
      : topic_size(topic_name.size()), type_size(type_name.size()) {
    Fill(topic, kTopicWords, topic_name);
    Fill(type, kTypeWords, type_name);
    mix = (topic[0] * 0x9E3779B97F4A7C15ULL) ^ topic[1] ^ (type[0] * 0xC2B2AE3D27D4EB4FULL) ^ type[1] ^
          (type[2] * 0x165667B19E3779F9ULL) ^ (topic_size << 48) ^ type_size;
  }

  bool Fits() const noexcept { return topic_size <= sizeof topic && type_size <= sizeof type; }
  bool operator==(const Key& other) const noexcept {
    return mix == other.mix && topic_size == other.topic_size && type_size == other.type_size &&
           std::memcmp(topic, other.topic, sizeof topic) == 0 && std::memcmp(type, other.type, sizeof type) == 0;
  }

  std::uint64_t mix;
  std::uint64_t topic[kTopicWords] = {};
  std::uint64_t type[kTypeWords] = {};
  std::size_t topic_size;
  std::size_t type_size;

 private:
  // Fixed-size loads only: a copy of a length known at run time costs more than the lookup.
  static void Fill(std::uint64_t* words, std::size_t count, const std::string& text) noexcept {
    const char* data = text.data();
    const std::size_t size = text.size();
    for (std::size_t w = 0; w < count; ++w) {
      const std::size_t offset = 8 * w;
      if (size >= offset + 8) {
        std::memcpy(&words[w], data + offset, 8);
      } else {
        if (size > offset) words[w] = Tail(data + offset, size - offset);
        return;
      }
    }
  }
  // The first n (1 to 7) bytes, each in a byte of its own: on a little-endian machine two
  // overlapping loads (their common bytes are the same), elsewhere one byte at a time.
  static std::uint64_t Tail(const char* p, std::size_t n) noexcept {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    if (n >= 4) {
      std::uint32_t low;
      std::uint32_t high;
      std::memcpy(&low, p, 4);
      std::memcpy(&high, p + n - 4, 4);
      return low | (static_cast<std::uint64_t>(high) << (8 * (n - 4)));
    }
    const auto byte = [p](std::size_t i) { return static_cast<std::uint64_t>(static_cast<unsigned char>(p[i])); };
    return byte(0) | (byte(n / 2) << (8 * (n / 2))) | (byte(n - 1) << (8 * (n - 1)));
#else
    std::uint64_t word = 0;
    for (std::size_t i = 0; i < n; ++i) word |= static_cast<std::uint64_t>(static_cast<unsigned char>(p[i])) << (8 * i);
    return word;
#endif
  }
};

}  // namespace

// Everything a blackboard holds for one topic and type. Slots are made on the first message
// (or write) of their key and kept: a robot's blackboard sees the same few keys every cycle.
struct Blackboard::Slot {
  // Laid out by use: a delivery goes from the hub straight here and to the contents named here
  // (not through the blackboard); State messages are in the first cache line, the queues after,
  // the key's strings last (compared only when a key does not fit in its tag).
  Contents* owner = nullptr;
  bool pending = false;  // listed in Contents::pending
  Entry state;           // message null: no State message yet
  // The inbox: what arrived since the last ProcessMessages(), bounded as the visible part is
  // (a State message replaces the one waiting before it).
  Entry inbox_state;  // message null: none waiting
  Ring<MessagePtr> signals;
  Ring<MessagePtr> inbox_signals;
  Ring<Entry> data;
  Ring<Entry> inbox_data;
  std::string topic;
  std::string type_name;
};

struct Blackboard::Contents {
  // What every call looks at first, together: the lock, the inbox's size and the earliest
  // wake-up, the last two read without the lock on the paths that usually find nothing.
  mutable SpinLock mutex;
  // inbox_size as of the last change (written under mutex): ProcessMessages() and
  // PendingMessages(), which a robot asks every cycle, tell an empty inbox from it.
  std::atomic<std::size_t> inbox_size_seen{0};
  // The earliest wake-up (ticks of the clock's epoch; the largest value when none), written
  // under mutex: the engine asks TakeDueWakeups() every cycle, nearly always too early.
  std::atomic<Duration::rep> next_wakeup{kNoWakeup};
  std::size_t inbox_size = 0;
  std::vector<Slot*> pending;  // slots with something in their inbox
  // The slots and, side by side in one small array, the tags of their keys: a lookup scans the
  // tags and compares strings once.
  std::vector<Key> keys;
  std::vector<std::unique_ptr<Slot>> slots;
  std::vector<std::string> topics;  // subscribed
  std::vector<TimePoint> wakeups;   // sorted, equal times kept (each is one wake-up)

  static constexpr Duration::rep kNoWakeup = std::numeric_limits<Duration::rep>::max();
};

Blackboard::Blackboard(MessageHub& hub, const std::string& name) : hub_(&hub) {
  if (name.size() <= kShortName) {
    std::memcpy(name_, name.data(), name.size());
    name_size_ = static_cast<unsigned char>(name.size());
  } else {
    // A copy of just the name, its address and length where a short name would be.
    char* copy = new char[name.size()];
    std::memcpy(copy, name.data(), name.size());
    const std::uint32_t size = static_cast<std::uint32_t>(std::min<std::size_t>(name.size(), UINT32_MAX));
    std::memcpy(name_, &copy, sizeof copy);
    std::memcpy(name_ + sizeof copy, &size, sizeof size);
    name_size_ = kLongName;
  }
}

Blackboard::~Blackboard() {
  Contents* c = contents_.load(std::memory_order_acquire);
  // Only a subscription puts a blackboard into the hub.
  if (c != nullptr && !c->topics.empty()) hub_->Detach(this);
  delete c;
  if (name_size_ == kLongName) {
    char* copy;
    std::memcpy(&copy, name_, sizeof copy);
    delete[] copy;
  }
}

std::string Blackboard::Name() const {
  if (name_size_ != kLongName) return std::string(name_, name_size_);
  const char* copy;
  std::uint32_t size;
  std::memcpy(&copy, name_, sizeof copy);
  std::memcpy(&size, name_ + sizeof copy, sizeof size);
  return std::string(copy, size);
}

Blackboard::Contents& Blackboard::Made() {
  Contents* c = contents_.load(std::memory_order_acquire);
  if (c != nullptr) return *c;
  // Two threads may come here at once: one's contents are installed, the other's dropped, and
  // both go on with the installed ones.
  auto made = std::make_unique<Contents>();
  if (contents_.compare_exchange_strong(c, made.get(), std::memory_order_acq_rel, std::memory_order_acquire)) {
    return *made.release();
  }
  return *c;
}

Blackboard::Slot* Blackboard::Find(const Contents& contents, const std::string& topic, const std::string& type_name) {
  // A handful of keys per blackboard, looked up on every read and delivery: a scan of their
  // tags beats a tree of string comparisons.
  const Key key(topic, type_name);
  const auto& keys = contents.keys;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (keys[i] == key) {
      Slot* slot = contents.slots[i].get();
      if (key.Fits() ||
          (detail::SameString(slot->type_name, type_name) && detail::SameString(slot->topic, topic))) {
        return slot;
      }
    }
  }
  return nullptr;
}

Blackboard::Slot& Blackboard::SlotFor(Contents& contents, const std::string& topic, const std::string& type_name) {
  if (Slot* slot = Find(contents, topic, type_name)) return *slot;
  auto slot = std::make_unique<Slot>();
  slot->owner = &contents;
  slot->topic = topic;
  slot->type_name = type_name;
  contents.keys.emplace_back(topic, type_name);
  contents.slots.push_back(std::move(slot));
  return *contents.slots.back();
}

void Blackboard::Subscribe(const std::string& topic) {
  {
    Contents& c = Made();
    std::lock_guard<SpinLock> lock(c.mutex);
    if (std::find(c.topics.begin(), c.topics.end(), topic) != c.topics.end()) {
      return;
    }
    c.topics.push_back(topic);
  }
  // Not under the lock: the hub delivers retained state into this blackboard (hub, then board lock).
  hub_->Attach(this, topic);
}

bool Blackboard::IsSubscribed(const std::string& topic) const {
  Contents* c = Peek();
  if (c == nullptr) return false;
  std::lock_guard<SpinLock> lock(c->mutex);
  return std::find(c->topics.begin(), c->topics.end(), topic) != c->topics.end();
}

Blackboard::Slot* Blackboard::Deliver(const std::string& topic, const std::string& type_name, Kind kind,
                                      const MessagePtr& message, TimePoint time) {
  Contents& c = Made();  // made already: only a subscribed blackboard is delivered to
  std::lock_guard<SpinLock> lock(c.mutex);
  Slot& slot = SlotFor(c, topic, type_name);
  Queue(c, slot, kind, message, time);
  return &slot;
}

void Blackboard::DeliverAt(Slot* slot, Kind kind, const MessagePtr& message, TimePoint time) {
  Contents& c = *slot->owner;
  std::lock_guard<SpinLock> lock(c.mutex);
  Queue(c, *slot, kind, message, time);
}

void Blackboard::Queue(Contents& c, Slot& slot, Kind kind, const MessagePtr& message, TimePoint time) {
  switch (kind) {
    case Kind::State:
      if (!slot.inbox_state.message) ++c.inbox_size;
      slot.inbox_state = Entry{message, time};
      break;
    case Kind::Signal:
      if (slot.inbox_signals.size() >= kSignalQueueLimit) {
        slot.inbox_signals.pop_front();
        --c.inbox_size;
      }
      slot.inbox_signals.push_back(message);
      ++c.inbox_size;
      break;
    case Kind::Data:
      if (slot.inbox_data.size() >= kDataHistoryLimit) {
        slot.inbox_data.pop_front();
        --c.inbox_size;
      }
      slot.inbox_data.push_back(Entry{message, time});
      ++c.inbox_size;
      break;
  }
  if (!slot.pending) {
    slot.pending = true;
    c.pending.push_back(&slot);
  }
  c.inbox_size_seen.store(c.inbox_size, std::memory_order_release);
}

void Blackboard::Apply(Slot& slot, Kind kind, const MessagePtr& message, TimePoint time) {
  switch (kind) {
    case Kind::State:
      slot.state = Entry{message, time};
      break;
    case Kind::Signal:
      if (slot.signals.size() >= kSignalQueueLimit) {
        slot.signals.pop_front();
      }
      slot.signals.push_back(message);
      break;
    case Kind::Data:
      if (slot.data.size() >= kDataHistoryLimit) {
        slot.data.pop_front();
      }
      slot.data.push_back(Entry{message, time});
      break;
  }
}

void Blackboard::ProcessMessages() {
  // An empty inbox (every guard of a step after the first refreshes the same blackboard) is
  // told without the lock. A message delivered meanwhile by another thread is made visible at
  // the next call, as if it had come just after this one.
  Contents* contents = Peek();
  if (contents == nullptr || contents->inbox_size_seen.load(std::memory_order_acquire) == 0) return;
  Contents& c = *contents;
  std::lock_guard<SpinLock> lock(c.mutex);
  if (c.inbox_size == 0) {
    return;
  }
  // Keys are independent of each other: in each, the order of arrival is kept.
  for (Slot* slot : c.pending) {
    if (slot->inbox_state.message) {
      slot->state = std::move(slot->inbox_state);
      slot->inbox_state = Entry{};
    }
    while (!slot->inbox_signals.empty()) {
      if (slot->signals.size() >= kSignalQueueLimit) slot->signals.pop_front();
      slot->signals.push_back(slot->inbox_signals.take_front());
    }
    while (!slot->inbox_data.empty()) {
      if (slot->data.size() >= kDataHistoryLimit) slot->data.pop_front();
      slot->data.push_back(slot->inbox_data.take_front());
    }
    slot->pending = false;
  }
  c.pending.clear();
  c.inbox_size = 0;
  c.inbox_size_seen.store(0, std::memory_order_release);
}

std::size_t Blackboard::PendingMessages() const {
  // Written under the lock at every change of the inbox: the count as of the last one.
  const Contents* c = Peek();
  return c == nullptr ? 0 : c->inbox_size_seen.load(std::memory_order_acquire);
}

void Blackboard::ReadStateTo(const std::string& topic, const std::string& type_name, Sink sink,
                             void* out) const {
  const Contents* c = Peek();
  if (c == nullptr) return;
  std::lock_guard<SpinLock> lock(c->mutex);
  const Slot* slot = Find(*c, topic, type_name);
  if (slot != nullptr && slot->state.message) sink(slot->state.message, out);
}

void Blackboard::ReadSignalTo(const std::string& topic, const std::string& type_name, Sink sink,
                              void* out) {
  Contents* c = Peek();
  if (c == nullptr) return;
  std::lock_guard<SpinLock> lock(c->mutex);
  Slot* slot = Find(*c, topic, type_name);
  if (slot == nullptr || slot->signals.empty()) return;
  sink(slot->signals.front(), out);
  slot->signals.pop_front();
}

void Blackboard::ReadDataTo(const std::string& topic, const std::string& type_name, Sink sink,
                            void* out) const {
  const Contents* c = Peek();
  if (c == nullptr) return;
  std::lock_guard<SpinLock> lock(c->mutex);
  Slot* slot = Find(*c, topic, type_name);
  if (slot != nullptr && !slot->data.empty()) sink(slot->data.back().message, out);
}

Blackboard::Slot* Blackboard::SlotOf(const std::string& topic, const std::string& type_name) {
  Contents& c = Made();
  std::lock_guard<SpinLock> lock(c.mutex);
  return &SlotFor(c, topic, type_name);
}

void Blackboard::ReadStateAt(Contents* contents, Slot* slot, Sink sink, void* out) {
  std::lock_guard<SpinLock> lock(contents->mutex);
  if (slot->state.message) sink(slot->state.message, out);
}

void Blackboard::ReadSignalAt(Contents* contents, Slot* slot, Sink sink, void* out) {
  std::lock_guard<SpinLock> lock(contents->mutex);
  if (slot->signals.empty()) return;
  sink(slot->signals.front(), out);
  slot->signals.pop_front();
}

void Blackboard::ReadDataAt(Contents* contents, Slot* slot, Sink sink, void* out) {
  std::lock_guard<SpinLock> lock(contents->mutex);
  if (!slot->data.empty()) sink(slot->data.back().message, out);
}

void ThrowUnbound(const std::string& type_name) {
  throw std::logic_error("kse::messaging::Reader<" + type_name +
                         "> read before Bind(blackboard, topic) (bind it in UserInit())");
}

namespace {

void Keep(const Blackboard::MessagePtr& found, void* out) {
  *static_cast<Blackboard::MessagePtr*>(out) = found;
}

}  // namespace

Blackboard::MessagePtr Blackboard::ReadStateMessage(const std::string& topic,
                                                    const std::string& type_name) const {
  MessagePtr message;
  ReadStateTo(topic, type_name, &Keep, &message);
  return message;
}

Blackboard::MessagePtr Blackboard::ReadSignalMessage(const std::string& topic,
                                                     const std::string& type_name) {
  MessagePtr message;
  ReadSignalTo(topic, type_name, &Keep, &message);
  return message;
}

Blackboard::MessagePtr Blackboard::ReadDataMessage(const std::string& topic,
                                                   const std::string& type_name) const {
  MessagePtr message;
  ReadDataTo(topic, type_name, &Keep, &message);
  return message;
}

std::vector<Stamped<google::protobuf::Message>> Blackboard::ReadDataHistoryMessages(
    const std::string& topic, const std::string& type_name, TimePoint since) const {
  std::vector<Stamped<google::protobuf::Message>> out;
  const Contents* c = Peek();
  if (c == nullptr) return out;
  std::lock_guard<SpinLock> lock(c->mutex);
  const Slot* slot = Find(*c, topic, type_name);
  if (slot == nullptr) {
    return out;
  }
  for (std::size_t i = 0; i < slot->data.size(); ++i) {
    const Entry& entry = slot->data[i];
    if (entry.time >= since) {
      out.push_back(Stamped<google::protobuf::Message>{entry.time, entry.message});
    }
  }
  return out;
}

std::size_t Blackboard::PendingSignals(const std::string& topic,
                                       const std::string& type_name) const {
  const Contents* c = Peek();
  if (c == nullptr) return 0;
  std::lock_guard<SpinLock> lock(c->mutex);
  const Slot* slot = Find(*c, topic, type_name);
  return slot == nullptr ? 0 : slot->signals.size();
}

void Blackboard::PublishMessage(const std::string& topic, Kind kind, MessagePtr message) {
  if (!message) {
    return;
  }
  const std::string& type_name = message->GetDescriptor()->full_name();  // before the move
  PublishNamed(topic, type_name, kind, std::move(message));
}

void Blackboard::PublishNamed(const std::string& topic, const std::string& type_name, Kind kind,
                              MessagePtr message) {
  const TimePoint now = Now();
  {
    Contents& c = Made();
    std::lock_guard<SpinLock> lock(c.mutex);
    Apply(SlotFor(c, topic, type_name), kind, message, now);
  }
  hub_->Publish(topic, type_name, kind, std::move(message), this);
}

void Blackboard::PublishCopy(const std::string& topic, Kind kind,
                             const google::protobuf::Message& message) {
  std::shared_ptr<google::protobuf::Message> copy(message.New());
  copy->CopyFrom(message);
  PublishMessage(topic, kind, std::move(copy));
}

void Blackboard::ScheduleWakeup(TimePoint time) {
  Contents& c = Made();
  std::lock_guard<SpinLock> lock(c.mutex);
  auto& wakeups = c.wakeups;
  wakeups.insert(std::upper_bound(wakeups.begin(), wakeups.end(), time), time);
  c.next_wakeup.store(wakeups.front().time_since_epoch().count(), std::memory_order_release);
}

std::optional<TimePoint> Blackboard::NextWakeup() const {
  const Contents* c = Peek();
  if (c == nullptr) return std::nullopt;
  std::lock_guard<SpinLock> lock(c->mutex);
  if (c->wakeups.empty()) {
    return std::nullopt;
  }
  return c->wakeups.front();
}

bool Blackboard::TakeDueWakeups(TimePoint now) {
  // None due yet (the usual answer) is told without the lock. A wake-up scheduled meanwhile by
  // another thread is taken at the next call, as if it had come just after this one.
  Contents* contents = Peek();
  if (contents == nullptr ||
      now.time_since_epoch().count() < contents->next_wakeup.load(std::memory_order_acquire)) {
    return false;
  }
  Contents& c = *contents;
  std::lock_guard<SpinLock> lock(c.mutex);
  auto& wakeups = c.wakeups;
  auto end = std::upper_bound(wakeups.begin(), wakeups.end(), now);
  if (end == wakeups.begin()) {
    return false;
  }
  wakeups.erase(wakeups.begin(), end);
  c.next_wakeup.store(wakeups.empty() ? Contents::kNoWakeup : wakeups.front().time_since_epoch().count(),
                      std::memory_order_release);
  return true;
}

}  // namespace kse::messaging
