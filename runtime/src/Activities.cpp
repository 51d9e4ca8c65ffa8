#include "EngineCore.h"

#include <algorithm>
#include <exception>
#include <limits>
#include <utility>

namespace statechart_engine::detail {

namespace {

constexpr std::size_t kStepsPerBatch = 1000;  // engine thread: check Stop() at least this often
// How often the engine thread looks at its clock when no wake-up time is near (a ManualClock
// moved by someone who did not call Wake()).
constexpr auto kClockLook = std::chrono::seconds(1);

}  // namespace

thread_local const EngineCore* current_loop_core = nullptr;
thread_local std::uint64_t current_loop_generation = 0;

// ---------------------------------------------------------------------------------------------
// Activities
// ---------------------------------------------------------------------------------------------

void EngineCore::LaunchInlineHeld(BasicState* state, IActivity* activity) {
  RunActivity(state, activity);
  UnwindIfGivenUp();
  if (current_loop_core != this) {
    // The run is over, but the region behaves as if it went on until the next call, as a
    // worker's run would: the region waits, the rest of the chart steps on.
    // Not among running_activities_: nothing runs, nothing is to be waited for.
    RunningOf(state).fetch_add(1, std::memory_order_acq_rel);
    inline_runs_.push_back(state);
    run_begins_work_.store(true, std::memory_order_release);
  }
}

// Out of the inline path, which most launches take (the simulator's, the benchmarks'): its lock
// and its lambda would give that path a larger frame.
void EngineCore::LaunchOnPool(BasicState* state, IActivity* activity) {
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    RunningOf(state).fetch_add(1, std::memory_order_acq_rel);
    running_activities_.fetch_add(1, std::memory_order_acq_rel);
    if (activity_runs_[state->slot_].load(std::memory_order_acquire)) {
      // Entered again (after an outer transition left it) while the last run goes on: one
      // IActivity object never runs twice at once, so the worker runs it again afterwards.
      ++relaunches_[state->slot_];
      return;
    }
    activity_runs_[state->slot_].store(true, std::memory_order_release);
  }
  pool_->Post([this, state, activity] {
    do {
      RunActivity(state, activity);
    } while (FinishActivity(state));
  });
}

void EngineCore::RunActivity(BasicState* state, IActivity* activity) {
  // Nothing but the call on the way that does not throw: the failure is told out of line.
  try {
    WatchedCall watched(SlotOf(state), CallKind::Activity, state);
    activity->Execute();
  } catch (const std::exception& e) {
    ActivityFailed(state, "threw", e.what());
  } catch (...) {
    ActivityFailed(state, "threw a non-standard exception", "");
  }
}

void EngineCore::ActivityFailed(BasicState* state, const char* failure, const std::string& message) {
  ++activity_failures_;
  std::string name;
  try {
    name = ActivityOf(state)->GetName();
  } catch (...) {
    name = "?";
  }
  Report(EngineReport::Kind::Failure, "activity '" + name + "' of " + DescribeLabelled(state) +
                                          " " + failure +
                                          (message.empty() ? std::string() : ": " + message));
}

bool EngineCore::FinishActivity(BasicState* state) {
  bool again = false;
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    if (abandoned_.load(std::memory_order_relaxed)) {
      return false;  // the statechart is gone: its region (maybe the root itself) with it
    }
    RunningOf(state).fetch_sub(1, std::memory_order_acq_rel);
    running_activities_.fetch_sub(1, std::memory_order_acq_rel);
    if (relaunches_[state->slot_] > 0) {
      --relaunches_[state->slot_];
      again = true;
    } else {
      activity_runs_[state->slot_].store(false, std::memory_order_release);
    }
    woken_ = true;
    ++wake_generation_;
  }
  wake_cv_.notify_all();
  return again;
}

// ---------------------------------------------------------------------------------------------
// Running
// ---------------------------------------------------------------------------------------------

bool EngineCore::TakeWake() {
  bool woken = false;
  // Set only under wake_mutex_: one seen unset here was set, if at all, concurrently with this
  // look, and waiting (RunUntilStable(), Loop()) looks again under the mutex.
  if (woken_.load(std::memory_order_acquire)) {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    woken = woken_.exchange(false, std::memory_order_relaxed);
  }
  const kse::messaging::TimePoint now = hub_.GetClock().Now();
  woken = root_blackboard_.TakeDueWakeups(now) || woken;
  const std::size_t boards = definition_->regions_.size() - 1;
  for (std::size_t i = 0; i < boards; ++i) woken = boards_[i].TakeDueWakeups(now) || woken;
  return woken;
}

