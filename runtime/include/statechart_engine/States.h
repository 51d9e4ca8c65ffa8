#ifndef STATECHART_ENGINE_STATES_H
#define STATECHART_ENGINE_STATES_H

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "statechart_engine/Interfaces.h"

namespace statechart_engine {

class TransitionSegmentBase;
class Statechart;
namespace detail {
class EngineCore;
}

/// The node types of the statechart metamodel (reference §1).
enum class StateKind { Or, And, Basic, Start, End, Condition };
const char* ToString(StateKind kind) noexcept;

/// A node of the statechart: a name, a parent (nullptr for the root), an active flag.
/// The constructor appends the state to its parent's children, so document order is creation
/// order. States are normally created, and owned, by Statechart::Add.
///
/// OnEntry() and OnExit() are hooks for subclasses; the engine calls them on its thread when the
/// state becomes active or inactive (see Statechart for the order).
class State {
 public:
  virtual ~State();
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  const std::string& Name() const noexcept { return name_; }
  State* Parent() const noexcept { return parent_; }
  StateKind Kind() const noexcept { return kind_; }
  /// Safe to call from any thread (the value may be stale; see Statechart::ActiveStates()).
  bool IsActive() const noexcept { return active_.load(std::memory_order_relaxed); }
  const std::vector<State*>& Children() const noexcept { return children_; }
  /// Outgoing transitions in the order the engine tries them (after Activate(): guarded ones
  /// first, each group in model order).
  const std::vector<TransitionSegmentBase*>& Outgoing() const noexcept { return outgoing_; }
  /// The blackboard of the nearest AND region or root containing this state (after Activate()).
  Blackboard* Scope() const noexcept { return scope_; }
  /// 0 for the root.
  std::size_t Depth() const noexcept { return depth_; }

  virtual void OnEntry() {}
  virtual void OnExit() {}

 protected:
  State(std::string name, State* parent, StateKind kind);

 private:
  friend class detail::EngineCore;
  friend class Statechart;

  std::string name_;
  State* parent_;
  StateKind kind_;
  std::size_t depth_;
  std::atomic<bool> active_{false};
  std::vector<State*> children_;
  std::vector<TransitionSegmentBase*> outgoing_;
  Blackboard* scope_ = nullptr;
};

/// An OR state: exactly one active child; activating it activates its START child. An OR state
/// whose parent is an AND state is a region and owns a blackboard. Its outgoing transitions are
/// tried only once it is done, i.e. its END child is active.
class OrState : public State {
 public:
  OrState(std::string name, State* parent);
  ~OrState() override;

  /// The active child (engine thread only), or nullptr.
  State* ActiveChild() const noexcept { return active_child_; }
  /// True for the children of an AND state.
  bool IsRegion() const noexcept;
  /// The region's own blackboard (after Activate()), nullptr for other OR states; the root's
  /// blackboard is Statechart::RootBlackboard().
  Blackboard* RegionBlackboard() const noexcept { return region_blackboard_.get(); }

 private:
  friend class detail::EngineCore;

  State* active_child_ = nullptr;
  State* start_ = nullptr;
  State* end_ = nullptr;
  std::unique_ptr<Blackboard> region_blackboard_;
};

/// An AND state: all its children (OR regions) are active together. Its outgoing transitions
/// are tried once every region is done.
class AndState : public State {
 public:
  AndState(std::string name, State* parent);
  ~AndState() override;
};

/// A BASIC state: entering it runs its activity once. While the activity runs, the transitions
/// leaving the state are not tried. A null activity finishes at once.
class BasicState : public State {
 public:
  BasicState(std::string name, State* parent, std::unique_ptr<IActivity> activity = nullptr);
  ~BasicState() override;

  IActivity* Activity() const noexcept { return activity_.get(); }
  /// True while the activity started by the last entry has not finished.
  bool IsRunning() const noexcept { return running_.load(std::memory_order_acquire); }
  /// How many times the activity has been started.
  std::size_t Launches() const noexcept { return launches_.load(std::memory_order_relaxed); }

 private:
  friend class detail::EngineCore;

  std::unique_ptr<IActivity> activity_;
  std::atomic<bool> running_{false};
  std::atomic<std::size_t> launches_{0};
};

/// The initial pseudo-state of an OR state.
class StartState : public State {
 public:
  StartState(std::string name, State* parent);
  ~StartState() override;
};

/// The final state of an OR state: once active, the OR state is done.
class EndState : public State {
 public:
  EndState(std::string name, State* parent);
  ~EndState() override;
};

/// A CONDITION connector: a transition into it fires only together with a chain of outgoing
/// transitions whose guards hold, ending in a state that is not a connector.
class ConditionConnector : public State {
 public:
  ConditionConnector(std::string name, State* parent);
  ~ConditionConnector() override;
};

}  // namespace statechart_engine

#endif
