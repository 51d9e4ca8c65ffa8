#ifndef STATECHART_ENGINE_STATECHART_H
#define STATECHART_ENGINE_STATECHART_H

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "kse/messaging/Blackboard.h"
#include "kse/messaging/MessageHub.h"
#include "statechart_engine/Definition.h"
#include "statechart_engine/Interfaces.h"
#include "statechart_engine/States.h"
#include "statechart_engine/TransitionSegment.h"

namespace statechart_engine {

/// Something the engine tells its user: a failure of user code, a call into user code that runs
/// longer than the watchdog's limit (and later its end), Stop() giving up on calls that do not
/// return, or a warning. Failures keep the texts they always had.
struct EngineReport {
  enum class Kind {
    Failure,       ///< a guard, action, activity or hook threw (and was counted)
    Overrun,       ///< a call has run longer than its watchdog limit and is still running
    OverrunEnded,  ///< that call returned at last
    Abandoned,     ///< Stop() or the destructor stopped waiting for calls that still run
    Warning,       ///< anything else (RunUntilStable's bound, a connector chain too deep)
  };
  Kind kind = Kind::Warning;
  std::string chart;  ///< the statechart's name
  std::string text;   ///< what happened, without the statechart's name
  /// Overrun and OverrunEnded: the call, e.g. "activity 'Scan' of state 0.2 'Node_0_2'" or
  /// "guard of transition 'A_TO_B' (0.1 -> 0.2)"; the same number in both reports of one
  /// overrun (never 0); how long the call had run when the watchdog looked.
  std::string call;
  std::uint64_t overrun = 0;
  std::chrono::milliseconds running{0};
};
const char* ToString(EngineReport::Kind kind) noexcept;
/// The line the default reporter writes on standard error: `[kse] statechart 'X': text`.
std::string ToString(const EngineReport& report);

/// Receives the engine's reports. It is called on whatever thread noticed (the engine's, a
/// worker's, the watchdog's), possibly on several at once, so it must be thread-safe, return
/// promptly and not call the statechart (whose engine may be stuck in the call reported).
using Reporter = std::function<void(const EngineReport&)>;

struct Options {
  /// Run activities on the calling thread, inside the transition that enters their state (the
  /// simulator does, so that a match is deterministic). An inline activity never leaves its
  /// region running.
  bool inline_activities = false;
  /// With inline activities: an activity's run lasts until the next RunUntilStable() or
  /// RunIfWoken() call, as a run on a worker takes time. Execute() runs when its state is
  /// entered; its region stays running (nothing in it steps) until that next call, which ends
  /// the run and re-evaluates. A driver that calls once per decision cycle (the simulated robot)
  /// so gives every activity at least one cycle: a loop through an activity's state takes one
  /// round per cycle instead of spinning inside one call, and the transitions are those a
  /// worker pool gives. Not for a statechart run by Start(): its engine thread ignores it.
  bool inline_activities_last_until_next_run = false;
  /// Size of the activity worker pool, as Monas' (0 behaves like inline_activities = true).
  std::size_t worker_threads = 10;
  /// The watchdog reports (once, as EngineReport::Kind::Overrun) every call into user code of
  /// this statechart (activity, guard, action, entry/exit hook, UserInit, observer) that runs
  /// longer than this. A behaviour step on a Nao takes milliseconds. Zero turns it off.
  /// SetActivityWatchdogLimit() sets it for one activity.
  std::chrono::milliseconds watchdog_limit{1000};
  /// Stop() and the destructor wait at most this long for the engine thread and the running
  /// activities; what still runs then is reported (Kind::Abandoned) and no longer waited for.
  std::chrono::milliseconds stop_limit{1000};
  /// Where reports go; empty: standard error, one line each (see ToString(EngineReport)).
  Reporter reporter;
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
/// - Guards and actions that throw are reported (Options::reporter, standard error by default)
///   and counted; a throwing guard counts as false.
/// - A watchdog thread reports calls into user code that run longer than a limit
///   (Options::watchdog_limit, 1 s by default), once per call, naming the call and its state or
///   transition. Stop() returns within Options::stop_limit even if a call never returns.
class Statechart {
 public:
  using Observer = std::function<void(const TransitionSegmentBase&)>;

  /// A statechart made from a shared definition (see Definition), which must be complete
  /// (std::logic_error otherwise, and when its given parts were taken by another statechart).
  Statechart(std::shared_ptr<const Definition> definition, kse::messaging::MessageHub& hub,
             Options options = {});
  /// A statechart that builds its own definition, through Add() and AddTransition(), until it
  /// is activated.
  Statechart(std::string name, kse::messaging::MessageHub& hub, Options options = {});
  ~Statechart();
  Statechart(const Statechart&) = delete;
  Statechart& operator=(const Statechart&) = delete;

