#ifndef KSE_RUNTIME_SRC_ENGINE_CORE_H
#define KSE_RUNTIME_SRC_ENGINE_CORE_H

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "EngineLock.h"
#include "Watchdog.h"
#include "WorkerPool.h"
#include "kse/messaging/Blackboard.h"
#include "kse/messaging/MessageHub.h"
#include "statechart_engine/Statechart.h"

namespace statechart_engine::detail {

/// Everything behind Statechart: ownership, the step algorithm, activities, the engine thread.
class EngineCore {
 private:
  // What every step reads, first (a step takes a few of the object's cache lines).

  // Guards the configuration (the active children), the observer and Activate. Workers never
  // take it.
  mutable EngineLock engine_lock_;
  // One block per statechart (Definition::Layout): the active children of its OR states, its
  // regions' running counts and blackboards, its activities' counts, the parts it made.
  unsigned char* block_ = nullptr;
  std::atomic<bool>* activity_runs_ = nullptr;  // by BASIC state: the last run has not ended
  std::atomic<State*>* active_child_ = nullptr;  // by OR state
  std::atomic<int>* running_ = nullptr;
  std::atomic<std::uint32_t>* launches_ = nullptr;
  std::uint32_t* relaunches_ = nullptr;
  kse::messaging::Blackboard* boards_ = nullptr;
  OrState* root_;
  // The deepest active state while the configuration is one path from the root (no AND state
  // on it), as the last transition fired left it; null when a step must walk down from the root.
  State* active_leaf_ = nullptr;
  std::atomic<bool> activated_{false};  // set as the root is entered
  bool inline_runs_last_;  // Options::inline_activities_last_until_next_run
  // Near a RunUntilStable() bound every segment fired goes into loop_record_ (one test per Fire()).
  bool recording_loop_ = false;
  std::unique_ptr<WorkerPool> pool_;
  std::atomic<std::uint64_t> given_up_generation_{0};  // engine threads up to it unwind after their call
  CallSlot engine_slot_;  // guards, actions, entry/exit hooks, UserInit, the observer
  Statechart::Observer observer_;
  std::atomic<std::size_t> transitions_taken_{0};
  std::atomic<std::size_t> step_number_{0};

  friend class statechart_engine::Statechart;

 public:
  /// `own`: the definition when the statechart builds it itself (completed at activation).
  EngineCore(std::shared_ptr<const Definition> definition, Definition* own,
             kse::messaging::MessageHub& hub, Options options);
  ~EngineCore();

  const Definition& GetDefinition() const noexcept { return *definition_; }
  const std::string& Name() const noexcept { return definition_->Name(); }

  void Activate();
  bool Step();
  bool RunIfWoken();
  bool RunUntilStable(std::size_t max_transitions);
  void Start();
  void Stop();
  /// Stop(), then join the worker pool. True when calls still run (Stop() abandoned them): the
  /// core must then be kept (KeepAbandoned), since they come back to it when they return.
  bool Shutdown();
  void Wake();

  // Reporting and the watchdog
  void Report(EngineReport::Kind kind, std::string text) const;
  /// To the reporter, or to standard error once the statechart is destroyed (the reporter may
  /// refer to what went with it) or when there is none.
  void Deliver(const EngineReport& report) const { Deliver(report, !abandoned_.load()); }
  void Deliver(const EngineReport& report, bool to_reporter) const;
  void SetReporter(Reporter reporter);
  void SetWatchdogLimit(std::chrono::milliseconds limit);
  std::chrono::milliseconds WatchdogLimit() const noexcept {
    return std::chrono::milliseconds(watchdog_limit_ms_.load(std::memory_order_relaxed));
  }
  void SetActivityWatchdogLimit(const std::string& activity, std::chrono::milliseconds limit);
  /// The shortest limit of any slot (zero when none is watched), for the watchdog's period.
  std::chrono::milliseconds ShortestWatchdogLimit() const noexcept;
  /// The watchdog's look at every slot: reports overruns and the end of reported ones.
  void Inspect(std::chrono::steady_clock::time_point now,
               const std::function<void(EngineReport)>& report);
  /// A core whose calls were abandoned, kept until the process ends (reachable, so that leak
  /// checkers do not count it).
  static void KeepAbandoned(std::unique_ptr<EngineCore> core);

  std::vector<std::string> ActiveStates() const;
  std::string UnsettledLoop() const;
  void SetObserver(Statechart::Observer observer);

