#ifndef STATECHART_ENGINE_STATECHART_H
#define STATECHART_ENGINE_STATECHART_H

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
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
  /// Run activities on the calling thread, inside the transition that enters their state (the
  /// simulator does, so that a match is deterministic). An inline activity never leaves its
  /// region running.
  bool inline_activities = false;
  /// Size of the activity worker pool, as Monas' (0 behaves like inline_activities = true).
  std::size_t worker_threads = 10;
};

/// The root of a statechart: an OR state that owns every state and transition created through
/// it, the root blackboard, the activity worker pool and (between Start() and Stop()) the
/// engine thread.
///
/// The rules are those of the Monas engine the original KSE generated code for; docs/semantics.md
/// states them with an example. In short:
/// - Activating an OR state activates its START; an AND state activates all its regions.
/// - Every state belongs to a region (the nearest AND region, or the root) with a running flag:
///   entering a BASIC state starts its activity and sets the flag until the activity returns;
///   while it is set, nothing in the region steps.
/// - One Step() steps the root. Stepping an OR state steps its active child; if nothing fired
///   there and the region is not running, the OR state tries its own outgoing transitions. An
///   AND state steps every region; if none fired and none is running, it tries its own. END
///   never steps; any other state tries its own transitions.
/// - A state's transitions are tried guarded ones first, in reverse model order, then unguarded
///   ones in model order; the first whose guard holds fires. A transition into a CONDITION
///   connector fires only together with a chain of connector transitions whose guards hold
///   (same order), taken as one step.
/// - Firing exits the source and its ancestors below the lowest common ancestor (innermost
///   first), runs the action, enters the target's ancestors top-down and the target.
/// - The engine re-evaluates (steps until nothing fires) only when it is woken: once activated,
///   when an activity returns, and when a wake-up time asked for by a TimeoutAction passes. A
///   publish does not wake it; guards read blackboard snapshots (Blackboard::ProcessMessages).
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

  /// Activates (if not yet) and runs the engine on its own thread until Stop(): whenever it is
  /// woken (an activity returned, a wake-up time passed), it steps until nothing fires.
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
  /// One step now, woken or not (activates first if needed): true when a transition fired.
  bool Step();
  /// What the engine thread does when it wakes: if the engine is woken (just activated, an
  /// activity returned, or a wake-up time has passed on its clock), steps until nothing fires.
  /// Does not wait for running activities. True when it stepped.
  bool RunIfWoken();
  /// RunIfWoken(), then waits for running activities and runs again, until nothing runs and the
  /// engine is not woken. Wake-up times still ahead are not waited for. Gives up after
  /// 1,000,000 transitions (a statechart that loops forever), with a warning.
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
  /// Steps begun so far (an observer sees the number of the step that took the segment).
  std::size_t StepNumber() const noexcept;
  /// The earliest time a TimeoutAction asked the engine to wake up at and that has not been
  /// taken yet, if any (what a driver of a ManualClock advances to).
  std::optional<kse::messaging::TimePoint> NextWakeup() const;
  /// Activities started and not finished yet.
  std::size_t RunningActivities() const noexcept;

  /// Called on the engine's thread for every transition segment taken, after it completed.
  void SetObserver(Observer observer);
  /// Makes the engine thread look at its clock again (e.g. after a ManualClock moved): it
  /// steps if a wake-up time has passed. It does not make the engine re-evaluate otherwise.
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
