#ifndef STATECHART_ENGINE_TRANSITION_SEGMENT_H
#define STATECHART_ENGINE_TRANSITION_SEGMENT_H

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "statechart_engine/Interfaces.h"
#include "statechart_engine/Part.h"
#include "statechart_engine/States.h"

namespace statechart_engine {

/// A transition of a Definition (or one segment of a chain through condition connectors):
/// source, target, an optional guard (none = always true) and an optional action, made for each
/// statechart of the definition (see Part). Named `<source>_TO_<target>`.
class TransitionSegmentBase {
 public:
  TransitionSegmentBase(State* source, State* target, Part<ICondition> condition,
                        Part<IAction> action);
  virtual ~TransitionSegmentBase();
  TransitionSegmentBase(const TransitionSegmentBase&) = delete;
  TransitionSegmentBase& operator=(const TransitionSegmentBase&) = delete;

  State* Source() const noexcept { return source_; }
  State* Target() const noexcept { return target_; }
  const std::string& Name() const noexcept { return name_; }
  /// The model's expression ("[guard]/actions"), as the generator gives it; empty when none was.
  /// For whoever shows the transition (the live monitor), never for the engine.
  const std::string& Text() const noexcept { return text_; }
  /// Sets the expression's text (while its definition is being built).
  void SetText(std::string text) { text_ = std::move(text); }
  bool IsGuarded() const noexcept { return static_cast<bool>(condition_); }
  bool HasAction() const noexcept { return static_cast<bool>(action_); }

  /// The lowest common ancestor (once the definition is complete): the lowest OR state that
  /// properly contains both source and target.
  State* LowestCommonAncestor() const noexcept { return lca_; }
  /// The region whose blackboard the condition and the action get (once complete): the
  /// nearest AND region or the root containing the lowest common ancestor.
  OrState* ScopeRegion() const noexcept { return scope_; }

 private:
  friend class detail::EngineCore;
  friend class Definition;

  // What firing reads, first.
  State* source_;
  State* target_;
  State* exit_top_ = nullptr;  // the child of lca_ that contains the source (once complete)
  // From the child of lca_ that contains the target down to it, in the definition's table of
  // paths (one allocation for every transition).
  State* const* entry_path_ = nullptr;
  // Where the condition and the action of a statechart lie (Definition::Layout): 0 none, 1
  // given, odd the slot of a pointer to a created one, even the offset of a made one.
  std::size_t condition_at_ = 0;
  std::size_t action_at_ = 0;
  std::uint32_t entry_length_ = 0;
  // From a BASIC or START state to a BASIC or END sibling (once complete): firing leaves and
  // enters one state each, with nothing above or below them to walk.
  bool between_siblings_ = false;
  // When the configuration after firing is one path from the root (no AND state on it): its
  // deepest state, where the next step starts (once complete); null otherwise.
  State* leaf_after_ = nullptr;
  State* lca_ = nullptr;
  OrState* scope_ = nullptr;
  Part<ICondition> condition_;
  Part<IAction> action_;
  std::string name_;
  std::string text_;
};

/// A transition between states of the given types (as the generator names them).
template <class Src, class Dst>
class TransitionSegment final : public TransitionSegmentBase {
  static_assert(std::is_base_of_v<State, Src>, "the source must be a State");
  static_assert(std::is_base_of_v<State, Dst>, "the target must be a State");

 public:
  TransitionSegment(Src* source, Dst* target, Part<ICondition> condition = nullptr,
                    Part<IAction> action = nullptr)
      : TransitionSegmentBase(source, target, std::move(condition), std::move(action)) {}

  Src* TypedSource() const noexcept { return static_cast<Src*>(Source()); }
  Dst* TypedTarget() const noexcept { return static_cast<Dst*>(Target()); }
};

}  // namespace statechart_engine

#endif
