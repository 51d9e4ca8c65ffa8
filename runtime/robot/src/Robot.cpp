#include <kse/robot/Robot.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <kse/messages/all.h>
#include <kse/messaging/Recycled.h>

namespace kse::robot {

using messaging::Kind;

struct Robot::Recycling {
	// A Data history keeps the last 100 WorldInfo messages (and the inbox one more).
	messaging::Recycled<WorldInfo> world{messaging::Blackboard::kDataHistoryLimit + 8};
	Perception last;  // what the last State messages said
	bool published_once = false;
	// the motion commands, read every cycle: their keys looked up once
	messaging::Reader<MotionWalkMessage> walk;
	messaging::Reader<MotionHeadMessage> head;
	messaging::Reader<MotionActionMessage> action;
};

Robot::Robot(const std::string& behaviour, const messaging::Clock& clock, statechart_engine::Reporter reporter)
	: behaviour_(behaviour), hub_(clock), motion_(hub_, "motion"), recycling_(std::make_unique<Recycling>()) {
	motion_.Subscribe("motion");
	recycling_->walk.Bind(motion_, "motion");
	recycling_->head.Bind(motion_, "motion");
	recycling_->action.Bind(motion_, "motion");
	statechart_engine::Options options;
	options.inline_activities = true;
	options.inline_activities_last_until_next_run = true;
	options.reporter = std::move(reporter);
	statechart_ = statechart_engine::StatechartFactory::Instance().Create(behaviour, hub_, options);
	if (!statechart_) {
		throw std::invalid_argument("no statechart registered as '" + behaviour + "'");
	}
	statechart_->Chart().Activate();
}

Robot::~Robot() = default;

namespace {

bool SameGame(const Perception& a, const Perception& b) {
	return a.player_state == b.player_state && a.game_state == b.game_state && a.team_number == b.team_number &&
	       a.team_color == b.team_color && a.player_number == b.player_number && a.kickoff == b.kickoff &&
	       a.our_score == b.our_score && a.their_score == b.their_score && a.secs_remaining == b.secs_remaining;
}

bool SamePose(const Pose& a, const Pose& b) { return a.x == b.x && a.y == b.y && a.theta == b.theta; }

// What a failed robot commands: a walk at zero speed.
MotionCommands StandStill() {
	MotionCommands stand;
	stand.walk = true;
	return stand;
}

// The topics and commands, made once (a publish takes the topic as a std::string).
const std::string kWorldstateTopic = "worldstate";
const std::string kBehaviorTopic = "behavior";
const std::string kWalkVelocityCommand = "setWalkTargetVelocity";
const std::string kWalkToCommand = "walkTo";
const std::string kHeadCommand = "setHead";

// Writes the perception into a WorldInfo, new or one published before: the same message
// WorldInfo::Clear() and the setters would make (every field the robot ever sets is set again or
// cleared; it never sets the others), without clearing what is written again anyway.
void Fill(WorldInfo& world, const Perception& perception) {
	auto* me = world.mutable_myposition();
	me->set_x(perception.estimate.x);
	me->set_y(perception.estimate.y);
	me->set_phi(perception.estimate.theta);
	me->set_confidence(perception.confidence);
	if (perception.ball.seen) {
		auto* ball = world.balls_size() > 0 ? world.mutable_balls(0) : world.add_balls();
		ball->set_relativex(perception.ball.x);
		ball->set_relativey(perception.ball.y);
		ball->set_relativexspeed(perception.ball.vx);
		ball->set_relativeyspeed(perception.ball.vy);
	} else if (world.balls_size() > 0) {
		world.mutable_balls()->Clear();
	}
}

}  // namespace

MotionCommands Robot::Step(const Perception& perception) {
	if (Failed()) return StandStill();
	// A State message stands until the next one: one equal to the last would change nothing a
	// reader sees, so it is published only when it differs (most cycles, none does).
	const Perception* last = recycling_->published_once ? &recycling_->last : nullptr;
	if (!last || !SameGame(perception, *last)) {
		auto game = std::make_shared<GameStateMessage>();
		game->set_player_state(perception.player_state);
		game->set_game_state(perception.game_state);
		game->set_team_number(perception.team_number);
		game->set_team_color(perception.team_color);
		game->set_player_number(perception.player_number);
		game->set_kickoff(perception.kickoff);
		game->set_our_score(perception.our_score);
		game->set_otherteam_score(perception.their_score);
		game->set_secs_remaining(perception.secs_remaining);
		hub_.Publish(kWorldstateTopic, Kind::State, std::shared_ptr<const GameStateMessage>(std::move(game)));
	}

	Fill(recycling_->world.Next(), perception);
	hub_.Publish(kWorldstateTopic, Kind::Data, std::shared_ptr<const WorldInfo>(recycling_->world.Last()));

	if (!last || perception.ball.seen != last->ball.seen) {
		auto head = std::make_shared<HeadToBMessage>();
		head->set_ballfound(perception.ball.seen ? 1 : 0);
		head->set_calibrated(1);
		hub_.Publish(kBehaviorTopic, Kind::State, std::shared_ptr<const HeadToBMessage>(std::move(head)));
	}

	if (!last || !SamePose(perception.ready_position, last->ready_position)) {
		auto position = std::make_shared<PositionMessage>();
		position->set_posx(perception.ready_position.x);
		position->set_posy(perception.ready_position.y);
		position->set_theta(perception.ready_position.theta);
		hub_.Publish(kBehaviorTopic, Kind::State, std::shared_ptr<const PositionMessage>(std::move(position)));
	}
	recycling_->last = perception;
	recycling_->published_once = true;

	auto& chart = statechart_->Chart();
	if (!chart.RunUntilStable(kTransitionsPerCycle)) {
		const std::string loop = chart.UnsettledLoop();
		failure_ = "the statechart took " + std::to_string(kTransitionsPerCycle) + " transitions in one decision cycle" +
		           (loop.empty() ? std::string() : ", round " + loop) + ", without waiting for an activity or a timer";
		return StandStill();
	}

	MotionCommands commands;
	// This robot reads every motion command of each cycle: with nothing new there is nothing to read.
	if (motion_.PendingMessages() == 0) return commands;
	motion_.ProcessMessages();
	while (auto walk = recycling_->walk.ReadSignal()) {
		if (walk->command() == kWalkVelocityCommand && walk->parameter_size() >= 3) {
			commands.walk = true;
			commands.walk_to = false;
			commands.vx = walk->parameter(0);
			commands.vy = walk->parameter(1);
			commands.vtheta = walk->parameter(2);
		} else if (walk->command() == kWalkToCommand && walk->parameter_size() >= 3) {
			commands.walk_to = true;
			commands.walk = false;
			commands.to_x = walk->parameter(0);
			commands.to_y = walk->parameter(1);
			commands.to_theta = walk->parameter(2);
		}
	}
	while (auto head_command = recycling_->head.ReadSignal()) {
		if (head_command->command() == kHeadCommand && head_command->parameter_size() >= 2) {
			commands.head = true;
			commands.yaw = head_command->parameter(0);
			commands.pitch = head_command->parameter(1);
		}
	}
	while (auto action = recycling_->action.ReadSignal()) {
		commands.actions.push_back(action->command());
	}
	return commands;
}

}  // namespace kse::robot
