#include "EngineCore.h"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace statechart_engine::detail {

namespace {

constexpr std::size_t kMaxConnectorChain = 64;

}  // namespace

// ---------------------------------------------------------------------------------------------
// The engine's lock, when it is taken
// ---------------------------------------------------------------------------------------------

namespace {

// Shared by every engine's lock: waiting for one is rare, and a waiter woken for another
// statechart's lock only looks again.
std::mutex& LockWaitMutex() {
  static std::mutex mutex;
  return mutex;
}

std::condition_variable& LockWaitSignal() {
  static std::condition_variable signal;
  return signal;
}

}  // namespace

void EngineLock::LockSlow(std::uintptr_t self) noexcept {
  for (unsigned attempt = 0;; ++attempt) {
    std::uintptr_t queued = queued_.load(std::memory_order_relaxed);
    if (queued == 0 && queued_.compare_exchange_strong(queued, self, std::memory_order_relaxed)) {
      queued = self;
    }
    if (queued == self) {
      std::uintptr_t expected = 0;
      if (owner_.compare_exchange_strong(expected, self, std::memory_order_acquire,
                                         std::memory_order_relaxed)) {
        queued_.store(0, std::memory_order_relaxed);
        return;
      }
    }
    // A step is short: look again at once a few times, then sleep until the holder gives the
    // lock back (a holder in a guard that hangs may keep it for seconds).
    if (attempt < 64) {
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
      continue;
    }
    std::unique_lock<std::mutex> lock(LockWaitMutex());
    if (owner_.load(std::memory_order_relaxed) != 0) {
      LockWaitSignal().wait_for(lock, std::chrono::milliseconds(1));
    } else {
      lock.unlock();
      std::this_thread::yield();  // free, but it goes to the queued thread first
    }
  }
}

void EngineLock::WakeWaiters() noexcept {
  // Taken and dropped: a waiter between its look at owner_ and its wait holds it, so the signal
  // cannot fall between the two.
  { std::lock_guard<std::mutex> lock(LockWaitMutex()); }
  LockWaitSignal().notify_all();
}

// ---------------------------------------------------------------------------------------------
// Stepping
// ---------------------------------------------------------------------------------------------

bool EngineCore::Step() {
  std::lock_guard<EngineLock> lock(engine_lock_);
  if (!IsActivated()) {
    Activate();
  }
  return StepRoot();
}

// Monas' Step() of each kind of state. A region's running flag stops everything in the region;
// the composite's own transitions come after its inside could not move, whatever is active in
// it (not only its END).
//
// The OR states along the active path are walked down in a loop and their transitions tried on
// the way back up (innermost first), which is what the recursion did, without a call per level.
bool EngineCore::StepState(State* state) {
  State* path[kUnrolledDepth];
  std::size_t depth = 0;
  for (;;) {
    if (state->kind_ == StateKind::Or) {
      if (RegionRunningOf(state)) break;  // nothing in a running region steps
      State* child = ActiveChildOf(state);
      if (child != nullptr && depth < kUnrolledDepth) {
        path[depth++] = state;
        state = child;
        continue;
      }
      if ((child != nullptr && StepState(child)) || TryTransitions(state)) return true;
      break;
    }
    if (state->kind_ == StateKind::And) {
      if (StepAnd(state)) return true;
      break;
    }
    // A leaf's region is its parent's, whose running count was just read as zero; only a step
    // (this one) could have raised it since.
    if (state->kind_ != StateKind::End && TryOutgoing(state)) return true;
    break;
  }
  // Back up: each OR state on the path tries its own once its inside could not move
  // (TryTransitions looks at its region's running flag again, as the recursion did).
  while (depth > 0) {
    if (TryTransitions(path[--depth])) return true;
  }
  return false;
}

