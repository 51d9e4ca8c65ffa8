#include "EngineCore.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <new>
#include <stdexcept>
#include <utility>

namespace statechart_engine::detail {

// ---------------------------------------------------------------------------------------------
// The statechart's own memory
// ---------------------------------------------------------------------------------------------

void EngineCore::MakeBlock() {
  const Definition& d = *definition_;
  if (d.HasGivenParts() && d.taken_.exchange(true)) {
    throw std::logic_error("statechart '" + Name() +
                           "': its definition was given objects (not made with Make<T>()), "
                           "which another statechart already took: it makes one statechart only");
  }
  block_ = static_cast<unsigned char*>(
      ::operator new(d.block_size_, std::align_val_t(d.block_align_)));
  activity_runs_ = reinterpret_cast<std::atomic<bool>*>(block_ + d.activity_runs_at_);
  active_child_ = reinterpret_cast<std::atomic<State*>*>(block_ + d.active_child_at_);
  running_ = reinterpret_cast<std::atomic<int>*>(block_ + d.running_at_);
  launches_ = reinterpret_cast<std::atomic<std::uint32_t>*>(block_ + d.launches_at_);
  relaunches_ = reinterpret_cast<std::uint32_t*>(block_ + d.relaunches_at_);
  boards_ = reinterpret_cast<kse::messaging::Blackboard*>(block_ + d.boards_at_);
  for (std::size_t i = 0; i < d.basic_states_.size(); ++i) {
    ::new (&activity_runs_[i]) std::atomic<bool>(false);
  }
  for (std::size_t i = 0; i < d.or_states_.size(); ++i) ::new (&active_child_[i]) std::atomic<State*>(nullptr);
  for (std::size_t i = 0; i < d.regions_.size(); ++i) ::new (&running_[i]) std::atomic<int>(0);
  for (std::size_t i = 0; i < d.basic_states_.size(); ++i) {
    ::new (&launches_[i]) std::atomic<std::uint32_t>(0);
  }
  std::fill_n(relaunches_, d.basic_states_.size(), 0U);

  // Blackboards, then the parts, which may subscribe to them; each step undone if a later fails.
  std::size_t boards = 0;
  std::size_t activities = 0;
  std::size_t transitions = 0;
  try {
    for (; boards + 1 < d.regions_.size(); ++boards) {
      ::new (&boards_[boards]) kse::messaging::Blackboard(hub_, d.regions_[boards + 1]->Name());
    }
    for (; activities < d.basic_states_.size(); ++activities) {
      BasicState* state = d.basic_states_[activities];
      MakePart(state->activity_, state->activity_at_, given_activities_);
    }
    for (; transitions < d.owned_transitions_.size(); ++transitions) {
      TransitionSegmentBase* t = d.owned_transitions_[transitions].get();
      MakePart(t->condition_, t->condition_at_, given_conditions_);
      try {
        MakePart(t->action_, t->action_at_, given_actions_);
      } catch (...) {
        if (t->condition_.Maker()) ConditionOf(t)->~ICondition();
        throw;
      }
    }
  } catch (...) {
    DestroyMade(transitions, activities, boards);
    ::operator delete(block_, std::align_val_t(d.block_align_));
    block_ = nullptr;
    throw;
  }
}

template <class I>
void EngineCore::MakePart(const Part<I>& part, std::size_t at, std::vector<std::unique_ptr<I>>& owned) {
  if (const auto* maker = part.Maker()) {
    maker->Construct(block_ + at - maker->Base());
  } else if (part.IsCreated()) {
    std::unique_ptr<I> object = (*part.creator_)();
    *reinterpret_cast<I**>(block_ + (at & ~std::size_t{1})) = object.get();
    owned.push_back(std::move(object));
  } else if (part.given_) {
    owned.push_back(std::move(part.given_));
  }
}

void EngineCore::DestroyMade(std::size_t transitions, std::size_t activities,
                             std::size_t boards) noexcept {
  const Definition& d = *definition_;
  // Transitions first (their conditions and actions may refer to blackboards), then the
  // activities, then the blackboards, as the states that held them went in reverse order.
  while (transitions > 0) {
    TransitionSegmentBase* t = d.owned_transitions_[--transitions].get();
    if (t->action_.Maker()) ActionOf(t)->~IAction();
    if (t->condition_.Maker()) ConditionOf(t)->~ICondition();
  }
  given_actions_.clear();
  given_conditions_.clear();
  while (activities > 0) {
    BasicState* state = d.basic_states_[--activities];
    if (state->activity_.Maker()) ActivityOf(state)->~IActivity();
  }
  given_activities_.clear();
  while (boards > 0) boards_[--boards].~Blackboard();
}

void EngineCore::DestroyBlock() noexcept {
  if (block_ == nullptr) return;
  const Definition& d = *definition_;
  DestroyMade(d.owned_transitions_.size(), d.basic_states_.size(), d.regions_.size() - 1);
  ::operator delete(block_, std::align_val_t(d.block_align_));
  block_ = nullptr;
}

// ---------------------------------------------------------------------------------------------
// Activation
// ---------------------------------------------------------------------------------------------

void EngineCore::CallUserInits() {
  const Definition& d = *definition_;
  for (BasicState* state : d.basic_states_) {
    IActivity* activity = ActivityOf(state);
    if (activity == nullptr) continue;
    activity->SetBlackboard(BoardOf(state->region_));
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
  for (const auto& owned : d.owned_transitions_) {
    TransitionSegmentBase* transition = owned.get();
    kse::messaging::Blackboard* scope = BoardOf(transition->scope_);
    ICondition* condition = ConditionOf(transition);
    IAction* action = ActionOf(transition);
    if (condition) condition->SetBlackboard(scope);
    if (action) action->SetBlackboard(scope);
    try {
      WatchedCall watched(engine_slot_, CallKind::GuardInit, transition);
      if (condition) condition->UserInit();
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
      WatchedCall watched(engine_slot_, CallKind::ActionInit, transition);
      if (action) action->UserInit();
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
  if (own_definition_ != nullptr) own_definition_->Complete();
  if (block_ == nullptr) MakeBlock();
  const Definition& d = *definition_;

  // The activities' names, asked once per definition (a statechart's first activation), so
  // that the watchdog never calls user code: an activity's class gives its name.
  std::call_once(d.activity_names_once_, [&] {
    d.activity_names_.reserve(d.basic_states_.size());
    for (BasicState* basic : d.basic_states_) {
      std::string name = "?";
      if (IActivity* activity = ActivityOf(basic)) {
        try {
          name = activity->GetName();
        } catch (...) {
        }
      }
      d.activity_names_.push_back(std::move(name));
    }
  });
  // One watchdog slot per activity. Inline activities are watched through the engine's own slot (SlotOf).
  activity_slot_count_ = d.basic_states_.size();
  if (UsesPool() && activity_slot_count_ > 0) {
    activity_slots_ = std::make_unique<CallSlot[]>(activity_slot_count_);
  }
  activity_limits_ms_ =
      std::make_unique<std::atomic<std::int64_t>[]>(std::max<std::size_t>(1, activity_slot_count_));
  for (std::size_t slot = 0; slot < activity_slot_count_; ++slot) activity_limits_ms_[slot] = -1;

  ApplyActivityLimits();
  if (UsesPool() && !pool_) {
    pool_ = std::make_unique<WorkerPool>(options_.worker_threads);
  }
  Watchdog::Instance().Watch(this);
  watched_ = true;
  CallUserInits();
  activated_.store(true, std::memory_order_release);
  EnterDefault(root_);
  {
    std::lock_guard<std::mutex> wake(wake_mutex_);
    woken_ = true;  // the first evaluation
    ++wake_generation_;
  }
  wake_cv_.notify_all();
}

}  // namespace statechart_engine::detail
