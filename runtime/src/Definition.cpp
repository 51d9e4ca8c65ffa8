#include "statechart_engine/Definition.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <utility>

#include "kse/messaging/Blackboard.h"

namespace statechart_engine {

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

std::string Describe(const State* state) { return "'" + state->Name() + "'"; }

// The tree below `state`, itself first, in document order.
void CollectStates(State* state, std::vector<State*>& out) {
  out.push_back(state);
  for (State* child : state->Children()) CollectStates(child, out);
}

// Room for `count` objects of type T at the end of a block of `size` bytes.
template <class T>
std::size_t Reserve(std::size_t& size, std::size_t& align, std::size_t count) {
  align = std::max(align, alignof(T));
  size = (size + alignof(T) - 1) / alignof(T) * alignof(T);
  const std::size_t at = size;
  size += sizeof(T) * count;
  return at;
}

template <class I>
std::size_t ReservePart(const Part<I>& part, std::size_t& size, std::size_t& align) {
  if (part.IsGiven()) return 1;
  if (part.IsCreated()) {
    // a slot for the pointer to the object its creator makes; the odd offset says so
    return Reserve<I*>(size, align, 1) | 1U;
  }
  const detail::PartMaker<I>* maker = part.Maker();
  if (maker == nullptr) return 0;
  align = std::max(align, maker->Align());
  size = (size + maker->Align() - 1) / maker->Align() * maker->Align();
  const std::size_t at = size;
  size += maker->Size();
  return at + maker->Base();  // the interface's address is what the engine needs
}

}  // namespace

Definition::Definition(std::string name) {
  auto root = std::make_unique<OrState>(std::move(name), nullptr);
  root_ = root.get();
  owned_states_.push_back(std::move(root));
}

Definition::~Definition() {
  // Transitions first, then the states in reverse creation order.
  owned_transitions_.clear();
  while (!owned_states_.empty()) owned_states_.pop_back();
}

void Definition::Fail(const std::string& why) const {
  throw std::logic_error("statechart '" + Name() + "': " + why);
}

void Definition::AdoptState(std::unique_ptr<State> state) {
  if (IsComplete()) {
    Fail("cannot add state '" + state->Name() + "' after activation");
  }
  owned_states_.push_back(std::move(state));
}

void Definition::AdoptTransition(std::unique_ptr<TransitionSegmentBase> transition) {
  if (transition->Source() == nullptr || transition->Target() == nullptr) {
    throw std::invalid_argument("statechart '" + Name() + "': a transition needs a source and a target");
  }
  if (IsComplete()) {
    Fail("cannot add transition '" + transition->Name() + "' after activation");
  }
  transition->source_->outgoing_.push_back(transition.get());
  owned_transitions_.push_back(std::move(transition));
}

std::vector<TransitionSegmentBase*> Definition::Transitions() const {
  std::vector<TransitionSegmentBase*> out;
  out.reserve(owned_transitions_.size());
  for (const auto& transition : owned_transitions_) out.push_back(transition.get());
  return out;
}

std::vector<State*> Definition::States() const {
  if (IsComplete()) return states_;
  std::vector<State*> states;
  CollectStates(root_, states);
  return states;
}

void Definition::CheckStructure() const {
  for (const auto& owned : owned_states_) {
    const State* top = owned.get();
    while (top->parent_ != nullptr) top = top->parent_;
    if (top != root_) {
      Fail("state " + Describe(owned.get()) + " is not inside this statechart");
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
          Fail("OR state " + Describe(state) + " needs exactly one START child, it has " +
               std::to_string(starts));
        }
        if (ends > 1) {
          Fail("OR state " + Describe(state) + " has more than one END child");
        }
        break;
      }
      case StateKind::And:
        for (State* child : state->children_) {
          if (child->kind_ != StateKind::Or) {
            Fail("AND state " + Describe(state) + " has a child that is not an OR state: " +
                 Describe(child));
          }
        }
        break;
      default:
        if (!state->children_.empty()) {
          Fail(std::string(ToString(state->kind_)) + " state " + Describe(state) +
               " cannot have children");
        }
        break;
    }
  }
}

