#ifndef STATECHART_ENGINE_TRANSITION_SEGMENT_H
#define STATECHART_ENGINE_TRANSITION_SEGMENT_H

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "statechart_engine/Interfaces.h"
#include "statechart_engine/States.h"

namespace statechart_engine {

/// A transition (or one segment of a chain through condition connectors): source, target, an
/// optional guard (none = always true) and an optional action. Named `<source>_TO_<target>`.
class TransitionSegmentBase {
 public:
  TransitionSegmentBase(State* source, State* target, std::unique_ptr<ICondition> condition,
                        std::unique_ptr<IAction> action);
  virtual ~TransitionSegmentBase();
  TransitionSegmentBase(const TransitionSegmentBase&) = delete;
  TransitionSegmentBase& operator=(const TransitionSegmentBase&) = delete;

  State* Source() const noexcept { return source_; }
  State* Target() const noexcept { return target_; }
  ICondition* Condition() const noexcept { return condition_.get(); }
  IAction* Action() const noexcept { return action_.get(); }
  const std::string& Name() const noexcept { return name_; }
  bool IsGuarded() const noexcept { return condition_ != nullptr; }

  /// The lowest common ancestor (after Activate()): the lowest OR state that properly contains
  /// both source and target.
  State* LowestCommonAncestor() const noexcept { return lca_; }
  /// The blackboard given to the condition and the action (after Activate()).
  Blackboard* Scope() const noexcept { return scope_; }

 private:
  friend class detail::EngineCore;

  State* source_;
  State* target_;
  std::unique_ptr<ICondition> condition_;
  std::unique_ptr<IAction> action_;
  std::string name_;

  // Computed by the engine when the statechart is activated.
  State* lca_ = nullptr;
  State* exit_top_ = nullptr;         // the child of lca_ that contains the source
  // From the child of lca_ that contains the target down to it, in the engine's table of paths
  // (one allocation for every transition of the statechart).
  State* const* entry_path_ = nullptr;
  Blackboard* scope_ = nullptr;
  std::uint32_t entry_length_ = 0;
};

/// A transition between states of the given types (as the generator names them).
template <class Src, class Dst>
class TransitionSegment final : public TransitionSegmentBase {
  static_assert(std::is_base_of_v<State, Src>, "the source must be a State");
  static_assert(std::is_base_of_v<State, Dst>, "the target must be a State");

 public:
  TransitionSegment(Src* source, Dst* target, std::unique_ptr<ICondition> condition = nullptr,
                    std::unique_ptr<IAction> action = nullptr)
      : TransitionSegmentBase(source, target, std::move(condition), std::move(action)) {}

  Src* TypedSource() const noexcept { return static_cast<Src*>(Source()); }
  Dst* TypedTarget() const noexcept { return static_cast<Dst*>(Target()); }
};

}  // namespace statechart_engine

#endif
