#ifndef STATECHART_ENGINE_STATECHART_H
#define STATECHART_ENGINE_STATECHART_H

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "kse/messaging/Blackboard.h"
#include "kse/messaging/MessageHub.h"
#include "statechart_engine/Interfaces.h"
#include "statechart_engine/States.h"
#include "statechart_engine/TransitionSegment.h"

namespace statechart_engine {

struct Options {
  /// Run activities on the engine's thread, inside the transition that enters their state.
  bool inline_activities = false;
  /// Size of the activity worker pool (0 behaves like inline_activities = true).
  std::size_t worker_threads = 2;
};

/// The root of a statechart: an OR state that owns every state and transition created through
/// it, the root blackboard, the activity worker pool and (between Start() and Stop()) the
/// engine thread.
///
/// Semantics (docs/runtime-api.md, reference §8):
/// - Activating an OR state activates its START; an AND state activates all its regions.
/// - One Step() steps the root: stepping an OR state steps its active child first (inner
///   transitions win: if anything fired inside, nothing else is tried on that path), then, if
///   the active child is not busy, tries the child's outgoing transitions, guarded ones before
///   unguarded ones, each group in model order; the first whose guard holds fires. An AND state
///   steps each of its regions. A BASIC state is busy while its activity runs, an OR state
///   until its END is active, an AND state until all its regions are done.
/// - Firing: exit the source's active descendants, the source and its ancestors below the
///   lowest common ancestor (innermost first, OnExit), run the action, enter the target's
///   ancestors below the LCA top-down and the target (OnEntry), then its default completion
///   (START of an OR state, every region of an AND state, the activity of a BASIC state).
///   AND regions are exited in reverse document order and entered in document order.
/// - A transition into a ConditionConnector fires only together with a chain of connector
///   transitions whose guards hold (tried in the same order, backtracking) that ends outside
///   connectors; all guards are evaluated first, then the segments fire in order.
/// - Guards and actions that throw are reported on standard error and counted; a throwing
///   guard counts as false.
class Statechart : public OrState {
 public:
  using Observer = std::function<void(const TransitionSegmentBase&)>;

  Statechart(std::string name, kse::messaging::MessageHub& hub, Options options = {});
  ~Statechart() override;

  /// Creates a state owned by this statechart: Add<OrState>("Node_0_3", Node_0).
  /// The structure is fixed once the statechart is activated.
  template <class S, class... A>
  S* Add(A&&... args) {
    static_assert(std::is_base_of_v<State, S>, "Add<S>: S must be a State");
    auto owned = std::make_unique<S>(std::forward<A>(args)...);
    S* raw = owned.get();
    AdoptState(std::move(owned));
    return raw;
  }

  /// Creates a transition owned by this statechart; model order is the order of these calls.
  template <class Src, class Dst>
  TransitionSegment<Src, Dst>* AddTransition(Src* source, Dst* target,
                                             std::unique_ptr<ICondition> condition = nullptr,
                                             std::unique_ptr<IAction> action = nullptr) {
    auto owned = std::make_unique<TransitionSegment<Src, Dst>>(source, target, std::move(condition),
                                                               std::move(action));
    auto* raw = owned.get();
    AdoptTransition(std::move(owned));
    return raw;
  }

  /// Activates (if not yet) and runs the engine on its own thread until Stop(). The engine
  /// re-evaluates when a message is published, an activity ends, a timer expires or Wake() is
  /// called (and at least once a second).
  void Start();
  /// Stops the engine thread and waits for running activities. The configuration is kept;
  /// Start() resumes. Safe to call when not started.
  void Stop();
  bool IsStarted() const noexcept;

  /// Checks the structure, gives blackboards to regions, conditions, actions and activities,
  /// calls every UserInit() and enters the root. Once; later calls do nothing. Throws
  /// std::logic_error when the structure is invalid (e.g. an OR state without START).
  void Activate();
  bool IsActivated() const noexcept;
  /// One run-to-completion step (activates first if needed): true when a transition fired.
  bool Step();
  /// Steps, waits for running activities and steps again until nothing fires and nothing runs.
  /// Gives up after 1,000,000 transitions (a statechart that loops forever), with a warning.
  void RunUntilStable();
  /// As above with an explicit bound on the transitions taken; false when it was reached.
  bool RunUntilStable(std::size_t max_transitions);

  /// Names of every active state, in document order (the root first). Thread-safe.
  std::vector<std::string> ActiveStates() const;
  /// Activities that threw.
  std::size_t ActivityFailures() const noexcept;
  /// Guards that threw (each counted as false).
  std::size_t GuardFailures() const noexcept;
  /// Actions, OnEntry/OnExit hooks and observers that threw.
  std::size_t ActionFailures() const noexcept;
  /// Transition segments taken so far.
  std::size_t TransitionsTaken() const noexcept;
  /// Activities started and not finished yet.
  std::size_t RunningActivities() const noexcept;

  /// Called on the engine's thread for every transition segment taken, after it completed.
  void SetObserver(Observer observer);
  /// Makes the engine thread re-evaluate (e.g. after a ManualClock moved or a guard reads
  /// something other than messages).
  void Wake();

  kse::messaging::MessageHub& Hub() const noexcept;
  Blackboard& RootBlackboard() const noexcept;
  const Options& GetOptions() const noexcept;
  /// Every state of the tree in document order (after Activate()).
  std::vector<State*> States() const;
  /// Every transition in model order.
  std::vector<TransitionSegmentBase*> Transitions() const;

 private:
  void AdoptState(std::unique_ptr<State> state);
  void AdoptTransition(std::unique_ptr<TransitionSegmentBase> transition);

  std::unique_ptr<detail::EngineCore> core_;
};

}  // namespace statechart_engine

#endif
