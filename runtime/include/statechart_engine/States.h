#ifndef STATECHART_ENGINE_STATES_H
#define STATECHART_ENGINE_STATES_H

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "statechart_engine/Interfaces.h"
#include "statechart_engine/Part.h"

namespace statechart_engine {

class TransitionSegmentBase;
class Statechart;
class OrState;
class Definition;
namespace detail {
class EngineCore;
}

/// The node types of the statechart metamodel (docs/statecharts.md).
enum class StateKind { Or, And, Basic, Start, End, Condition };
const char* ToString(StateKind kind) noexcept;

/// A node of a statechart's Definition: a name, a label (the model's `0.3.2`, given by generated
/// code), a parent (nullptr for the root). The constructor appends the state to its parent's
/// children, so document order is creation order. States are created, and owned, by
/// Definition::Add (or Statechart::Add, for a statechart that builds its own definition).
///
/// A state is shared by every statechart made from its definition: what changes as a statechart
/// runs (whether the state is active, its region running, its activity) is the statechart's,
/// asked of it (Statechart::IsActive(state) ...).
///
/// OnEntry() and OnExit() are hooks for subclasses; the engine calls them on a statechart's
/// thread when the state becomes active or inactive in it (see Statechart for the order).
class State {
 public:
  virtual ~State();
  State(const State&) = delete;
  State& operator=(const State&) = delete;

  const std::string& Name() const noexcept { return name_; }
  /// The model's label; the name when none was given.
  const std::string& Label() const noexcept { return label_.empty() ? name_ : label_; }
  /// Sets the label (while its definition is being built).
  void SetLabel(std::string label) { label_ = std::move(label); }
  State* Parent() const noexcept { return parent_; }
  StateKind Kind() const noexcept { return kind_; }
  const std::vector<State*>& Children() const noexcept { return children_; }
  /// Outgoing transitions in the order the engine tries them (once the definition is complete:
  /// guarded ones first in reverse model order, then unguarded ones in model order).
  const std::vector<TransitionSegmentBase*>& Outgoing() const noexcept { return outgoing_; }
  /// The region this state belongs to: the nearest AND region or the root containing it (a
  /// region belongs to itself). While an activity of the region runs, nothing in it steps.
  OrState* Region() const noexcept { return region_; }
  /// 0 for the root.
  std::size_t Depth() const noexcept { return depth_; }
  /// The state's place in document order, the root's 0 (once the definition is complete).
  std::uint32_t Index() const noexcept { return index_; }

  /// Hooks for subclasses. State's own do nothing, and the engine does not call them: a state
  /// class that overrides neither costs a transition no call.
  virtual void OnEntry();
  virtual void OnExit();

 protected:
  State(std::string name, State* parent, StateKind kind);

 private:
  friend class detail::EngineCore;
  friend class Definition;

  // What a step reads first, in the object's first cache line.
  State* parent_;
  OrState* region_ = nullptr;
  StateKind kind_;
  // Whether OnEntry()/OnExit() are overridden, i.e. worth a call (once complete).
  bool calls_entry_ = true;
  bool calls_exit_ = true;
  std::uint32_t depth_;
  std::uint32_t index_ = 0;
  // Its place among the OR states (for the active child) or BASIC states (activity), as its
  // kind has one; and its region's place (running count, blackboard). Once complete.
  std::uint32_t slot_ = 0;
  std::uint32_t region_slot_ = 0;
  // 1 + the OR slot of its parent, 0 when the parent is not an OR state (once complete).
  std::uint32_t parent_or_slot_ = 0;
  // BASIC: where a statechart's activity lies (see TransitionSegmentBase::condition_at_).
  std::uint32_t activity_at_ = 0;
  std::vector<TransitionSegmentBase*> outgoing_;
  std::vector<State*> children_;
  std::string name_;
  std::string label_;
};

/// An OR state: exactly one active child; activating it activates its START. An OR state
/// whose parent is an AND state is a region: it owns a blackboard and a running flag. Its
/// outgoing transitions are tried whenever nothing fired inside and its region is not running
/// (not only once its END is active).
class OrState : public State {
 public:
  OrState(std::string name, State* parent);
  ~OrState() override;

  /// True for the children of an AND state.
  bool IsRegion() const noexcept;

 private:
  friend class detail::EngineCore;
  friend class Definition;

  State* start_ = nullptr;
};

/// An AND state: all its children (OR regions) are active together and step independently. Its
/// outgoing transitions are tried when no region took a transition and none is running.
class AndState : public State {
 public:
  AndState(std::string name, State* parent);
  ~AndState() override;
};

/// A BASIC state: entering it runs its activity once. While the activity runs, its region is
/// running: nothing in the region steps. A state without an activity finishes at once.
class BasicState : public State {
 public:
  BasicState(std::string name, State* parent, Part<IActivity> activity = nullptr);
  ~BasicState() override;

  bool HasActivity() const noexcept { return static_cast<bool>(activity_); }

 private:
  friend class detail::EngineCore;
  friend class Definition;

  Part<IActivity> activity_;
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