  // The statechart's own part of a state or transition of its definition (after Activate()).
  // A state is active when each OR state above it has it (or the state above it) as its active
  // child, and the root has been entered: the active children are the whole configuration.
  bool IsActive(const State* state) const noexcept {
    if (!IsActivated()) return false;
    for (const State* s = state; s->parent_ != nullptr; s = s->parent_) {
      if (s->parent_or_slot_ != 0 && active_child_[s->parent_or_slot_ - 1].load(std::memory_order_relaxed) != s) {
        return false;
      }
    }
    return true;
  }
  State* ActiveChild(const State* state) const noexcept {
    if (block_ == nullptr || state->kind_ != StateKind::Or) return nullptr;
    return ActiveChildOf(state);
  }
  bool RegionRunning(const OrState* region) const noexcept {
    return block_ != nullptr &&
           running_[region->region_slot_].load(std::memory_order_acquire) > 0;
  }
  bool ActivityRunning(const BasicState* state) const noexcept {
    return block_ != nullptr && activity_runs_[state->slot_].load(std::memory_order_acquire);
  }
  std::size_t Launches(const BasicState* state) const noexcept {
    return block_ == nullptr ? 0 : launches_[state->slot_].load(std::memory_order_relaxed);
  }
  // These three only once the block is made (MakeBlock).
  IActivity* ActivityOf(const BasicState* state) const noexcept {
    return Object(state->activity_, state->activity_at_);
  }
  ICondition* ConditionOf(const TransitionSegmentBase* transition) const noexcept {
    return Object(transition->condition_, transition->condition_at_);
  }
  IAction* ActionOf(const TransitionSegmentBase* transition) const noexcept {
    return Object(transition->action_, transition->action_at_);
  }
  bool HasBlock() const noexcept { return block_ != nullptr; }
  kse::messaging::Blackboard* BoardOf(const OrState* region) const noexcept {
    if (region->region_slot_ == 0) return &root_blackboard_;
    return block_ == nullptr ? nullptr : &boards_[region->region_slot_ - 1];
  }

  /// The earliest wake-up time its blackboards hold, if any.
  std::optional<kse::messaging::TimePoint> NextWakeup() const;

  bool IsStarted() const noexcept { return started_.load(std::memory_order_acquire); }
  bool IsActivated() const noexcept { return activated_.load(std::memory_order_acquire); }

  kse::messaging::MessageHub& hub_;
  Options options_;
  mutable kse::messaging::Blackboard root_blackboard_;

  std::atomic<std::size_t> activity_failures_{0};
  std::atomic<std::size_t> guard_failures_{0};
  std::atomic<std::size_t> action_failures_{0};
  std::atomic<std::size_t> running_activities_{0};
  std::atomic<std::size_t> overruns_{0};

 private:
  // A statechart's guard, action or activity (after MakeBlock): see Definition::Layout.
  template <class I>
  I* Object(const Part<I>& part, std::size_t at) const noexcept {
    if ((at & 1U) == 0) return at == 0 ? nullptr : reinterpret_cast<I*>(block_ + at);  // made, or none
    if (at == 1) return part.given_object_;
    return *reinterpret_cast<I* const*>(block_ + (at & ~std::size_t{1}));
  }
  bool RegionRunningOf(const State* state) const noexcept {
    return running_[state->region_slot_].load(std::memory_order_acquire) > 0;
  }
  std::atomic<int>& RunningOf(const State* state) noexcept { return running_[state->region_slot_]; }
  // Written by the engine's thread only (under its lock); atomic for a reader of IsActive().
  State* ActiveChildOf(const State* or_state) const noexcept {
    return active_child_[or_state->slot_].load(std::memory_order_relaxed);
  }
  void SetActiveChild(std::uint32_t parent_or_slot, State* child) noexcept {
    if (parent_or_slot != 0) active_child_[parent_or_slot - 1].store(child, std::memory_order_relaxed);
  }

  // The statechart's own memory (Activate)
  void MakeBlock();
  template <class I>
  void MakePart(const Part<I>& part, std::size_t at, std::vector<std::unique_ptr<I>>& owned);
  /// Destroys, last made first, the parts of the first `transitions` transitions and
  /// `activities` BASIC states, and the first `boards` region blackboards.
  void DestroyMade(std::size_t transitions, std::size_t activities, std::size_t boards) noexcept;
  void DestroyBlock() noexcept;
  void CallUserInits();

