#ifndef STATECHART_ENGINE_DEFINITION_H
#define STATECHART_ENGINE_DEFINITION_H

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "statechart_engine/Part.h"
#include "statechart_engine/States.h"
#include "statechart_engine/TransitionSegment.h"

namespace statechart_engine {

/// The structure of a statechart, built once and shared by every Statechart made from it
/// (ADR 0032): its states, its transitions and how each statechart makes their guards, actions
/// and activities. A generated statechart class builds its definition the first time one is
/// made, and each statechart then holds only what changes as it runs.
///
///   auto definition = std::make_shared<Definition>("Goalie");
///   auto* start = definition->Add<StartState>("Start", definition->Root());
///   auto* scan = definition->Add<BasicState>("Scan", definition->Root(), Make<ScanActivity>());
///   definition->AddTransition(start, scan, Make<BallSeen>(), Make<TimeoutAction>("behavior", 250));
///   definition->Complete();
///   Statechart one(definition, hub), two(definition, hub);
///
/// Built on one thread; once Complete() (the first statechart activated completes it), it no
/// longer changes and is read by any number of threads.
class Definition {
 public:
  explicit Definition(std::string name);
  ~Definition();
  Definition(const Definition&) = delete;
  Definition& operator=(const Definition&) = delete;

  const std::string& Name() const noexcept { return root_->Name(); }
  /// The root OR state (named as the definition); the parent of the top states.
  OrState* Root() const noexcept { return root_; }

  /// Creates a state owned by the definition: Add<OrState>("Node_0_3", parent).
  template <class S, class... A>
  S* Add(A&&... args) {
    static_assert(std::is_base_of_v<State, S>, "Add<S>: S must be a State");
    auto owned = std::make_unique<S>(std::forward<A>(args)...);
    S* raw = owned.get();
    AdoptState(std::move(owned));
    return raw;
  }

  /// Creates a transition owned by the definition; model order is the order of these calls.
  template <class Src, class Dst>
  TransitionSegment<Src, Dst>* AddTransition(Src* source, Dst* target,
                                             Part<ICondition> condition = nullptr,
                                             Part<IAction> action = nullptr) {
    auto owned = std::make_unique<TransitionSegment<Src, Dst>>(source, target, std::move(condition),
                                                               std::move(action));
    auto* raw = owned.get();
    AdoptTransition(std::move(owned));
    return raw;
  }

  /// Checks the structure and computes what the engine needs (transition order, paths,
  /// regions, the layout of a statechart's memory). Once; later calls do nothing. Throws
  /// std::logic_error when the structure is invalid (e.g. an OR state without START).
  void Complete();
  bool IsComplete() const noexcept { return complete_.load(std::memory_order_acquire); }

  /// Every state in document order, the root first (before Complete(), the tree built so far).
  std::vector<State*> States() const;
  /// Every transition in model order.
  std::vector<TransitionSegmentBase*> Transitions() const;
  /// True when a part was given as an object (see Part): only one statechart can be made.
  bool HasGivenParts() const noexcept { return given_parts_; }

 private:
  friend class detail::EngineCore;

  void AdoptState(std::unique_ptr<State> state);
  void AdoptTransition(std::unique_ptr<TransitionSegmentBase> transition);
  void CheckStructure() const;
  void ComputeTransition(TransitionSegmentBase& transition);
  void Layout();
  [[noreturn]] void Fail(const std::string& why) const;

  std::mutex complete_mutex_;
  std::atomic<bool> complete_{false};
  mutable std::atomic<bool> taken_{false};  // a statechart took the given parts
  bool given_parts_ = false;

  OrState* root_;
  std::vector<std::unique_ptr<State>> owned_states_;  // the root first
  std::vector<std::unique_ptr<TransitionSegmentBase>> owned_transitions_;  // model order

  // Once complete
  std::vector<State*> states_;             // document order
  std::vector<OrState*> or_states_;        // by slot
  std::vector<OrState*> regions_;          // by region slot: the root, then AND regions
  std::vector<BasicState*> basic_states_;  // by slot
  std::vector<State*> entry_paths_;        // every transition's entry path, one after the other
  // By BASIC state slot, asked of the first statechart activated (for the watchdog's reports).
  mutable std::once_flag activity_names_once_;
  mutable std::vector<std::string> activity_names_;

  // The layout of a statechart's block: offsets of its arrays and made parts, and its size.
  std::size_t activity_runs_at_ = 0;  // std::atomic<bool> per BASIC state
  std::size_t active_child_at_ = 0;  // std::atomic<State*> per OR state
  std::size_t running_at_ = 0;       // std::atomic<int> per region
  std::size_t launches_at_ = 0;      // std::atomic<std::uint32_t> per BASIC state
  std::size_t relaunches_at_ = 0;    // std::uint32_t per BASIC state
  std::size_t boards_at_ = 0;        // kse::messaging::Blackboard per region but the root
  std::size_t block_size_ = 0;
  std::size_t block_align_ = alignof(std::max_align_t);
};

}  // namespace statechart_engine

#endif