void EngineCore::BeginRun() {
  // Nothing to end (set under the lock with what there is): one that a step on another thread
  // makes meanwhile is ended at the next run, as if that step had come after this look.
  if (!run_begins_work_.load(std::memory_order_acquire)) return;
  {
    std::lock_guard<EngineLock> lock(engine_lock_);
    run_begins_work_.store(false, std::memory_order_relaxed);
    if (!unsettled_loop_.empty()) unsettled_loop_.clear();
    if (inline_runs_.empty()) return;
    for (BasicState* state : inline_runs_) {
      RunningOf(state).fetch_sub(1, std::memory_order_acq_rel);
    }
    inline_runs_.clear();
  }
  std::lock_guard<std::mutex> lock(wake_mutex_);
  woken_ = true;  // as FinishActivity: an activity's end makes the engine look again
  ++wake_generation_;
}

bool EngineCore::StepUntilQuiet(std::size_t max_transitions, std::size_t first) {
  // The last kLoopRecord segments before the bound are recorded, to name the loop.
  constexpr std::size_t kLoopRecord = 128;
  const std::size_t record_from = max_transitions > kLoopRecord ? max_transitions - kLoopRecord : 0;
  std::lock_guard<EngineLock> lock(engine_lock_);
  for (;;) {
    const std::size_t taken = transitions_taken_.load(std::memory_order_relaxed) - first;
    if (taken >= record_from && !recording_loop_) {
      loop_record_.clear();
      recording_loop_ = true;
    }
    if (!StepRoot()) break;
    if (transitions_taken_.load(std::memory_order_relaxed) - first >= max_transitions) {
      recording_loop_ = false;
      unsettled_loop_ = DescribeLoop(loop_record_);
      if (!unsettled_loop_.empty()) run_begins_work_.store(true, std::memory_order_release);
      Report(EngineReport::Kind::Warning,
             "RunUntilStable stopped after " + std::to_string(max_transitions) +
                 " transitions: the statechart does not settle" +
                 (unsettled_loop_.empty() ? std::string()
                                          : "; it goes round " + unsettled_loop_ +
                                                " without waiting for an activity or a timer"));
      return false;
    }
  }
  recording_loop_ = false;
  return true;
}

std::string EngineCore::DescribeLoop(const std::vector<const TransitionSegmentBase*>& fired) {
  // A loop that repeats within the record shows twice in a row at its end.
  const std::size_t n = fired.size();
  for (std::size_t period = 1; period <= n / 2; ++period) {
    const auto span = static_cast<std::ptrdiff_t>(period);
    if (!std::equal(fired.end() - span, fired.end(), fired.end() - 2 * span)) continue;
    std::string text;
    for (std::size_t i = n - period; i < n; ++i) {
      text += Labelled(fired[i]->Source()) + " -> ";
    }
    return text + Labelled(fired[n - 1]->Target());
  }
  return "";
}

std::string EngineCore::UnsettledLoop() const {
  std::lock_guard<EngineLock> lock(engine_lock_);
  return unsettled_loop_;
}

bool EngineCore::RunIfWoken() {
  Activate();
  BeginRun();
  if (!TakeWake()) {
    return false;
  }
  StepUntilQuiet(std::numeric_limits<std::size_t>::max(), 0);
  return true;
}

bool EngineCore::RunUntilStable(std::size_t max_transitions) {
  Activate();
  BeginRun();
  const std::size_t first = transitions_taken_.load(std::memory_order_relaxed);
  for (;;) {
    if (TakeWake()) {
      if (!StepUntilQuiet(max_transitions, first)) {
        return false;
      }
      continue;
    }
    if (!pool_) {
      // Activities run inline: none is running, and only another thread's Start() could have
      // set woken_ since TakeWake() (and the engine thread it starts then steps).
      return true;
    }
    std::unique_lock<std::mutex> lock(wake_mutex_);
    if (woken_) {
      continue;
    }
    if (running_activities_.load(std::memory_order_acquire) == 0) {
      return true;
    }
    wake_cv_.wait(lock, [this] {
      return woken_ || running_activities_.load(std::memory_order_acquire) == 0;
    });
  }
}

