#include "statechart_engine/Statechart.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "EngineCore.h"

namespace statechart_engine {
namespace detail {

namespace {

std::string DescribeTransition(const TransitionSegmentBase* transition) {
  return "transition '" + transition->Name() + "' (" + transition->Source()->Label() + " -> " +
         transition->Target()->Label() + ")";
}

}  // namespace

EngineCore::EngineCore(std::shared_ptr<const Definition> definition, Definition* own,
                       kse::messaging::MessageHub& hub, Options options)
    : root_(definition->Root()),
      inline_runs_last_(options.inline_activities_last_until_next_run),
      hub_(hub),
      options_(std::move(options)),
      root_blackboard_(hub, definition->Name()),
      definition_(std::move(definition)),
      own_definition_(own),
      watchdog_limit_ms_(std::max<std::int64_t>(0, options_.watchdog_limit.count())) {
  if (options_.reporter) reporter_ = std::make_shared<const Reporter>(options_.reporter);
}

EngineCore::~EngineCore() {
  Shutdown();
  DestroyBlock();
}

// ---------------------------------------------------------------------------------------------
// Reports and the watchdog
// ---------------------------------------------------------------------------------------------

void EngineCore::Report(EngineReport::Kind kind, std::string text) const {
  EngineReport report;
  report.kind = kind;
  report.chart = Name();
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
      if (definition_->activity_names_[slot] == activity) {
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
    const std::int64_t own = activity_limits_ms_[state->slot_].load(std::memory_order_relaxed);
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
             definition_->activity_names_[basic->slot_] + "' of " + DescribeLabelled(state);
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
        ended.chart = Name();
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
    overrun.chart = Name();
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
  if (activity_slots_) {
    for (std::size_t slot = 0; slot < activity_slot_count_; ++slot) look(activity_slots_[slot]);
  }
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

}  // namespace detail

// -------------------------------------------------------------------------------------------
// Statechart
// -------------------------------------------------------------------------------------------

Statechart::Statechart(std::shared_ptr<const Definition> definition, kse::messaging::MessageHub& hub,
                       Options options) {
  if (definition == nullptr) throw std::invalid_argument("a statechart needs a definition");
  if (!definition->IsComplete()) {
    throw std::logic_error("statechart '" + definition->Name() +
                           "': its definition is not complete (Definition::Complete())");
  }
  core_ = std::make_unique<detail::EngineCore>(std::move(definition), nullptr, hub, std::move(options));
}

Statechart::Statechart(std::string name, kse::messaging::MessageHub& hub, Options options)
    : own_(std::make_shared<Definition>(std::move(name))),
      core_(std::make_unique<detail::EngineCore>(own_, own_.get(), hub, std::move(options))) {}

Statechart::~Statechart() {
  if (core_->Shutdown()) {
    detail::EngineCore::KeepAbandoned(std::move(core_));
  } else {
    core_.reset();
  }
}

Definition& Statechart::OwnDefinition() {
  if (!own_) {
    throw std::logic_error("statechart '" + Name() +
                           "' is made from a shared definition: add states to the definition");
  }
  return *own_;
}

const std::string& Statechart::Name() const noexcept { return core_->Name(); }
OrState* Statechart::Root() const noexcept { return core_->GetDefinition().Root(); }
const Definition& Statechart::GetDefinition() const noexcept { return core_->GetDefinition(); }

bool Statechart::IsActive(const State* state) const noexcept { return core_->IsActive(state); }
State* Statechart::ActiveChild(const State* state) const noexcept { return core_->ActiveChild(state); }
bool Statechart::IsRunning(const State* state) const noexcept {
  if (state->Kind() == StateKind::Basic) {
    return core_->ActivityRunning(static_cast<const BasicState*>(state));
  }
  if (state->Kind() == StateKind::Or && state->Region() == state) {
    return core_->RegionRunning(static_cast<const OrState*>(state));
  }
  return false;
}
std::size_t Statechart::Launches(const BasicState* state) const noexcept { return core_->Launches(state); }
IActivity* Statechart::ActivityOf(const BasicState* state) const noexcept {
  return core_->HasBlock() ? core_->ActivityOf(state) : nullptr;
}
ICondition* Statechart::ConditionOf(const TransitionSegmentBase* transition) const noexcept {
  return core_->HasBlock() ? core_->ConditionOf(transition) : nullptr;
}
IAction* Statechart::ActionOf(const TransitionSegmentBase* transition) const noexcept {
  return core_->HasBlock() ? core_->ActionOf(transition) : nullptr;
}
Blackboard* Statechart::ScopeOf(const State* state) const noexcept {
  return state->Region() == nullptr ? nullptr : core_->BoardOf(state->Region());
}
Blackboard* Statechart::ScopeOf(const TransitionSegmentBase* transition) const noexcept {
  return transition->ScopeRegion() == nullptr ? nullptr : core_->BoardOf(transition->ScopeRegion());
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
std::string Statechart::UnsettledLoop() const { return core_->UnsettledLoop(); }
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
std::vector<State*> Statechart::States() const { return core_->GetDefinition().States(); }
std::vector<TransitionSegmentBase*> Statechart::Transitions() const {
  return core_->GetDefinition().Transitions();
}

}  // namespace statechart_engine