bool EngineCore::StepUp(State* leaf) {
  // The count cannot rise during the step until something fires (only a step launches), so one
  // look serves every state on the path.
  if (RegionRunningOf(root_)) return false;
  for (State* state = leaf; state != root_; state = state->parent_) {
    if (state->kind_ != StateKind::End && TryOutgoing(state)) return true;
  }
  return false;
}

bool EngineCore::StepAnd(State* state) {
  // Whether a region was running is taken before the regions step, as Monas did.
  bool running = false;
  for (const State* region : state->children_) {
    running = running || running_[AsOr(region)->region_slot_].load(std::memory_order_acquire) > 0;
  }
  bool fired = false;
  for (State* region : state->children_) {
    fired = StepState(region) || fired;
  }
  if (fired) {
    return true;
  }
  return !running && TryTransitions(state);
}

bool EngineCore::Evaluate(TransitionSegmentBase* transition, ICondition* condition) {
  bool holds = false;
  try {
    WatchedCall watched(engine_slot_, CallKind::Guard, transition);
    holds = condition->Eval();
  } catch (const std::exception& e) {
    ++guard_failures_;
    Report(EngineReport::Kind::Failure,
           "guard of '" + transition->Name() + "' threw (taken as false): " + e.what());
  } catch (...) {
    ++guard_failures_;
    Report(EngineReport::Kind::Failure,
           "guard of '" + transition->Name() + "' threw (taken as false)");
  }
  UnwindIfGivenUp();
  return holds;
}

bool EngineCore::FindChain(State* connector, std::size_t depth) {
  if (depth >= kMaxConnectorChain) {
    Report(EngineReport::Kind::Warning, "condition connector chain deeper than " +
                                            std::to_string(kMaxConnectorChain) + " at " +
                                            Describe(connector) + ", not taken");
    return false;
  }
  for (TransitionSegmentBase* next : connector->outgoing_) {
    if (!EvalGuard(next)) continue;
    chain_.push_back(next);
    if (next->target_->kind_ != StateKind::Condition || FindChain(next->target_, depth + 1)) {
      return true;
    }
    chain_.pop_back();
  }
  return false;
}

bool EngineCore::TryOutgoing(State* state) {
  for (TransitionSegmentBase* transition : state->outgoing_) {
    if (!EvalGuard(transition)) continue;
    if (transition->target_->kind_ != StateKind::Condition) {
      Fire(transition);
      return true;
    }
    if (FireThroughConnectors(transition)) return true;
  }
  return false;
}

// Out of TryTransitions, which most steps run without a connector: the chain's bookkeeping
// would give it a larger frame.
bool EngineCore::FireThroughConnectors(TransitionSegmentBase* transition) {
  chain_.clear();
  chain_.push_back(transition);
  if (!FindChain(transition->target_, 0)) {
    return false;
  }
  // Every guard of the chain has been evaluated; now the segments fire in order.
  std::vector<TransitionSegmentBase*> chain;
  chain.swap(chain_);
  for (TransitionSegmentBase* segment : chain) {
    Fire(segment);
  }
  chain.clear();
  chain_.swap(chain);  // keep the capacity
  return true;
}

