#ifndef STATECHART_ENGINE_TIMEOUT_ACTION_H
#define STATECHART_ENGINE_TIMEOUT_ACTION_H

#include <string>

#include "statechart_engine/Interfaces.h"

namespace statechart_engine {

/// `/TimeoutAction.topic.ms`: (re)starts the timer of `topic` on the action's blackboard;
/// `TimeoutCheck(topic)` in a guard is generated as `_blk->TimeoutExpired("topic")`.
/// Generated action lists that also do other things derive from it and call
/// TimeoutAction::Execute() from their Execute().
class TimeoutAction : public IAction {
 public:
  TimeoutAction(std::string topic, int milliseconds);

  void Execute() override;

  const std::string& Topic() const noexcept { return topic_; }
  int Milliseconds() const noexcept { return milliseconds_; }

 private:
  std::string topic_;
  int milliseconds_;
};

}  // namespace statechart_engine

#endif
