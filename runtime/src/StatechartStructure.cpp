#include "EngineCore.h"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <utility>

namespace statechart_engine::detail {

namespace {

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

// Whether a state's class overrides OnEntry()/OnExit(): generated states never do, and a call
// of State's own (empty) hooks is skipped. G++ can name the function a virtual call would reach
// (its bound member function extension); elsewhere every hook is called.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpmf-conversions"
#pragma GCC diagnostic ignored "-Wpedantic"
using Hook = void (*)(State*);
Hook EntryOf(State* state) { return reinterpret_cast<Hook>(state->*(&State::OnEntry)); }
Hook ExitOf(State* state) { return reinterpret_cast<Hook>(state->*(&State::OnExit)); }
#pragma GCC diagnostic pop

bool OverridesEntry(State* state) {
  static StartState plain("", nullptr);  // State's own hooks
  static const Hook none = EntryOf(&plain);
  return EntryOf(state) != none;
}
bool OverridesExit(State* state) {
  static StartState plain("", nullptr);
  static const Hook none = ExitOf(&plain);
  return ExitOf(state) != none;
}
#else
bool OverridesEntry(State*) { return true; }
bool OverridesExit(State*) { return true; }
#endif

}  // namespace

// ---------------------------------------------------------------------------------------------
// Ownership
// ---------------------------------------------------------------------------------------------

void EngineCore::AdoptState(std::unique_ptr<State> state) {
  std::lock_guard<EngineLock> lock(engine_lock_);
  if (IsActivated()) {
    throw std::logic_error("statechart '" + chart_.Name() + "': cannot add state '" +
                           state->Name() + "' after activation");
  }
  owned_states_.push_back(std::move(state));
}

void EngineCore::AdoptTransition(std::unique_ptr<TransitionSegmentBase> transition) {
  std::lock_guard<EngineLock> lock(engine_lock_);
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
  std::lock_guard<EngineLock> lock(engine_lock_);
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

void EngineCore::ComputeTransition(TransitionSegmentBase& t) {
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

  // Appended to entry_paths_; Prepare points the transition at it once every path is in.
  const std::size_t first = entry_paths_.size();
  for (State* s = target; s != a; s = s->parent_) {
    entry_paths_.push_back(s);
  }
  std::reverse(entry_paths_.begin() + static_cast<std::ptrdiff_t>(first), entry_paths_.end());
  t.entry_length_ = static_cast<std::uint32_t>(entry_paths_.size() - first);

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
  states_.reserve(owned_states_.size() + 1);  // the root and what it owns
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
    state->calls_entry_ = OverridesEntry(state);
    state->calls_exit_ = OverridesExit(state);
  }
  entry_paths_.clear();
  for (const auto& transition : owned_transitions_) {
    ComputeTransition(*transition);
  }
  entry_paths_.shrink_to_fit();
  std::size_t next = 0;
  for (const auto& transition : owned_transitions_) {
    transition->entry_path_ = entry_paths_.data() + next;
    next += transition->entry_length_;
  }
  // The structure is fixed from here on: no room kept for growth.
  owned_states_.shrink_to_fit();
  owned_transitions_.shrink_to_fit();
  for (State* state : states_) state->children_.shrink_to_fit();

  // One watchdog slot per activity; its name is asked once, here, so that the watchdog never
  // calls user code.
  slot_states_.clear();
  activity_names_.clear();
  const auto basics = static_cast<std::size_t>(std::count_if(
      states_.begin(), states_.end(), [](const State* s) { return s->kind_ == StateKind::Basic; }));
  slot_states_.reserve(basics);
  activity_names_.reserve(basics);
  for (State* state : states_) {
    if (state->kind_ != StateKind::Basic) continue;
    auto* basic = static_cast<BasicState*>(state);
    basic->watch_slot_ = static_cast<std::uint32_t>(slot_states_.size());
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
  // Inline activities are watched through the engine's own slot (SlotOf).
  if (UsesPool() && activity_slot_count_ > 0) {
    activity_slots_ = std::make_unique<CallSlot[]>(activity_slot_count_);
  }
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
  std::lock_guard<EngineLock> lock(engine_lock_);
  if (IsActivated()) {
    return;
  }
  Prepare();
  ApplyActivityLimits();
  if (UsesPool() && !pool_) {
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

}  // namespace statechart_engine::detail
