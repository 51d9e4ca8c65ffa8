#ifndef STATECHART_ENGINE_STATES_H
#define STATECHART_ENGINE_STATES_H

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "statechart_engine/Interfaces.h"

namespace statechart_engine {

class TransitionSegmentBase;
class Statechart;
class OrState;
namespace detail {
class EngineCore;
}

/// The node types of the statechart metamodel (docs/statecharts.md).
enum class StateKind { Or, And, Basic, Start, End, Condition };
const char* ToString(StateKind kind) noexcept;

/// A node of the statechart: a name, a label (the model's `0.3.2`, given by generated code), a
/// parent (nullptr for the root), an active flag. The constructor appends the state to its
/// parent's children, so document order is creation order. States are normally created, and
/// owned, by Statechart::Add.
///
/// OnEntry() and OnExit() are hooks for subclasses; the engine calls them on its thread when the
/// state becomes active or inactive (see Statechart for the order).
class State {
 public:
  virtual ~State();
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  const std::string& Name() const noexcept { return name_; }
  /// The model's label; the name when none was given.
  const std::string& Label() const noexcept { return label_.empty() ? name_ : label_; }
  /// Sets the label (before the statechart is activated).
  void SetLabel(std::string label) { label_ = std::move(label); }
  State* Parent() const noexcept { return parent_; }
  StateKind Kind() const noexcept { return kind_; }
  /// Safe to call from any thread (the value may be stale; see Statechart::ActiveStates()).
  bool IsActive() const noexcept { return active_.load(std::memory_order_relaxed); }
  const std::vector<State*>& Children() const noexcept { return children_; }
  /// Outgoing transitions in the order the engine tries them (after Activate(): guarded ones
  /// first in reverse model order, then unguarded ones in model order).
  const std::vector<TransitionSegmentBase*>& Outgoing() const noexcept { return outgoing_; }
  /// The blackboard of the nearest AND region or root containing this state (after Activate()).
  Blackboard* Scope() const noexcept { return scope_; }
  /// The region this state belongs to: the nearest AND region or the root containing it (a
  /// region belongs to itself). While an activity of the region runs, nothing in it steps.
  OrState* Region() const noexcept { return region_; }
  /// 0 for the root.
  std::size_t Depth() const noexcept { return depth_; }

  /// Hooks for subclasses. State's own do nothing, and the engine does not call them: a state
  /// class that overrides neither costs a transition no call.
  virtual void OnEntry();
  virtual void OnExit();

 protected:
  State(std::string name, State* parent, StateKind kind);

 private:
  friend class detail::EngineCore;
  friend class Statechart;

  std::string name_;
  std::string label_;
  State* parent_;
  StateKind kind_;
  std::atomic<bool> active_{false};
  // Whether OnEntry()/OnExit() are overridden, i.e. worth a call (after Activate()).
  bool calls_entry_ = true;
  bool calls_exit_ = true;
  std::uint32_t depth_;
  std::vector<State*> children_;
  std::vector<TransitionSegmentBase*> outgoing_;
  Blackboard* scope_ = nullptr;
  OrState* region_ = nullptr;
};

/// An OR state: exactly one active child; activating it activates its START child. An OR state
/// whose parent is an AND state is a region: it owns a blackboard and a running flag. Its
/// outgoing transitions are tried whenever nothing fired inside and its region is not running
/// (not only once its END is active).
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
  /// For a region or the root: true while an activity of the region runs.
  bool IsRunning() const noexcept { return running_.load(std::memory_order_acquire) > 0; }

 private:
  friend class detail::EngineCore;

  State* active_child_ = nullptr;
  State* start_ = nullptr;
  std::unique_ptr<Blackboard> region_blackboard_;
  std::atomic<int> running_{0};  // activities of the region started and not finished
};

/// An AND state: all its children (OR regions) are active together and step independently. Its
/// outgoing transitions are tried when no region took a transition and none is running.
class AndState : public State {
 public:
  AndState(std::string name, State* parent);
  ~AndState() override;
};

/// A BASIC state: entering it runs its activity once. While the activity runs, its region is
/// running: nothing in the region steps. A null activity finishes at once.
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
  std::uint32_t relaunches_ = 0;  // entries while the activity still ran (engine's wake lock)
  std::uint32_t watch_slot_ = 0;  // the watchdog's slot of the activity (after Activate)
};

/// The initial pseudo-state of an OR state.
class StartState : public State {
 public:
  StartState(std::string name, State* parent);
  ~StartState() override;
};

/// The final state of an OR state. It never steps: once it is active, only the OR state's own
/// transitions can move on.
class EndState : public State {
 public:
  EndState(std::string name, State* parent);
  ~EndState() override;
};

/// A CONDITION connector: a transition into it fires only together with a chain of outgoing
/// transitions whose guards hold (tried in the engine's order), ending in a state that is not a
/// connector; the chain is one step.
class ConditionConnector : public State {
 public:
  ConditionConnector(std::string name, State* parent);
  ~ConditionConnector() override;
};

}  // namespace statechart_engine

#endif
