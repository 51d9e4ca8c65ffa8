#ifndef STATECHART_ENGINE_TIMEOUT_ACTION_H
#define STATECHART_ENGINE_TIMEOUT_ACTION_H

#include <chrono>
#include <memory>
#include <string>

#include "kse/messages/Behavior.pb.h"
#include "statechart_engine/Interfaces.h"

namespace statechart_engine {

// Timers as the Monas engine kept them: a timer is the TimeoutMsg{wakeup} State message on a
// topic, so every reader of that topic shares it. `wakeup` holds the wake-up time as
// microseconds on the hub's clock (empty: no timer set).

/// What every TimeoutAction does at start: publishes an empty TimeoutMsg on the topic.
void InitTimeout(Blackboard& blackboard, const std::string& topic);

/// `TimeoutAction.topic.ms`: publishes TimeoutMsg{now + after} on the topic and asks the engine
/// to wake up at that time.
void SetTimeout(Blackboard& blackboard, const std::string& topic, std::chrono::milliseconds after);

/// `TimeoutCheck(topic)`, given the TimeoutMsg a guard read from its blackboard: true once the
/// wake-up time has passed on the blackboard's clock; false while there is none.
bool TimeoutCheck(const Blackboard& blackboard, const std::shared_ptr<const TimeoutMsg>& message);

/// The guard `[TimeoutCheck(topic)]` on its own, as the generator writes it: reads the topic's
/// TimeoutMsg, refreshes the blackboard, then decides (for charts written by hand).
class TimeoutCondition : public ICondition {
 public:
  explicit TimeoutCondition(std::string topic);

  void UserInit() override;
  bool Eval() override;

 private:
  std::string topic_;
};

/// The action `/TimeoutAction.topic.ms` on its own (generated action lists that do more call
/// InitTimeout and SetTimeout themselves).
class TimeoutAction : public IAction {
 public:
  TimeoutAction(std::string topic, int milliseconds);

  void UserInit() override;
  void Execute() override;

  const std::string& Topic() const noexcept { return topic_; }
  int Milliseconds() const noexcept { return milliseconds_; }

 private:
  std::string topic_;
  int milliseconds_;
};

}  // namespace statechart_engine

#endif
