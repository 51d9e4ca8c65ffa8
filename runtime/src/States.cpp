#include "statechart_engine/States.h"

#include <utility>

namespace statechart_engine {

const char* ToString(StateKind kind) noexcept {
  switch (kind) {
    case StateKind::Or:
      return "OR";
    case StateKind::And:
      return "AND";
    case StateKind::Basic:
      return "BASIC";
    case StateKind::Start:
      return "START";
    case StateKind::End:
      return "END";
    case StateKind::Condition:
      return "CONDITION";
  }
  return "?";
}

State::State(std::string name, State* parent, StateKind kind)
    : parent_(parent),
      kind_(kind),
      depth_(parent != nullptr ? parent->depth_ + 1 : 0),
      name_(std::move(name)) {
  if (parent_ != nullptr) {
    parent_->children_.push_back(this);
  }
}

State::~State() = default;

void State::OnEntry() {}
void State::OnExit() {}

OrState::OrState(std::string name, State* parent) : State(std::move(name), parent, StateKind::Or) {}
OrState::~OrState() = default;

bool OrState::IsRegion() const noexcept {
  return Parent() != nullptr && Parent()->Kind() == StateKind::And;
}

AndState::AndState(std::string name, State* parent)
    : State(std::move(name), parent, StateKind::And) {}
AndState::~AndState() = default;

BasicState::BasicState(std::string name, State* parent, Part<IActivity> activity)
    : State(std::move(name), parent, StateKind::Basic), activity_(std::move(activity)) {}
BasicState::~BasicState() = default;

StartState::StartState(std::string name, State* parent)
    : State(std::move(name), parent, StateKind::Start) {}
StartState::~StartState() = default;

EndState::EndState(std::string name, State* parent) : State(std::move(name), parent, StateKind::End) {}
EndState::~EndState() = default;

ConditionConnector::ConditionConnector(std::string name, State* parent)
    : State(std::move(name), parent, StateKind::Condition) {}
ConditionConnector::~ConditionConnector() = default;

}  // namespace statechart_engine
