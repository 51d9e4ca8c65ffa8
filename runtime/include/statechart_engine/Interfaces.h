#ifndef STATECHART_ENGINE_INTERFACES_H
#define STATECHART_ENGINE_INTERFACES_H

#include <string>

#include "kse/messaging/Blackboard.h"
#include "kse/messaging/Kind.h"

namespace statechart_engine {

using Blackboard = kse::messaging::Blackboard;
using Kind = kse::messaging::Kind;

/// A transition guard. The engine gives it the blackboard of the transition's scope (the
/// nearest AND region or the root containing the transition's lowest common ancestor) before
/// UserInit(), which usually subscribes to the topics Eval() reads.
class ICondition {
 public:
  virtual ~ICondition();
  virtual void UserInit() {}
  virtual bool Eval() = 0;

  /// Set by the engine; tests may set it to use a condition on its own.
  void SetBlackboard(Blackboard* blackboard) noexcept { _blk = blackboard; }
  Blackboard* GetBlackboard() const noexcept { return _blk; }

 protected:
  Blackboard* _blk = nullptr;
};

/// A transition action, run between leaving the source and entering the target.
class IAction {
 public:
  virtual ~IAction();
  virtual void UserInit() {}
  virtual void Execute() = 0;

  void SetBlackboard(Blackboard* blackboard) noexcept { _blk = blackboard; }
  Blackboard* GetBlackboard() const noexcept { return _blk; }

 protected:
  Blackboard* _blk = nullptr;
};

/// The work of a BASIC state: Execute() runs once each time the state is entered, on the
/// engine's worker pool (or inline, see Options). Its return value is ignored. An exception is
/// reported on standard error, counted (Statechart::ActivityFailures()) and treated as finished.
/// The blackboard is that of the nearest AND region or root containing the state.
class IActivity {
 public:
  virtual ~IActivity();
  virtual void UserInit() {}
  virtual int Execute() = 0;
  virtual std::string GetName() = 0;

  void SetBlackboard(Blackboard* blackboard) noexcept { _blk = blackboard; }
  Blackboard* GetBlackboard() const noexcept { return _blk; }

 protected:
  Blackboard* _blk = nullptr;
};

}  // namespace statechart_engine

#endif