  // Stepping
  bool StepRoot() {
    // Written only under engine_lock_: a plain increment, no locked read-modify-write.
    step_number_.store(step_number_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    if (State* leaf = active_leaf_) return StepUp(leaf);
    return StepState(root_);
  }
  /// StepState(root_) when the configuration is one path from the root down to `leaf`: every
  /// state on it is in the root's region, and each tries its transitions, innermost first.
  bool StepUp(State* leaf);
  bool StepState(State* state);
  bool StepAnd(State* state);
  /// OR states walked down in a loop by StepState; deeper ones recurse.
  static constexpr std::size_t kUnrolledDepth = 16;
  /// Fires the first transition out of the state whose guard holds, unless its region runs.
  bool TryTransitions(State* state) { return !RegionRunningOf(state) && TryOutgoing(state); }
  bool TryOutgoing(State* state);
  /// A guard into a CONDITION connector held: fires the chain through it if one can go on.
  bool FireThroughConnectors(TransitionSegmentBase* transition);
  bool EvalGuard(TransitionSegmentBase* transition) {
    ICondition* condition = ConditionOf(transition);
    return condition == nullptr || Evaluate(transition, condition);
  }
  /// Calls the guard: a guard that throws is taken as false, and reported.
  bool Evaluate(TransitionSegmentBase* transition, ICondition* condition);
  bool FindChain(State* connector, std::size_t depth);
  void Fire(TransitionSegmentBase* transition);

  // Entering and leaving
  /// Makes the state its parent's active child and calls its OnEntry(), if overridden.
  void Enter(State* state) {
    SetActiveChild(state->parent_or_slot_, state);
    if (state->calls_entry_) CallEntry(state);
  }
  /// Calls the state's OnExit(), if overridden, and leaves it (its inside already left).
  void Leave(State* state) {
    if (state->calls_exit_) CallExit(state);
    SetActiveChild(state->parent_or_slot_, nullptr);
  }
  void CallEntry(State* state);
  void CallExit(State* state);
  void Complete(State* state);
  void EnterDefault(State* state);
  void EnterAlong(State* const* path, std::size_t length, std::size_t index);
  void Exit(State* state);

  // Activities
  void Launch(BasicState* state) {
    IActivity* activity = ActivityOf(state);
    if (activity == nullptr) return;
    // Only a step (under the engine's lock) launches: a plain increment, no locked instruction.
    std::atomic<std::uint32_t>& launches = launches_[state->slot_];
    launches.store(launches.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    if (pool_) {
      LaunchOnPool(state, activity);
    } else if (inline_runs_last_) {
      LaunchInlineHeld(state, activity);
    } else {
      RunActivity(state, activity);
      UnwindIfGivenUp();
    }
  }
  /// Options::inline_activities_last_until_next_run: runs the activity, then holds its region.
  void LaunchInlineHeld(BasicState* state, IActivity* activity);
  void LaunchOnPool(BasicState* state, IActivity* activity);
  void RunActivity(BasicState* state, IActivity* activity);
  void ActivityFailed(BasicState* state, const char* failure, const std::string& message);
  /// Called on a worker after the activity returned: true when it must run again (its state
  /// was entered again while it ran).
  bool FinishActivity(BasicState* state);

  // Waking
  /// Consumes the reasons to re-evaluate: woken_ and the wake-up times due on the clock.
  bool TakeWake();
  /// Steps until nothing fires or the bound is reached (then false, with a warning).
  bool StepUntilQuiet(std::size_t max_transitions, std::size_t first);
  void Loop(std::uint64_t generation);
  bool Retired(std::uint64_t generation) const noexcept {
    return loop_generation_.load(std::memory_order_acquire) != generation;
  }
  /// After a call into user code on the engine's thread: when this is an engine thread Stop()
  /// gave up on, unwinds the step (the statechart may have been destroyed meanwhile, and the
  /// rest of the step would touch its freed states; alive, it has another engine thread).
  void UnwindIfGivenUp() const {
    if (given_up_generation_.load(std::memory_order_relaxed) != 0) UnwindIfThisThreadWasGivenUp();
  }
  void UnwindIfThisThreadWasGivenUp() const;

  /// At the start of RunUntilStable() and RunIfWoken(): the inline activities whose run lasts
  /// until the next run (Options::inline_activities_last_until_next_run) end, their regions
  /// free and the engine woken; the last unsettled loop is forgotten.
  void BeginRun();
  /// The loop at the end of the segments fired last, as its states ("" when none repeats).
  static std::string DescribeLoop(const std::vector<const TransitionSegmentBase*>& fired);

  bool UsesPool() const noexcept { return !options_.inline_activities && options_.worker_threads > 0; }

  // Watchdog
  /// An inline activity runs on the engine's thread: its slot, always in the cache.
  CallSlot& SlotOf(const BasicState* state) noexcept {
    return pool_ ? activity_slots_[state->slot_] : engine_slot_;
  }
  std::string DescribeCall(CallKind kind, const void* subject) const;
  /// The call running in a slot now: false when none (or calls come and go too fast to say).
  bool ReadCall(const CallSlot& slot, CallKind& kind, const void*& subject) const noexcept;
  /// The same, described; "" when none.
  std::string CurrentCall(const CallSlot& slot) const;
  std::int64_t LimitOf(CallKind kind, const void* subject) const noexcept;
  void ApplyActivityLimits();

  // Kept by every statechart made from it (and by the core of one abandoned, for reports).
  std::shared_ptr<const Definition> definition_;
  Definition* own_definition_;
  // Parts given as objects, or created for this statechart, on the heap.
  std::vector<std::unique_ptr<ICondition>> given_conditions_;
  std::vector<std::unique_ptr<IAction>> given_actions_;
  std::vector<std::unique_ptr<IActivity>> given_activities_;

  std::vector<TransitionSegmentBase*> chain_;               // scratch for connector chains
  std::vector<BasicState*> inline_runs_;  // inline activities that end at the next run
  // Whether BeginRun() has anything to do (inline_runs_ or unsettled_loop_ not empty): set
  // under engine_lock_, read without it, so that the cycles with nothing to end (most of a
  // robot's) take no lock for it.
  std::atomic<bool> run_begins_work_{false};
  std::vector<const TransitionSegmentBase*> loop_record_;
  std::string unsettled_loop_;  // under engine_lock_


  // Waking the engine (thread or RunUntilStable) and the activity bookkeeping.
  std::mutex wake_mutex_;
  std::condition_variable wake_cv_;
  std::uint64_t wake_generation_ = 0;  // any change: a wake, an activity's end, Stop()
  // A reason to re-evaluate. Written under wake_mutex_; atomic so that TakeWake() can see that
  // there is none without taking the mutex (the common case of a RunUntilStable() per cycle).
  std::atomic<bool> woken_{false};
  std::vector<std::uint64_t> live_loops_;  // generations of engine threads not ended yet
  std::atomic<bool> abandoned_{false};     // destroyed while calls still ran (set under wake_mutex_)

  std::mutex control_mutex_;  // serialises Start/Stop/Shutdown
  std::thread thread_;
  std::atomic<std::uint64_t> loop_generation_{0};  // the engine thread that may run; Stop() retires it
  std::atomic<bool> started_{false};

  // Reports and the watchdog
  mutable std::mutex reporter_mutex_;
  std::shared_ptr<const Reporter> reporter_;  // null: standard error
  std::unique_ptr<CallSlot[]> activity_slots_;  // by activity, only for a worker pool
  std::unique_ptr<std::atomic<std::int64_t>[]> activity_limits_ms_;  // by activity, -1: the statechart's
  std::size_t activity_slot_count_ = 0;
  std::atomic<std::int64_t> watchdog_limit_ms_;
  std::mutex limits_mutex_;
  std::vector<std::pair<std::string, std::chrono::milliseconds>> activity_limits_;
  bool watched_ = false;
};

// What more than one of the engine's source files needs.

inline OrState* AsOr(State* state) { return static_cast<OrState*>(state); }

inline const OrState* AsOr(const State* state) { return static_cast<const OrState*>(state); }

inline std::string Describe(const State* state) { return "'" + state->Name() + "'"; }

// A state as a modeller sees it: its label too ("0.2 'Look'", or "'Look'" when it has none).
inline std::string Labelled(const State* state) {
  if (state->Label() == state->Name()) return "'" + state->Name() + "'";
  return state->Label() + " '" + state->Name() + "'";
}

// For the watchdog and Stop().
inline std::string DescribeLabelled(const State* state) { return "state " + Labelled(state); }

// "250 ms", "1.3 s": a watchdog limit is often below a second, a hang seldom.
inline std::string Seconds(std::chrono::steady_clock::duration duration) {
  char text[32];
  const double seconds = std::chrono::duration<double>(duration).count();
  if (seconds < 1) {
    std::snprintf(text, sizeof text, "%.0f ms", seconds * 1000);
  } else {
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  }
  return text;
}

// Unwinds a step whose engine thread Stop() gave up on, once its call returns.
struct GivenUp {};

// Which engine thread this is, for GivenUp: only that thread unwinds, not a caller of
// RunUntilStable() on another thread. Set by Loop().
extern thread_local const EngineCore* current_loop_core;
extern thread_local std::uint64_t current_loop_generation;

}  // namespace statechart_engine::detail

#endif
