#include "statechart_engine/Interfaces.h"

#include <utility>

#include "statechart_engine/Factories.h"
#include "statechart_engine/TimeoutAction.h"
#include "statechart_engine/TransitionSegment.h"

namespace statechart_engine {

ICondition::~ICondition() = default;
IAction::~IAction() = default;
IActivity::~IActivity() = default;
IStatechart::~IStatechart() = default;

TimeoutAction::TimeoutAction(std::string topic, int milliseconds)
    : topic_(std::move(topic)), milliseconds_(milliseconds) {}

void TimeoutAction::Execute() {
  if (_blk != nullptr) {
    _blk->SetTimeout(topic_, std::chrono::milliseconds(milliseconds_));
  }
}

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
