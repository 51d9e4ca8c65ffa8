#include "statechart_engine/Statechart.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "EngineCore.h"

namespace statechart_engine {
namespace detail {

namespace {

constexpr std::size_t kMaxConnectorChain = 64;
constexpr std::size_t kStepsPerBatch = 1000;  // engine thread: check Stop() at least this often
// How often the engine thread looks at its clock when no wake-up time is near (a ManualClock
// moved by someone who did not call Wake()).
constexpr auto kClockLook = std::chrono::seconds(1);

OrState* AsOr(State* state) { return static_cast<OrState*>(state); }

const OrState* AsOr(const State* state) { return static_cast<const OrState*>(state); }

// The order in which Monas tried a state's transitions: each guarded one was inserted at the
// front of the list as it was created, each unguarded one appended.
void OrderOutgoing(std::vector<TransitionSegmentBase*>& outgoing) {
  std::vector<TransitionSegmentBase*> ordered;
  ordered.reserve(outgoing.size());
  for (auto it = outgoing.rbegin(); it != outgoing.rend(); ++it) {
    if ((*it)->IsGuarded()) ordered.push_back(*it);
  }
  for (TransitionSegmentBase* transition : outgoing) {
    if (!transition->IsGuarded()) ordered.push_back(transition);
  }
  outgoing.swap(ordered);
}

std::string Describe(const State* state) { return "'" + state->Name() + "'"; }

// For the watchdog and Stop(): the model's label too, which is what a modeller sees.
std::string DescribeLabelled(const State* state) {
  if (state->Label() == state->Name()) return "state '" + state->Name() + "'";
  return "state " + state->Label() + " '" + state->Name() + "'";
}

std::string DescribeTransition(const TransitionSegmentBase* transition) {
  return "transition '" + transition->Name() + "' (" + transition->Source()->Label() + " -> " +
         transition->Target()->Label() + ")";
}

// "250 ms", "1.3 s": a watchdog limit is often below a second, a hang seldom.
std::string Seconds(std::chrono::steady_clock::duration duration) {
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
// RunUntilStable() on another thread.
thread_local const EngineCore* current_loop_core = nullptr;
thread_local std::uint64_t current_loop_generation = 0;

}  // namespace

EngineCore::EngineCore(Statechart& chart, kse::messaging::MessageHub& hub, Options options)
    : hub_(hub),
      options_(std::move(options)),
      root_blackboard_(hub, chart.Name()),
      chart_(chart),
      chart_name_(chart.Name()),
      watchdog_limit_ms_(std::max<std::int64_t>(0, options_.watchdog_limit.count())) {
  if (options_.reporter) reporter_ = std::make_shared<const Reporter>(options_.reporter);
}

EngineCore::~EngineCore() {
  Shutdown();
  // Transitions first (their conditions and actions may refer to blackboards), then the
  // states in reverse creation order.
  owned_transitions_.clear();
  while (!owned_states_.empty()) {
    owned_states_.pop_back();
  }
}

// ---------------------------------------------------------------------------------------------
// Reports and the watchdog
// ---------------------------------------------------------------------------------------------

void EngineCore::Report(EngineReport::Kind kind, std::string text) const {
  EngineReport report;
  report.kind = kind;
  report.chart = chart_name_;
  report.text = std::move(text);
  Deliver(report);
}

void EngineCore::Deliver(const EngineReport& report, bool to_reporter) const {
  std::shared_ptr<const Reporter> reporter;
  if (to_reporter) {
    std::lock_guard<std::mutex> lock(reporter_mutex_);
    reporter = reporter_;
  }
  if (reporter) {
    try {
      (*reporter)(report);
      return;
    } catch (...) {
      // a reporter that throws loses nothing: the report goes to standard error
    }
  }
  std::cerr << ToString(report) + '\n' << std::flush;
}

void EngineCore::SetReporter(Reporter reporter) {
  auto shared = reporter ? std::make_shared<const Reporter>(std::move(reporter)) : nullptr;
  std::lock_guard<std::mutex> lock(reporter_mutex_);
  reporter_ = std::move(shared);
}

void EngineCore::SetWatchdogLimit(std::chrono::milliseconds limit) {
  watchdog_limit_ms_.store(std::max<std::int64_t>(0, limit.count()), std::memory_order_relaxed);
  Watchdog::Instance().LimitsChanged();
}

void EngineCore::SetActivityWatchdogLimit(const std::string& activity,
                                          std::chrono::milliseconds limit) {
  {
    std::lock_guard<std::mutex> lock(limits_mutex_);
    auto found = std::find_if(activity_limits_.begin(), activity_limits_.end(),
                              [&](const auto& entry) { return entry.first == activity; });
    if (found != activity_limits_.end()) {
      found->second = limit;
    } else {
      activity_limits_.emplace_back(activity, limit);
    }
  }
  if (IsActivated()) ApplyActivityLimits();
  Watchdog::Instance().LimitsChanged();
}

void EngineCore::ApplyActivityLimits() {
  std::lock_guard<std::mutex> lock(limits_mutex_);
  for (std::size_t slot = 0; slot < activity_slot_count_; ++slot) {
    for (const auto& [activity, limit] : activity_limits_) {
      if (activity_names_[slot] == activity) {
        activity_limits_ms_[slot].store(std::max<std::int64_t>(0, limit.count()),
                                        std::memory_order_relaxed);
      }
    }
  }
}

std::chrono::milliseconds EngineCore::ShortestWatchdogLimit() const noexcept {
  std::int64_t shortest = watchdog_limit_ms_.load(std::memory_order_relaxed);
  for (std::size_t slot = 0; slot < activity_slot_count_; ++slot) {
    const std::int64_t own = activity_limits_ms_[slot].load(std::memory_order_relaxed);
    if (own > 0 && (shortest == 0 || own < shortest)) shortest = own;
  }
  return std::chrono::milliseconds(shortest);
}

std::int64_t EngineCore::LimitOf(CallKind kind, const void* subject) const noexcept {
  if (kind == CallKind::Activity) {
    const auto* state = static_cast<const BasicState*>(subject);
    const std::int64_t own = activity_limits_ms_[state->watch_slot_].load(std::memory_order_relaxed);
    if (own >= 0) return own;
  }
  return watchdog_limit_ms_.load(std::memory_order_relaxed);
}

std::string EngineCore::DescribeCall(CallKind kind, const void* subject) const {
  const auto* state = static_cast<const State*>(subject);
  const auto* transition = static_cast<const TransitionSegmentBase*>(subject);
  switch (kind) {
    case CallKind::Activity:
    case CallKind::ActivityInit: {
      const auto* basic = static_cast<const BasicState*>(state);
      return std::string(kind == CallKind::ActivityInit ? "UserInit of activity '" : "activity '") +
             activity_names_[basic->watch_slot_] + "' of " + DescribeLabelled(state);
    }
    case CallKind::Guard:
      return "guard of " + DescribeTransition(transition);
    case CallKind::GuardInit:
      return "UserInit of the guard of " + DescribeTransition(transition);
    case CallKind::Action:
      return "action of " + DescribeTransition(transition);
    case CallKind::ActionInit:
      return "UserInit of the action of " + DescribeTransition(transition);
    case CallKind::Entry:
      return "OnEntry of " + DescribeLabelled(state);
    case CallKind::Exit:
      return "OnExit of " + DescribeLabelled(state);
    case CallKind::Observer:
      return "observer of " + DescribeTransition(transition);
  }
  return "?";
}

bool EngineCore::ReadCall(const CallSlot& slot, CallKind& kind, const void*& subject) const noexcept {
  // A seqlock read: what the slot says is the call of the sequence number read before and after.
  for (int attempt = 0; attempt < 3; ++attempt) {
    const std::uint64_t before = slot.sequence.load(std::memory_order_acquire);
    if ((before & 1U) == 0) return false;
    // acquire: the sequence is read again only after these (no fence: ThreadSanitizer has none)
    kind = slot.kind.load(std::memory_order_acquire);
    subject = slot.subject.load(std::memory_order_acquire);
    if (slot.sequence.load(std::memory_order_relaxed) == before) return true;
  }
  return false;  // calls come and go too fast: nothing hangs here
}

std::string EngineCore::CurrentCall(const CallSlot& slot) const {
  CallKind kind;
  const void* subject;
  return ReadCall(slot, kind, subject) ? DescribeCall(kind, subject) : std::string();
}

void EngineCore::Inspect(std::chrono::steady_clock::time_point now,
                         const std::function<void(EngineReport)>& report) {
  auto look = [&](CallSlot& slot) {
    const std::uint64_t sequence = slot.sequence.load(std::memory_order_acquire);
    if (sequence != slot.seen) {
      if (slot.overrun != 0) {
        EngineReport ended;
        ended.kind = EngineReport::Kind::OverrunEnded;
        ended.chart = chart_name_;
        ended.overrun = slot.overrun;
        ended.running = std::chrono::duration_cast<std::chrono::milliseconds>(now - slot.since);
        ended.call = std::move(slot.call);
        ended.text = ended.call + " returned after about " + Seconds(now - slot.since);
        report(std::move(ended));
        slot.overrun = 0;
        slot.call.clear();
      }
      slot.seen = sequence;
      slot.since = now;
      return;
    }
    if ((sequence & 1U) == 0 || slot.overrun != 0) return;
    CallKind kind;
    const void* subject;
    if (!ReadCall(slot, kind, subject)) return;
    const std::int64_t limit = LimitOf(kind, subject);
    if (limit <= 0 || now - slot.since < std::chrono::milliseconds(limit)) return;
    const std::string call = DescribeCall(kind, subject);
    slot.overrun = Watchdog::NextOverrunId();
    overruns_.fetch_add(1, std::memory_order_relaxed);
    EngineReport overrun;
    overrun.kind = EngineReport::Kind::Overrun;
    overrun.chart = chart_name_;
    overrun.overrun = slot.overrun;
    overrun.running = std::chrono::duration_cast<std::chrono::milliseconds>(now - slot.since);
    overrun.text = call + " has been running for " + Seconds(now - slot.since) +
                   " (watchdog limit " + Seconds(std::chrono::milliseconds(limit)) +
                   "); it is still running";
    overrun.call = call;
    slot.call = call;
    report(std::move(overrun));
  };
  look(engine_slot_);
  for (std::size_t slot = 0; slot < activity_slot_count_; ++slot) look(activity_slots_[slot]);
}

void EngineCore::UnwindIfThisThreadWasGivenUp() const {
  const std::uint64_t given_up = given_up_generation_.load();
  if (given_up != 0 && current_loop_core == this && current_loop_generation <= given_up) {
    throw GivenUp{};
  }
}

void EngineCore::KeepAbandoned(std::unique_ptr<EngineCore> core) {
  static std::mutex mutex;
  static auto* const kept = new std::vector<std::unique_ptr<EngineCore>>();
  std::lock_guard<std::mutex> lock(mutex);
  kept->push_back(std::move(core));
}

// ---------------------------------------------------------------------------------------------
// Ownership
// ---------------------------------------------------------------------------------------------

void EngineCore::AdoptState(std::unique_ptr<State> state) {
  std::lock_guard<std::recursive_mutex> lock(engine_mutex_);
  if (IsActivated()) {
    throw std::logic_error("statechart '" + chart_.Name() + "': cannot add state '" +
                           state->Name() + "' after activation");
  }
  owned_states_.push_back(std::move(state));
}

void EngineCore::AdoptTransition(std::unique_ptr<TransitionSegmentBase> transition) {
  std::lock_guard<std::recursive_mutex> lock(engine_mutex_);
  if (IsActivated()) {
    throw std::logic_error("statechart '" + chart_.Name() + "': cannot add transition '" +
                           transition->Name() + "' after activation");
  }
  transition->Source()->outgoing_.push_back(transition.get());
  owned_transitions_.push_back(std::move(transition));
}

std::vector<State*> EngineCore::States() const {
  std::vector<State*> out;
  CollectStates(&chart_, out);
  return out;
}

std::vector<TransitionSegmentBase*> EngineCore::Transitions() const {
  std::lock_guard<std::recursive_mutex> lock(engine_mutex_);
  std::vector<TransitionSegmentBase*> out;
  out.reserve(owned_transitions_.size());
  for (const auto& transition : owned_transitions_) {
    out.push_back(transition.get());
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Structure
// ---------------------------------------------------------------------------------------------

void EngineCore::CollectStates(State* state, std::vector<State*>& out) const {
  out.push_back(state);
  for (State* child : state->children_) {
    CollectStates(child, out);
  }
}

void EngineCore::CheckStructure() const {
  auto fail = [this](const std::string& why) {
    throw std::logic_error("statechart '" + chart_.Name() + "': " + why);
  };
  for (const auto& owned : owned_states_) {
    const State* top = owned.get();
    while (top->parent_ != nullptr) {
      top = top->parent_;
    }
    if (top != &chart_) {
      fail("state " + Describe(owned.get()) + " is not inside this statechart");
    }
  }
  for (State* state : states_) {
    switch (state->kind_) {
      case StateKind::Or: {
        std::size_t starts = 0;
        std::size_t ends = 0;
        for (State* child : state->children_) {
          starts += child->kind_ == StateKind::Start ? 1U : 0U;
          ends += child->kind_ == StateKind::End ? 1U : 0U;
        }
        if (starts != 1) {
          fail("OR state " + Describe(state) + " needs exactly one START child, it has " +
               std::to_string(starts));
        }
        if (ends > 1) {
          fail("OR state " + Describe(state) + " has more than one END child");
        }
        break;
      }
      case StateKind::And:
        for (State* child : state->children_) {
          if (child->kind_ != StateKind::Or) {
            fail("AND state " + Describe(state) + " has a child that is not an OR state: " +
                 Describe(child));
          }
        }
        break;
      default:
        if (!state->children_.empty()) {
          fail(std::string(ToString(state->kind_)) + " state " + Describe(state) +
               " cannot have children");
        }
        break;
    }
  }
}

void EngineCore::ComputeTransition(TransitionSegmentBase& t) const {
  auto fail = [this, &t](const std::string& why) {
    throw std::logic_error("statechart '" + chart_.Name() + "': transition '" + t.Name() + "' " +
                           why);
  };
  State* source = t.source_;
  State* target = t.target_;
  auto inside = [this](const State* state) {
    while (state->parent_ != nullptr) {
      state = state->parent_;
    }
    return state == &chart_;
  };
  if (!inside(source) || !inside(target)) {
    fail("connects a state outside this statechart");
  }
  if (source->parent_ == nullptr || target->parent_ == nullptr) {
    fail("cannot leave or enter the root");
  }
  if (target->kind_ == StateKind::Start) {
    fail("enters a START state");
  }
  if (source->kind_ == StateKind::End) {
    fail("leaves an END state");
  }
  // Lowest common ancestor of the parents = lowest state properly containing both ends.
  State* a = source->parent_;
  State* b = target->parent_;
  while (a->depth_ > b->depth_) a = a->parent_;
  while (b->depth_ > a->depth_) b = b->parent_;
  while (a != b) {
    a = a->parent_;
    b = b->parent_;
  }
  // Leaving one region of an AND state for another leaves the whole AND state.
  while (a->kind_ == StateKind::And) {
    a = a->parent_;
  }
  t.lca_ = a;

  State* exit_top = source;
  while (exit_top->parent_ != a) {
    exit_top = exit_top->parent_;
  }
  t.exit_top_ = exit_top;

  t.entry_path_.clear();
  for (State* s = target; s != a; s = s->parent_) {
    t.entry_path_.push_back(s);
  }
  std::reverse(t.entry_path_.begin(), t.entry_path_.end());

  State* scope_owner = a;
  while (scope_owner->parent_ != nullptr &&
         !(scope_owner->kind_ == StateKind::Or && AsOr(scope_owner)->IsRegion())) {
    scope_owner = scope_owner->parent_;
  }
  t.scope_ = scope_owner->parent_ == nullptr ? &root_blackboard_
                                             : AsOr(scope_owner)->region_blackboard_.get();
  if (t.condition_) t.condition_->SetBlackboard(t.scope_);
  if (t.action_) t.action_->SetBlackboard(t.scope_);
}

void EngineCore::Prepare() {
  states_.clear();
  CollectStates(&chart_, states_);
  CheckStructure();

  blackboards_.clear();
  blackboards_.push_back(&root_blackboard_);
  for (State* state : states_) {
    if (state->kind_ == StateKind::Or) {
      OrState* orState = AsOr(state);
      orState->start_ = nullptr;
      for (State* child : state->children_) {
        if (child->kind_ == StateKind::Start) orState->start_ = child;
      }
      if (orState->IsRegion()) {
        if (!orState->region_blackboard_) {
          orState->region_blackboard_ =
              std::make_unique<kse::messaging::Blackboard>(hub_, orState->Name());
        }
        blackboards_.push_back(orState->region_blackboard_.get());
      }
    }
    if (state->parent_ == nullptr) {
      state->scope_ = &root_blackboard_;
      state->region_ = AsOr(state);
    } else if (state->kind_ == StateKind::Or && AsOr(state)->IsRegion()) {
      state->scope_ = AsOr(state)->region_blackboard_.get();
      state->region_ = AsOr(state);
    } else {
      state->scope_ = state->parent_->scope_;
      state->region_ = state->parent_->region_;
    }
    if (state->kind_ == StateKind::Basic) {
      if (IActivity* activity = static_cast<BasicState*>(state)->activity_.get()) {
        activity->SetBlackboard(state->scope_);
      }
    }
    OrderOutgoing(state->outgoing_);
  }
  for (const auto& transition : owned_transitions_) {
    ComputeTransition(*transition);
  }

  // One watchdog slot per activity; its name is asked once, here, so that the watchdog never
  // calls user code.
  slot_states_.clear();
  activity_names_.clear();
  for (State* state : states_) {
    if (state->kind_ != StateKind::Basic) continue;
    auto* basic = static_cast<BasicState*>(state);
    basic->watch_slot_ = slot_states_.size();
    slot_states_.push_back(basic);
    std::string name = "?";
    if (basic->activity_) {
      try {
        name = basic->activity_->GetName();
      } catch (...) {
      }
    }
    activity_names_.push_back(std::move(name));
  }
  activity_slot_count_ = slot_states_.size();
  activity_slots_ = std::make_unique<CallSlot[]>(std::max<std::size_t>(1, activity_slot_count_));
  activity_limits_ms_ =
      std::make_unique<std::atomic<std::int64_t>[]>(std::max<std::size_t>(1, activity_slot_count_));
  for (std::size_t slot = 0; slot < activity_slot_count_; ++slot) activity_limits_ms_[slot] = -1;
}

void EngineCore::CallUserInits() {
  for (State* state : states_) {
    if (state->kind_ != StateKind::Basic) continue;
    IActivity* activity = static_cast<BasicState*>(state)->activity_.get();
    if (activity == nullptr) continue;
    try {
      WatchedCall watched(engine_slot_, CallKind::ActivityInit, state);
      activity->UserInit();
    } catch (const std::exception& e) {
      ++activity_failures_;
      Report(EngineReport::Kind::Failure,
             "UserInit of the activity of state " + Describe(state) + " threw: " + e.what());
    } catch (...) {
      ++activity_failures_;
      Report(EngineReport::Kind::Failure,
             "UserInit of the activity of state " + Describe(state) + " threw");
    }
  }
  for (const auto& transition : owned_transitions_) {
    try {
      WatchedCall watched(engine_slot_, CallKind::GuardInit, transition.get());
      if (transition->condition_) transition->condition_->UserInit();
    } catch (const std::exception& e) {
      ++guard_failures_;
      Report(EngineReport::Kind::Failure,
             "UserInit of the guard of '" + transition->Name() + "' threw: " + e.what());
    } catch (...) {
      ++guard_failures_;
      Report(EngineReport::Kind::Failure,
             "UserInit of the guard of '" + transition->Name() + "' threw");
    }
    try {
      WatchedCall watched(engine_slot_, CallKind::ActionInit, transition.get());
      if (transition->action_) transition->action_->UserInit();
    } catch (const std::exception& e) {
      ++action_failures_;
      Report(EngineReport::Kind::Failure,
             "UserInit of the action of '" + transition->Name() + "' threw: " + e.what());
    } catch (...) {
      ++action_failures_;
      Report(EngineReport::Kind::Failure,
             "UserInit of the action of '" + transition->Name() + "' threw");
    }
  }
}

void EngineCore::Activate() {
  if (IsActivated()) {
    return;  // without the lock: an engine thread stuck in a guard holds it
  }
  std::lock_guard<std::recursive_mutex> lock(engine_mutex_);
  if (IsActivated()) {
    return;
  }
  Prepare();
  ApplyActivityLimits();
  if (!options_.inline_activities && options_.worker_threads > 0 && !pool_) {
    pool_ = std::make_unique<WorkerPool>(options_.worker_threads);
  }
  Watchdog::Instance().Watch(this);
  watched_ = true;
  CallUserInits();
  activated_.store(true, std::memory_order_release);
  EnterDefault(&chart_);
  {
    std::lock_guard<std::mutex> wake(wake_mutex_);
    woken_ = true;  // the first evaluation
    ++wake_generation_;
  }
  wake_cv_.notify_all();
}

// ---------------------------------------------------------------------------------------------
// Stepping
// ---------------------------------------------------------------------------------------------

bool EngineCore::Step() {
  std::lock_guard<std::recursive_mutex> lock(engine_mutex_);
  if (!IsActivated()) {
    Activate();
  }
  return StepRoot();
}

bool EngineCore::StepRoot() {
  // Written only under engine_mutex_: a plain increment, no locked read-modify-write.
  step_number_.store(step_number_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  return StepState(&chart_);
}

// Monas' Step() of each kind of state. A region's running flag stops everything in the region;
// the composite's own transitions come after its inside could not move, whatever is active in
// it (not only its END).
bool EngineCore::StepState(State* state) {
  switch (state->kind_) {
    case StateKind::Or: {
      if (state->region_->IsRunning()) {
        return false;
      }
      State* child = AsOr(state)->active_child_;
      if (child != nullptr && StepState(child)) {
        return true;
      }
      return TryTransitions(state);
    }
    case StateKind::And: {
      // Whether a region was running is taken before the regions step, as Monas did.
      bool running = false;
      for (const State* region : state->children_) {
        running = running || AsOr(region)->IsRunning();
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
    case StateKind::End:
      return false;
    default:
      return TryTransitions(state);
  }
}

bool EngineCore::EvalGuard(TransitionSegmentBase* transition) {
  ICondition* condition = transition->condition_.get();
  if (condition == nullptr) {
    return true;
  }
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

bool EngineCore::TryTransitions(State* state) {
  if (state->region_->IsRunning()) {
    return false;
  }
  for (TransitionSegmentBase* transition : state->outgoing_) {
    if (!EvalGuard(transition)) continue;
    if (transition->target_->kind_ != StateKind::Condition) {
      Fire(transition);
      return true;
    }
    chain_.clear();
    chain_.push_back(transition);
    if (!FindChain(transition->target_, 0)) {
      continue;
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
  return false;
}

void EngineCore::Fire(TransitionSegmentBase* transition) {
  Exit(transition->exit_top_);
  if (IAction* action = transition->action_.get()) {
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
  EnterAlong(transition->entry_path_, 0);
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
}

// ---------------------------------------------------------------------------------------------
// Entering and leaving
// ---------------------------------------------------------------------------------------------

void EngineCore::Enter(State* state) {
  if (state->parent_ != nullptr && state->parent_->kind_ == StateKind::Or) {
    AsOr(state->parent_)->active_child_ = state;
  }
  state->active_.store(true, std::memory_order_relaxed);
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

void EngineCore::EnterAlong(const std::vector<State*>& path, std::size_t index) {
  State* state = path[index];
  Enter(state);
  if (index + 1 == path.size()) {
    Complete(state);
    return;
  }
  State* next = path[index + 1];
  if (state->kind_ == StateKind::And) {
    for (State* region : state->children_) {
      if (region == next) {
        EnterAlong(path, index + 1);
      } else {
        EnterDefault(region);
      }
    }
  } else {
    EnterAlong(path, index + 1);
  }
}

void EngineCore::Exit(State* state) {
  if (state->kind_ == StateKind::Or) {
    if (State* child = AsOr(state)->active_child_) {
      Exit(child);
    }
  } else if (state->kind_ == StateKind::And) {
    for (auto it = state->children_.rbegin(); it != state->children_.rend(); ++it) {
      if ((*it)->IsActive()) {
        Exit(*it);
      }
    }
  }
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
  state->active_.store(false, std::memory_order_relaxed);
  if (state->parent_ != nullptr && state->parent_->kind_ == StateKind::Or) {
    AsOr(state->parent_)->active_child_ = nullptr;
  }
}

// ---------------------------------------------------------------------------------------------
// Activities
// ---------------------------------------------------------------------------------------------

void EngineCore::Launch(BasicState* state) {
  if (!state->activity_) {
    return;
  }
  state->launches_.fetch_add(1, std::memory_order_relaxed);
  if (!pool_) {
    RunActivity(state);
    UnwindIfGivenUp();
    return;
  }
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    state->region_->running_.fetch_add(1, std::memory_order_acq_rel);
    running_activities_.fetch_add(1, std::memory_order_acq_rel);
    if (state->running_.load(std::memory_order_acquire)) {
      // Entered again (after an outer transition left it) while the last run goes on: one
      // IActivity object never runs twice at once, so the worker runs it again afterwards.
      ++state->relaunches_;
      return;
    }
    state->running_.store(true, std::memory_order_release);
  }
  pool_->Post([this, state] {
    do {
      RunActivity(state);
    } while (FinishActivity(state));
  });
}

void EngineCore::RunActivity(BasicState* state) {
  IActivity* activity = state->activity_.get();
  const char* failure = nullptr;
  std::string message;
  try {
    WatchedCall watched(SlotOf(state), CallKind::Activity, state);
    activity->Execute();
    return;
  } catch (const std::exception& e) {
    failure = "threw";
    message = e.what();
  } catch (...) {
    failure = "threw a non-standard exception";
  }
  ++activity_failures_;
  std::string name;
  try {
    name = activity->GetName();
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
    state->region_->running_.fetch_sub(1, std::memory_order_acq_rel);
    running_activities_.fetch_sub(1, std::memory_order_acq_rel);
    if (state->relaunches_ > 0) {
      --state->relaunches_;
      again = true;
    } else {
      state->running_.store(false, std::memory_order_release);
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
  bool woken;
  {
    std::lock_guard<std::mutex> lock(wake_mutex_);
    woken = woken_;
    woken_ = false;
  }
  const kse::messaging::TimePoint now = hub_.GetClock().Now();
  for (kse::messaging::Blackboard* board : blackboards_) {
    woken = board->TakeDueWakeups(now) || woken;
  }
  return woken;
}

bool EngineCore::StepUntilQuiet(std::size_t max_transitions, std::size_t first) {
  std::lock_guard<std::recursive_mutex> lock(engine_mutex_);
  while (StepRoot()) {
    if (transitions_taken_.load(std::memory_order_relaxed) - first >= max_transitions) {
      Report(EngineReport::Kind::Warning, "RunUntilStable stopped after " +
                                              std::to_string(max_transitions) +
                                              " transitions: the statechart does not settle");
      return false;
    }
  }
  return true;
}

bool EngineCore::RunIfWoken() {
  Activate();
  if (!TakeWake()) {
    return false;
  }
  StepUntilQuiet(std::numeric_limits<std::size_t>::max(), 0);
  return true;
}

bool EngineCore::RunUntilStable(std::size_t max_transitions) {
  Activate();
  const std::size_t first = transitions_taken_.load(std::memory_order_relaxed);
  for (;;) {
    if (TakeWake()) {
      if (!StepUntilQuiet(max_transitions, first)) {
        return false;
      }
      continue;
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
  std::optional<kse::messaging::TimePoint> next;
  for (const kse::messaging::Blackboard* board : blackboards_) {
    auto wakeup = board->NextWakeup();
    if (wakeup && (!next || *wakeup < *next)) {
      next = wakeup;
    }
  }
  return next;
}

void EngineCore::Start() {
  Activate();
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
      if (slot_states_[slot]->IsRunning()) {
        left.push_back(DescribeCall(CallKind::Activity, slot_states_[slot]));
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
  report.chart = chart_name_;
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
        std::lock_guard<std::recursive_mutex> lock(engine_mutex_);
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
  std::lock_guard<std::recursive_mutex> lock(engine_mutex_);
  std::vector<std::string> names;
  for (const State* state : states_) {
    if (state->IsActive()) {
      names.push_back(state->Name());
    }
  }
  return names;
}

void EngineCore::SetObserver(Statechart::Observer observer) {
  std::lock_guard<std::recursive_mutex> lock(engine_mutex_);
  observer_ = std::move(observer);
}

}  // namespace detail

// -------------------------------------------------------------------------------------------
// Statechart
// -------------------------------------------------------------------------------------------

Statechart::Statechart(std::string name, kse::messaging::MessageHub& hub, Options options)
    : OrState(std::move(name), nullptr),
      core_(std::make_unique<detail::EngineCore>(*this, hub, options)) {}

Statechart::~Statechart() {
  if (core_->Shutdown()) {
    detail::EngineCore::KeepAbandoned(std::move(core_));
  } else {
    core_.reset();
  }
}

void Statechart::AdoptState(std::unique_ptr<State> state) { core_->AdoptState(std::move(state)); }

void Statechart::AdoptTransition(std::unique_ptr<TransitionSegmentBase> transition) {
  if (transition->Source() == nullptr || transition->Target() == nullptr) {
    throw std::invalid_argument("statechart '" + Name() + "': a transition needs a source and a target");
  }
  core_->AdoptTransition(std::move(transition));
}

void Statechart::Start() { core_->Start(); }
void Statechart::Stop() { core_->Stop(); }
bool Statechart::IsStarted() const noexcept { return core_->IsStarted(); }
void Statechart::Activate() { core_->Activate(); }
bool Statechart::IsActivated() const noexcept { return core_->IsActivated(); }
bool Statechart::Step() { return core_->Step(); }
bool Statechart::RunIfWoken() { return core_->RunIfWoken(); }

void Statechart::RunUntilStable() { RunUntilStable(1000000); }
bool Statechart::RunUntilStable(std::size_t max_transitions) {
  return core_->RunUntilStable(max_transitions);
}

std::vector<std::string> Statechart::ActiveStates() const { return core_->ActiveStates(); }
std::size_t Statechart::ActivityFailures() const noexcept { return core_->activity_failures_.load(); }
std::size_t Statechart::GuardFailures() const noexcept { return core_->guard_failures_.load(); }
std::size_t Statechart::ActionFailures() const noexcept { return core_->action_failures_.load(); }
std::size_t Statechart::TransitionsTaken() const noexcept { return core_->transitions_taken_.load(); }
std::size_t Statechart::StepNumber() const noexcept { return core_->step_number_.load(); }
std::optional<kse::messaging::TimePoint> Statechart::NextWakeup() const { return core_->NextWakeup(); }
std::size_t Statechart::RunningActivities() const noexcept {
  return core_->running_activities_.load();
}
std::size_t Statechart::Overruns() const noexcept { return core_->overruns_.load(); }
void Statechart::SetReporter(Reporter reporter) { core_->SetReporter(std::move(reporter)); }
void Statechart::SetWatchdogLimit(std::chrono::milliseconds limit) { core_->SetWatchdogLimit(limit); }
std::chrono::milliseconds Statechart::WatchdogLimit() const noexcept { return core_->WatchdogLimit(); }
void Statechart::SetActivityWatchdogLimit(const std::string& activity,
                                          std::chrono::milliseconds limit) {
  core_->SetActivityWatchdogLimit(activity, limit);
}

const char* ToString(EngineReport::Kind kind) noexcept {
  switch (kind) {
    case EngineReport::Kind::Failure:
      return "failure";
    case EngineReport::Kind::Overrun:
      return "overrun";
    case EngineReport::Kind::OverrunEnded:
      return "overrun-ended";
    case EngineReport::Kind::Abandoned:
      return "abandoned";
    case EngineReport::Kind::Warning:
      return "warning";
  }
  return "?";
}

std::string ToString(const EngineReport& report) {
  return "[kse] statechart '" + report.chart + "': " + report.text;
}
void Statechart::SetObserver(Observer observer) { core_->SetObserver(std::move(observer)); }
void Statechart::Wake() { core_->Wake(); }
kse::messaging::MessageHub& Statechart::Hub() const noexcept { return core_->hub_; }
Blackboard& Statechart::RootBlackboard() const noexcept { return core_->root_blackboard_; }
const Options& Statechart::GetOptions() const noexcept { return core_->options_; }
std::vector<State*> Statechart::States() const { return core_->States(); }
std::vector<TransitionSegmentBase*> Statechart::Transitions() const { return core_->Transitions(); }

}  // namespace statechart_engine