void Definition::ComputeTransition(TransitionSegmentBase& t) {
  auto fail = [this, &t](const std::string& why) { Fail("transition '" + t.Name() + "' " + why); };
  State* source = t.source_;
  State* target = t.target_;
  auto inside = [this](const State* state) {
    while (state->parent_ != nullptr) state = state->parent_;
    return state == root_;
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
  while (a->kind_ == StateKind::And) a = a->parent_;
  t.lca_ = a;

  State* exit_top = source;
  while (exit_top->parent_ != a) exit_top = exit_top->parent_;
  t.exit_top_ = exit_top;

  // Appended to entry_paths_; Complete points the transition at it once every path is in.
  const std::size_t first = entry_paths_.size();
  for (State* s = target; s != a; s = s->parent_) entry_paths_.push_back(s);
  std::reverse(entry_paths_.begin() + static_cast<std::ptrdiff_t>(first), entry_paths_.end());
  t.entry_length_ = static_cast<std::uint32_t>(entry_paths_.size() - first);
  t.scope_ = a->region_;
  auto leaf = [](const State* s) {
    return s->kind_ != StateKind::Or && s->kind_ != StateKind::And && s->kind_ != StateKind::Condition;
  };
  t.between_siblings_ = exit_top == source && t.entry_length_ == 1 && leaf(source) && leaf(target);
  State* deepest = target;
  while (deepest != nullptr && deepest->kind_ == StateKind::Or) deepest = static_cast<OrState*>(deepest)->start_;
  bool one_path = deepest != nullptr && deepest->kind_ != StateKind::And && deepest->kind_ != StateKind::Condition;
  for (State* s = target->parent_; one_path && s != nullptr; s = s->parent_) {
    one_path = s->kind_ != StateKind::And;
  }
  t.leaf_after_ = one_path ? deepest : nullptr;
}

void Definition::Complete() {
  if (IsComplete()) return;
  std::lock_guard<std::mutex> lock(complete_mutex_);
  if (IsComplete()) return;

  states_.clear();
  states_.reserve(owned_states_.size());
  CollectStates(root_, states_);
  CheckStructure();

  or_states_.clear();
  regions_.clear();
  basic_states_.clear();
  for (std::size_t i = 0; i < states_.size(); ++i) {
    State* state = states_[i];
    state->index_ = static_cast<std::uint32_t>(i);
    switch (state->kind_) {
      case StateKind::Or: {
        auto* or_state = static_cast<OrState*>(state);
        state->slot_ = static_cast<std::uint32_t>(or_states_.size());
        or_states_.push_back(or_state);
        or_state->start_ = nullptr;
        for (State* child : state->children_) {
          if (child->kind_ == StateKind::Start) or_state->start_ = child;
        }
        if (state->parent_ == nullptr || or_state->IsRegion()) {
          regions_.push_back(or_state);
        }
        break;
      }
      case StateKind::Basic:
        state->slot_ = static_cast<std::uint32_t>(basic_states_.size());
        basic_states_.push_back(static_cast<BasicState*>(state));
        break;
      default:
        break;
    }
    if (state->parent_ == nullptr ||
        (state->kind_ == StateKind::Or && static_cast<OrState*>(state)->IsRegion())) {
      state->region_ = static_cast<OrState*>(state);
      state->region_slot_ = static_cast<std::uint32_t>(regions_.size() - 1);
    } else {
      state->region_ = state->parent_->region_;
      state->region_slot_ = state->parent_->region_slot_;
    }
    state->parent_or_slot_ = state->parent_ != nullptr && state->parent_->kind_ == StateKind::Or
                                 ? state->parent_->slot_ + 1
                                 : 0;
    OrderOutgoing(state->outgoing_);
    state->calls_entry_ = OverridesEntry(state);
    state->calls_exit_ = OverridesExit(state);
  }
  entry_paths_.clear();
  for (const auto& transition : owned_transitions_) ComputeTransition(*transition);
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

  Layout();
  complete_.store(true, std::memory_order_release);
}

void Definition::Layout() {
  std::size_t size = 0;
  std::size_t align = 1;
  activity_runs_at_ = Reserve<std::atomic<bool>>(size, align, basic_states_.size());
  active_child_at_ = Reserve<std::atomic<State*>>(size, align, or_states_.size());
  running_at_ = Reserve<std::atomic<int>>(size, align, regions_.size());
  launches_at_ = Reserve<std::atomic<std::uint32_t>>(size, align, basic_states_.size());
  relaunches_at_ = Reserve<std::uint32_t>(size, align, basic_states_.size());
  boards_at_ = Reserve<kse::messaging::Blackboard>(size, align, regions_.size() - 1);
  given_parts_ = false;
  for (BasicState* basic : basic_states_) {
    basic->activity_at_ = static_cast<std::uint32_t>(ReservePart(basic->activity_, size, align));
    given_parts_ = given_parts_ || basic->activity_.IsGiven();
  }
  for (const auto& transition : owned_transitions_) {
    transition->condition_at_ = ReservePart(transition->condition_, size, align);
    transition->action_at_ = ReservePart(transition->action_, size, align);
    given_parts_ = given_parts_ || transition->condition_.IsGiven() || transition->action_.IsGiven();
  }
  block_size_ = std::max<std::size_t>(size, 1);
  block_align_ = align;
}

}  // namespace statechart_engine
