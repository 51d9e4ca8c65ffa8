#include "statechart_engine/Interfaces.h"

#include <charconv>
#include <chrono>
#include <cstdint>
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

}  // namespace

void InitTimeout(Blackboard& blackboard, const std::string& topic) {
  blackboard.Publish(topic, Kind::State, TimeoutMsg());
}

void SetTimeout(Blackboard& blackboard, const std::string& topic, std::chrono::milliseconds after) {
  const kse::messaging::TimePoint wakeup = blackboard.Now() + after;
  // Made as the message to publish, not copied into one: a timer is set on most steps.
  auto message = std::make_shared<TimeoutMsg>();
  message->set_wakeup(std::to_string(Microseconds(wakeup)));
  blackboard.PublishMessage(topic, Kind::State, std::move(message));
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
                                             std::unique_ptr<ICondition> condition,
                                             std::unique_ptr<IAction> action)
    : source_(source),
      target_(target),
      condition_(std::move(condition)),
      action_(std::move(action)),
      name_((source != nullptr ? source->Name() : std::string("?")) + "_TO_" +
            (target != nullptr ? target->Name() : std::string("?"))) {}

TransitionSegmentBase::~TransitionSegmentBase() = default;

}  // namespace statechart_engine