  const std::string& Name() const noexcept;
  /// The root OR state of its definition.
  OrState* Root() const noexcept;
  const Definition& GetDefinition() const noexcept;

  /// Creates a state in the statechart's own definition: Add<OrState>("Node_0_3", Node_0); the
  /// statechart itself stands for its root. The structure is fixed once the statechart is
  /// activated. Throws std::logic_error for a statechart made from a shared definition.
  template <class S, class... A>
  S* Add(A&&... args) {
    return OwnDefinition().Add<S>(RootFor(std::forward<A>(args))...);
  }

  /// Creates a transition in the statechart's own definition; model order is the order of
  /// these calls.
  template <class Src, class Dst>
  TransitionSegment<Src, Dst>* AddTransition(Src* source, Dst* target,
                                             Part<ICondition> condition = nullptr,
                                             Part<IAction> action = nullptr) {
    return OwnDefinition().AddTransition(source, target, std::move(condition), std::move(action));
  }

  /// Activates (if not yet) and runs the engine on its own thread until Stop(): whenever it is
  /// woken (an activity returned, a wake-up time passed), it steps until nothing fires.
  void Start();
  /// Stops the engine thread and waits for running activities, at most Options::stop_limit in
  /// all: a call that has not returned by then is reported (Kind::Abandoned) and goes on alone.
  /// An activity left so finishes as usual. An engine thread left so (in a guard, an action, a
  /// hook) holds the engine's lock until its call returns, then ends at once, without the rest
  /// of its step: a transition it was taking stays half-taken. The configuration is kept;
  /// Start() resumes (once such a call returned). Safe when not started. The destructor stops
  /// too, and returns within stop_limit and about a second more even then: what it left
  /// comes back, when it returns, to the engine's own objects, which are kept for it.
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
  /// As above with an explicit bound on the transitions taken; false when it was reached. The
  /// warning then names the loop the last transitions went round (see UnsettledLoop()).
  bool RunUntilStable(std::size_t max_transitions);
  /// The loop the last RunUntilStable() that reached its bound went round, as its states'
  /// labels and names from where it was to where it came back ("0.2 'Chase' -> 0.2.3 'C' ->
  /// 0.2 'Chase'"); empty when none did. Thread-safe.
  std::string UnsettledLoop() const;

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
  /// Calls the watchdog reported as running longer than their limit.
  std::size_t Overruns() const noexcept;

  /// Replaces the reporter (Options::reporter); empty: standard error. Thread-safe.
  void SetReporter(Reporter reporter);
  /// The watchdog limit of every call that has no limit of its own (Options::watchdog_limit);
  /// zero: not watched. Thread-safe, at any time.
  void SetWatchdogLimit(std::chrono::milliseconds limit);
  std::chrono::milliseconds WatchdogLimit() const noexcept;
  /// The watchdog limit of the activities named so (IActivity::GetName()), in every state that
  /// runs one; zero: never reported. Thread-safe, before or after Activate().
  void SetActivityWatchdogLimit(const std::string& activity, std::chrono::milliseconds limit);

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

  // What changes in this statechart as it runs, for a state or transition of its definition.
  // Safe to call from any thread (the value may be stale; see ActiveStates()); nullptr, false
  // or 0 before Activate().

  bool IsActive(const State* state) const noexcept;
  /// The active child of an OR state (the root included), or nullptr.
  State* ActiveChild(const State* state) const noexcept;
  /// For a region or the root: an activity of the region runs. For a BASIC state: the activity
  /// started by its last entry has not finished.
  bool IsRunning(const State* state) const noexcept;
  /// How many times the activity of a BASIC state has been started.
  std::size_t Launches(const BasicState* state) const noexcept;
  IActivity* ActivityOf(const BasicState* state) const noexcept;
  ICondition* ConditionOf(const TransitionSegmentBase* transition) const noexcept;
  IAction* ActionOf(const TransitionSegmentBase* transition) const noexcept;
  /// The blackboard of a state's region (the nearest AND region or the root containing it).
  Blackboard* ScopeOf(const State* state) const noexcept;
  /// The blackboard a transition's condition and action get.
  Blackboard* ScopeOf(const TransitionSegmentBase* transition) const noexcept;
  /// Every transition in model order.
  std::vector<TransitionSegmentBase*> Transitions() const;

 private:
  Definition& OwnDefinition();
  template <class T>
  static decltype(auto) RootFor(T&& argument) {
    if constexpr (std::is_same_v<std::decay_t<T>, Statechart*>) {
      return static_cast<State*>(argument->Root());
    } else {
      return std::forward<T>(argument);
    }
  }

  std::shared_ptr<Definition> own_;  // a definition the statechart builds itself
  std::unique_ptr<detail::EngineCore> core_;
};

}  // namespace statechart_engine

#endif