void EngineCore::Wake() {
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    ++wake_generation_;
  }
  wake_cv_.notify_all();
}

std::optional<kse::messaging::TimePoint> EngineCore::NextWakeup() const {
  std::optional<kse::messaging::TimePoint> next = root_blackboard_.NextWakeup();
  const std::size_t boards = block_ == nullptr ? 0 : definition_->regions_.size() - 1;
  for (std::size_t i = 0; i < boards; ++i) {
    auto wakeup = boards_[i].NextWakeup();
    if (wakeup && (!next || *wakeup < *next)) {
      next = wakeup;
    }
  }
  return next;
}

void EngineCore::Start() {
  Activate();
  BeginRun();  // the engine thread does not wait for inline runs: they end now
  std::lock_guard<std::mutex> control(control_mutex_);
  if (thread_.joinable()) {
    return;
  }
  std::uint64_t generation;
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    generation = loop_generation_.load(std::memory_order_relaxed) + 1;
    loop_generation_.store(generation, std::memory_order_release);
    live_loops_.push_back(generation);
    woken_ = true;  // a (re)started engine looks at its configuration first, as Monas' did
  }
  thread_ = std::thread([this, generation] { Loop(generation); });
  started_.store(true, std::memory_order_release);
}

void EngineCore::Stop() {
  std::lock_guard<std::mutex> control(control_mutex_);
  const auto deadline = std::chrono::steady_clock::now() +
                        std::min<std::chrono::steady_clock::duration>(
                            std::max(options_.stop_limit, std::chrono::milliseconds(0)),
                            std::chrono::hours(24 * 365));
  std::vector<std::string> left;
  if (thread_.joinable()) {
    std::uint64_t generation;
    bool ended;
    {
      std::unique_lock<std::mutex> lock(wake_mutex_);
      generation = loop_generation_.load(std::memory_order_relaxed);
      loop_generation_.store(generation + 1, std::memory_order_release);  // retires the thread
      ++wake_generation_;
      wake_cv_.notify_all();
      ended = wake_cv_.wait_until(lock, deadline, [&] {
        return std::find(live_loops_.begin(), live_loops_.end(), generation) == live_loops_.end();
      });
      if (!ended) {
        // From now on the thread unwinds as soon as its call returns (UnwindIfGivenUp).
        given_up_generation_.store(std::max(given_up_generation_.load(), generation));
      }
    }
    if (ended) {
      thread_.join();
    } else {
      const std::string call = CurrentCall(engine_slot_);
      left.push_back("the engine thread" + (call.empty() ? std::string() : ", in the " + call));
      thread_.detach();
    }
    started_.store(false, std::memory_order_release);
  }
  {
    std::unique_lock<std::mutex> lock(wake_mutex_);
    wake_cv_.wait_until(lock, deadline, [this] {
      return running_activities_.load(std::memory_order_acquire) == 0;
    });
  }
  if (running_activities_.load(std::memory_order_acquire) > 0) {
    for (std::size_t slot = 0; slot < activity_slot_count_; ++slot) {
      if (activity_runs_[slot].load(std::memory_order_acquire)) {
        left.push_back(DescribeCall(CallKind::Activity, definition_->basic_states_[slot]));
      }
    }
  }
  if (!left.empty()) {
    std::string text = "Stop() stopped waiting after " +
                       Seconds(std::max(options_.stop_limit, std::chrono::milliseconds(0))) +
                       " for calls that have not returned; they go on alone: ";
    for (std::size_t i = 0; i < left.size(); ++i) text += (i ? "; " : "") + left[i];
    Report(EngineReport::Kind::Abandoned, std::move(text));
  }
}