void EngineCore::Fire(TransitionSegmentBase* transition) {
  // Unknown until the configuration is whole again; a step taken by user code during this one
  // (the lock is recursive) leaves it unknown.
  active_leaf_ = nullptr;
  const std::size_t step = step_number_.load(std::memory_order_relaxed);
  // Most transitions of a behaviour go from one state to a sibling: no walk up or down.
  const bool between_siblings = transition->between_siblings_;
  if (between_siblings) {
    Leave(transition->source_);
  } else {
    Exit(transition->exit_top_);
  }
  if (IAction* action = ActionOf(transition)) {
    try {
      WatchedCall watched(engine_slot_, CallKind::Action, transition);
      action->Execute();
    } catch (const std::exception& e) {
      ++action_failures_;
      Report(EngineReport::Kind::Failure, "action of '" + transition->Name() + "' threw: " + e.what());
    } catch (...) {
      ++action_failures_;
      Report(EngineReport::Kind::Failure, "action of '" + transition->Name() + "' threw");
    }
    UnwindIfGivenUp();
  }
  if (between_siblings) {
    State* target = transition->target_;
    Enter(target);
    if (target->kind_ == StateKind::Basic) Launch(static_cast<BasicState*>(target));
  } else {
    EnterAlong(transition->entry_path_, transition->entry_length_, 0);
  }
  if (recording_loop_) loop_record_.push_back(transition);
  transitions_taken_.store(transitions_taken_.load(std::memory_order_relaxed) + 1,
                          std::memory_order_relaxed);
  if (observer_) {
    try {
      WatchedCall watched(engine_slot_, CallKind::Observer, transition);
      observer_(*transition);
    } catch (const std::exception& e) {
      ++action_failures_;
      Report(EngineReport::Kind::Failure,
             "observer threw on '" + transition->Name() + "': " + e.what());
    } catch (...) {
      ++action_failures_;
      Report(EngineReport::Kind::Failure, "observer threw on '" + transition->Name() + "'");
    }
    UnwindIfGivenUp();
  }
  if (step_number_.load(std::memory_order_relaxed) == step) active_leaf_ = transition->leaf_after_;
}

// ---------------------------------------------------------------------------------------------
// Entering and leaving
// ---------------------------------------------------------------------------------------------

void EngineCore::CallEntry(State* state) {
  try {
    WatchedCall watched(engine_slot_, CallKind::Entry, state);
    state->OnEntry();
  } catch (const std::exception& e) {
    ++action_failures_;
    Report(EngineReport::Kind::Failure, "OnEntry of " + Describe(state) + " threw: " + e.what());
  } catch (...) {
    ++action_failures_;
    Report(EngineReport::Kind::Failure, "OnEntry of " + Describe(state) + " threw");
  }
  UnwindIfGivenUp();
}

void EngineCore::Complete(State* state) {
  switch (state->kind_) {
    case StateKind::Or:
      EnterDefault(AsOr(state)->start_);
      break;
    case StateKind::And:
      for (State* region : state->children_) {
        EnterDefault(region);
      }
      break;
    case StateKind::Basic:
      Launch(static_cast<BasicState*>(state));
      break;
    default:
      break;
  }
}

void EngineCore::EnterDefault(State* state) {
  Enter(state);
  Complete(state);
}

void EngineCore::EnterAlong(State* const* path, std::size_t length, std::size_t index) {
  State* state = path[index];
  Enter(state);
  if (index + 1 == length) {
    Complete(state);
    return;
  }
  State* next = path[index + 1];
  if (state->kind_ == StateKind::And) {
    for (State* region : state->children_) {
      if (region == next) {
        EnterAlong(path, length, index + 1);
      } else {
        EnterDefault(region);
      }
    }
  } else {
    EnterAlong(path, length, index + 1);
  }
}

void EngineCore::Exit(State* state) {
  if (state->kind_ == StateKind::Or) {
    if (State* child = ActiveChildOf(state)) {
      Exit(child);
    }
  } else if (state->kind_ == StateKind::And) {
    for (auto it = state->children_.rbegin(); it != state->children_.rend(); ++it) {
      if (ActiveChildOf(*it) != nullptr) {  // a region entered (all are, unless a step was cut short)
        Exit(*it);
      }
    }
  }
  Leave(state);
}

void EngineCore::CallExit(State* state) {
  try {
    WatchedCall watched(engine_slot_, CallKind::Exit, state);
    state->OnExit();
  } catch (const std::exception& e) {
    ++action_failures_;
    Report(EngineReport::Kind::Failure, "OnExit of " + Describe(state) + " threw: " + e.what());
  } catch (...) {
    ++action_failures_;
    Report(EngineReport::Kind::Failure, "OnExit of " + Describe(state) + " threw");
  }
  UnwindIfGivenUp();
}

}  // namespace statechart_engine::detail
