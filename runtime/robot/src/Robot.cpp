#include <kse/robot/Robot.h>

#include <stdexcept>
#include <utility>

#include <kse/messages/all.h>

namespace kse::robot {

using messaging::Kind;

Robot::Robot(const std::string& behaviour, const messaging::Clock& clock, statechart_engine::Reporter reporter)
	: behaviour_(behaviour), hub_(clock), motion_(hub_, "motion") {
	motion_.Subscribe("motion");
	statechart_engine::Options options;
	options.inline_activities = true;
	options.reporter = std::move(reporter);
	statechart_ = statechart_engine::StatechartFactory::Instance().Create(behaviour, hub_, options);
	if (!statechart_) {
		throw std::invalid_argument("no statechart registered as '" + behaviour + "'");
	}
	statechart_->Chart().Activate();
}

MotionCommands Robot::Step(const Perception& perception) {
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
	hub_.Publish("worldstate", Kind::State, game);

	auto world = std::make_shared<WorldInfo>();
	auto* me = world->mutable_myposition();
	me->set_x(perception.estimate.x);
	me->set_y(perception.estimate.y);
	me->set_phi(perception.estimate.theta);
	me->set_confidence(perception.confidence);
	if (perception.ball.seen) {
		auto* ball = world->add_balls();
		ball->set_relativex(perception.ball.x);
		ball->set_relativey(perception.ball.y);
		ball->set_relativexspeed(perception.ball.vx);
		ball->set_relativeyspeed(perception.ball.vy);
	}
	hub_.Publish("worldstate", Kind::Data, world);

	auto head = std::make_shared<HeadToBMessage>();
	head->set_ballfound(perception.ball.seen ? 1 : 0);
	head->set_calibrated(1);
	hub_.Publish("behavior", Kind::State, head);

	auto position = std::make_shared<PositionMessage>();
	position->set_posx(perception.ready_position.x);
	position->set_posy(perception.ready_position.y);
	position->set_theta(perception.ready_position.theta);
	hub_.Publish("behavior", Kind::State, position);

	statechart_->Chart().RunUntilStable();

	motion_.ProcessMessages();
	MotionCommands commands;
	while (auto walk = motion_.ReadSignal<MotionWalkMessage>("motion")) {
		if (walk->command() == "setWalkTargetVelocity" && walk->parameter_size() >= 3) {
			commands.walk = true;
			commands.walk_to = false;
			commands.vx = walk->parameter(0);
			commands.vy = walk->parameter(1);
			commands.vtheta = walk->parameter(2);
		} else if (walk->command() == "walkTo" && walk->parameter_size() >= 3) {
			commands.walk_to = true;
			commands.walk = false;
			commands.to_x = walk->parameter(0);
			commands.to_y = walk->parameter(1);
			commands.to_theta = walk->parameter(2);
		}
	}
	while (auto head_command = motion_.ReadSignal<MotionHeadMessage>("motion")) {
		if (head_command->command() == "setHead" && head_command->parameter_size() >= 2) {
			commands.head = true;
			commands.yaw = head_command->parameter(0);
			commands.pitch = head_command->parameter(1);
		}
	}
	while (auto action = motion_.ReadSignal<MotionActionMessage>("motion")) {
		commands.actions.push_back(action->command());
	}
	return commands;
}

}  // namespace kse::robot