bool EngineCore::Shutdown() {
  if (abandoned_.load()) {
    return true;
  }
  Stop();
  {
    // An engine thread Stop() gave up on unwinds once its call returns, but it must be inside
    // that call (not between two) when the states are freed: wait for it to be, or to end.
    std::unique_lock<std::mutex> lock(wake_mutex_);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
    while (!live_loops_.empty() && !engine_slot_.Busy() &&
           std::chrono::steady_clock::now() < deadline) {
      wake_cv_.wait_for(lock, std::chrono::milliseconds(1));
    }
  }
  if (watched_) {
    Watchdog::Instance().Unwatch(this);
    watched_ = false;
  }
  bool abandon;
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    abandon = !live_loops_.empty() || running_activities_.load(std::memory_order_acquire) > 0;
    if (abandon) abandoned_.store(true);
  }
  if (!abandon) {
    pool_.reset();
    return false;
  }
  const std::size_t activities = running_activities_.load();
  std::size_t threads;
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    threads = live_loops_.size();
  }
  if (pool_) pool_->Close(std::chrono::steady_clock::now() + std::chrono::milliseconds(100));
  EngineReport report;
  report.kind = EngineReport::Kind::Abandoned;
  report.chart = Name();
  report.text = "destroyed while " + std::to_string(activities) + " activit" +
                (activities == 1 ? "y" : "ies") + " and " + std::to_string(threads) +
                " engine thread" + (threads == 1 ? "" : "s") +
                " still ran; the engine's own objects are kept for them to return to";
  // The reporter still belongs to the caller here (it is destroying the statechart now).
  Deliver(report, true);
  return true;
}

// Monas' engine thread: `while (Step());`, then sleep until an activity returns or a timeout
// worker wakes it. Waking more often (Wake(), the periodic look at the clock) changes nothing:
// without a reason the engine does not step.
void EngineCore::Loop(std::uint64_t generation) {
  current_loop_core = this;
  current_loop_generation = generation;
  const kse::messaging::Clock& clock = hub_.GetClock();
  for (;;) {
    std::uint64_t seen;
    {
      std::lock_guard<std::mutex> lock(wake_mutex_);
      if (Retired(generation)) {
        break;
      }
      seen = wake_generation_;
    }
    std::optional<kse::messaging::TimePoint> wakeup;
    try {
      if (TakeWake()) {
        std::lock_guard<EngineLock> lock(engine_lock_);
        std::size_t steps = 0;
        bool more = false;
        while (!Retired(generation) && StepRoot()) {
          if (++steps >= kStepsPerBatch) {
            more = true;  // look at Stop() between batches, then go on
            break;
          }
        }
        if (more) {
          std::lock_guard<std::mutex> wake(wake_mutex_);
          woken_ = true;
          continue;
        }
      }
      wakeup = NextWakeup();
    } catch (const GivenUp&) {
      break;  // the step is cut short: what it would touch may be freed
    } catch (const std::exception& e) {
      Report(EngineReport::Kind::Warning, std::string("engine step failed: ") + e.what());
    } catch (...) {
      Report(EngineReport::Kind::Warning, "engine step failed");
    }
    std::unique_lock<std::mutex> lock(wake_mutex_);
    auto woken = [&] { return Retired(generation) || woken_ || wake_generation_ != seen; };
    auto wait = std::chrono::duration_cast<std::chrono::steady_clock::duration>(kClockLook);
    if (wakeup) {
      const auto until = *wakeup - clock.Now();
      wait = std::max(std::chrono::steady_clock::duration::zero(), std::min(wait, until));
    }
    wake_cv_.wait_for(lock, wait, woken);
  }
  std::lock_guard<std::mutex> lock(wake_mutex_);
  live_loops_.erase(std::remove(live_loops_.begin(), live_loops_.end(), generation), live_loops_.end());
  wake_cv_.notify_all();
}

std::vector<std::string> EngineCore::ActiveStates() const {
  std::lock_guard<EngineLock> lock(engine_lock_);
  std::vector<std::string> names;
  if (!IsActive(root_)) return names;
  // Down the active children: only they hold active states, so this is document order.
  std::vector<const State*> pending{root_};
  while (!pending.empty()) {
    const State* state = pending.back();
    pending.pop_back();
    names.push_back(state->Name());
    if (state->kind_ == StateKind::Or) {
      if (const State* child = ActiveChildOf(state)) pending.push_back(child);
    } else if (state->kind_ == StateKind::And) {
      for (auto it = state->children_.rbegin(); it != state->children_.rend(); ++it) {
        if (ActiveChildOf(*it) != nullptr) pending.push_back(*it);
      }
    }
  }
  return names;
}

void EngineCore::SetObserver(Statechart::Observer observer) {
  std::lock_guard<EngineLock> lock(engine_lock_);
  observer_ = std::move(observer);
}

}  // namespace statechart_engine::detail
