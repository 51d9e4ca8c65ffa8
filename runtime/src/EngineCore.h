#ifndef KSE_RUNTIME_SRC_ENGINE_CORE_H
#define KSE_RUNTIME_SRC_ENGINE_CORE_H

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "WorkerPool.h"
#include "kse/messaging/Blackboard.h"
#include "kse/messaging/MessageHub.h"
#include "statechart_engine/Statechart.h"

namespace statechart_engine::detail {

/// Everything behind Statechart: ownership, the step algorithm, activities, the engine thread.
class EngineCore {
 public:
  EngineCore(Statechart& chart, kse::messaging::MessageHub& hub, Options options);
  ~EngineCore();

  void AdoptState(std::unique_ptr<State> state);
  void AdoptTransition(std::unique_ptr<TransitionSegmentBase> transition);

  void Activate();
  bool Step();
  bool RunIfWoken();
  bool RunUntilStable(std::size_t max_transitions);
  void Start();
  void Stop();
  /// Stop(), join the worker pool.
  void Shutdown();
  void Wake();

  std::vector<std::string> ActiveStates() const;
  std::vector<State*> States() const;
  std::vector<TransitionSegmentBase*> Transitions() const;
  void SetObserver(Statechart::Observer observer);

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
  std::atomic<std::size_t> transitions_taken_{0};
  std::atomic<std::size_t> step_number_{0};
  std::atomic<std::size_t> running_activities_{0};

 private:
  // Structure (Activate)
  void Prepare();
  void CollectStates(State* state, std::vector<State*>& out) const;
  void CheckStructure() const;
  void ComputeTransition(TransitionSegmentBase& transition) const;
  void CallUserInits();

  // Stepping
  bool StepRoot();
  bool StepState(State* state);
  bool TryTransitions(State* state);
  bool EvalGuard(TransitionSegmentBase* transition);
  bool FindChain(State* connector, std::size_t depth);
  void Fire(TransitionSegmentBase* transition);

  // Entering and leaving
  void Enter(State* state);
  void Complete(State* state);
  void EnterDefault(State* state);
  void EnterAlong(const std::vector<State*>& path, std::size_t index);
  void Exit(State* state);

  // Activities
  void Launch(BasicState* state);
  void RunActivity(BasicState* state);
  /// Called on a worker after the activity returned: true when it must run again (its state
  /// was entered again while it ran).
  bool FinishActivity(BasicState* state);

  // Waking
  /// Consumes the reasons to re-evaluate: woken_ and the wake-up times due on the clock.
  bool TakeWake();
  /// Steps until nothing fires or the bound is reached (then false, with a warning).
  bool StepUntilQuiet(std::size_t max_transitions, std::size_t first);
  void Loop();
  void WaitForActivities();

  void Report(const std::string& what) const;

  Statechart& chart_;
  std::vector<std::unique_ptr<State>> owned_states_;
  std::vector<std::unique_ptr<TransitionSegmentBase>> owned_transitions_;  // model order

  // Guards the configuration (active flags, active children), the observer and Activate.
  // Workers never take it.
  mutable std::recursive_mutex engine_mutex_;
  std::vector<State*> states_;                              // document order, after Prepare
  std::vector<kse::messaging::Blackboard*> blackboards_;    // root + regions
  std::vector<TransitionSegmentBase*> chain_;               // scratch for connector chains
  Statechart::Observer observer_;
  std::atomic<bool> activated_{false};

  std::unique_ptr<WorkerPool> pool_;

  // Waking the engine (thread or RunUntilStable) and the activity bookkeeping.
  std::mutex wake_mutex_;
  std::condition_variable wake_cv_;
  std::uint64_t wake_generation_ = 0;  // any change: a wake, an activity's end, Stop()
  bool woken_ = false;                 // a reason to re-evaluate
  bool stop_requested_ = false;

  std::mutex control_mutex_;  // serialises Start/Stop/Shutdown
  std::thread thread_;
  std::atomic<bool> started_{false};
};

}  // namespace statechart_engine::detail

#endif
