#include "statechart_engine/Interfaces.h"

#include <atomic>
#include <charconv>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <system_error>
#include <utility>

#include "statechart_engine/Factories.h"
#include "statechart_engine/TimeoutAction.h"
#include "statechart_engine/TransitionSegment.h"

namespace statechart_engine {

ICondition::~ICondition() = default;
IAction::~IAction() = default;
IActivity::~IActivity() = default;
IStatechart::~IStatechart() = default;

namespace {

std::int64_t Microseconds(kse::messaging::TimePoint time) {
  return std::chrono::duration_cast<std::chrono::microseconds>(time.time_since_epoch()).count();
}

// The TimeoutMsg messages this thread set timers with, used again once nobody else holds one:
// a timer is set on most steps, and the message it replaces is let go at that very publish (by
// the blackboard and the hub), to be freed as the next one is made. The oldest of a few is
// looked at, so that each robot of a simulation, all on one thread, finds its own last one gone.
class TimeoutMessages {
 public:
  std::shared_ptr<TimeoutMsg> Next() {
    std::shared_ptr<TimeoutMsg>& oldest = ring_[next_];
    next_ = (next_ + 1) % kKept;
#ifndef __SANITIZE_THREAD__
    // use_count() is a relaxed load: the fence orders what the last other owner did with the
    // message before it let go (a release, in the count) before our writes. ThreadSanitizer
    // does not see fences, so a build with it makes every message anew.
    if (oldest && oldest.use_count() == 1) {
      std::atomic_thread_fence(std::memory_order_acquire);
      return oldest;  // only its wake-up time is ever set, and it is set again
    }
#endif
    oldest = std::make_shared<TimeoutMsg>();  // ours dropped: one still held stays with its holder
    return oldest;
  }

 private:
  static constexpr std::size_t kKept = 32;
  std::shared_ptr<TimeoutMsg> ring_[kKept];
  std::size_t next_ = 0;
};

}  // namespace

void InitTimeout(Blackboard& blackboard, const std::string& topic) {
  blackboard.Publish(topic, Kind::State, TimeoutMsg());
}

void SetTimeout(Blackboard& blackboard, const std::string& topic, std::chrono::milliseconds after) {
  const kse::messaging::TimePoint wakeup = blackboard.Now() + after;
  // Made as the message to publish, not copied into one: a timer is set on most steps.
  thread_local TimeoutMessages messages;
  std::shared_ptr<TimeoutMsg> message = messages.Next();
  char digits[24];
  const auto written = std::to_chars(digits, digits + sizeof digits, Microseconds(wakeup));
  message->set_wakeup(digits, static_cast<std::size_t>(written.ptr - digits));
  blackboard.PublishMessage(topic, Kind::State, std::shared_ptr<const TimeoutMsg>(std::move(message)));
  blackboard.ScheduleWakeup(wakeup);
}

bool TimeoutCheck(const Blackboard& blackboard, const std::shared_ptr<const TimeoutMsg>& message) {
  if (message == nullptr || message->wakeup().empty()) {
    return false;
  }
  std::int64_t wakeup = 0;
  const std::string& text = message->wakeup();
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), wakeup);
  if (error != std::errc() || end != text.data() + text.size()) {
    return false;  // not a wake-up time of ours (a foreign TimeoutMsg): no timer set
  }
  return Microseconds(blackboard.Now()) >= wakeup;
}

TimeoutCondition::TimeoutCondition(std::string topic) : topic_(std::move(topic)) {}

void TimeoutCondition::UserInit() { _blk->Subscribe(topic_); }

bool TimeoutCondition::Eval() {
  const auto timeout = _blk->ReadState<TimeoutMsg>(topic_);
  _blk->ProcessMessages();
  return TimeoutCheck(*_blk, timeout);
}

TimeoutAction::TimeoutAction(std::string topic, int milliseconds)
    : topic_(std::move(topic)), milliseconds_(milliseconds) {}

void TimeoutAction::UserInit() { InitTimeout(*_blk, topic_); }

void TimeoutAction::Execute() { SetTimeout(*_blk, topic_, std::chrono::milliseconds(milliseconds_)); }

TransitionSegmentBase::TransitionSegmentBase(State* source, State* target,
                                             Part<ICondition> condition, Part<IAction> action)
    : source_(source),
      target_(target),
      condition_(std::move(condition)),
      action_(std::move(action)),
      name_((source != nullptr ? source->Name() : std::string("?")) + "_TO_" +
            (target != nullptr ? target->Name() : std::string("?"))) {}

TransitionSegmentBase::~TransitionSegmentBase() = default;

}  // namespace statechart_engine
