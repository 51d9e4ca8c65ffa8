#include <kse/sim/Referee.h>

#include <algorithm>
#include <cmath>

#include <kse/sim/GameControlData.h>

namespace kse::sim {

namespace {
constexpr double kOutOfFieldMargin = 0.15;  // a robot this far beyond the lines has left the field
constexpr double kInPlace = 0.3;            // m from its kick-off pose counts as in place
// sums of 10 ms ticks fall a hair short of round durations
bool Reached(double elapsed, double duration) { return elapsed >= duration - 1e-6; }
}  // namespace

const char* ToString(GameState state) {
	switch (state) {
		case GameState::Initial: return "INITIAL";
		case GameState::Ready: return "READY";
		case GameState::Set: return "SET";
		case GameState::Playing: return "PLAYING";
		case GameState::Finished: return "FINISHED";
		case GameState::Standby: return "STANDBY";
	}
	return "?";
}

const Referee::Penalised& Referee::Find(int body) const {
	static const Penalised none;
	for (const auto& entry : penalised_) {
		if (entry.body == body) return entry;
	}
	return none;
}

void Referee::Enter(GameState state, std::vector<RefereeEvent>& events) {
	state_ = state;
	in_state_ = 0;
	events.push_back({RefereeEvent::Type::State, -1, -1, ToString(state)});
}

Pose2 Referee::ReturnPose(const World& world, int body) const {
	const Body& robot = world.bodies[static_cast<std::size_t>(body)];
	const int side = Side(robot.team);
	// on the penalty-mark line of its own half, on the sideline away from the ball
	const double x = -side * (field::kHalfLength - field::kPenaltyMarkDistance);
	const double y = world.ball.position.y >= 0 ? -field::kHalfWidth : field::kHalfWidth;
	return {x, y, y > 0 ? -kPi / 2 : kPi / 2};
}

void Referee::PlaceForKickOff(World& world, const std::vector<Pose2>& ready_poses, bool only_illegal,
                              std::vector<RefereeEvent>& events) {
	world.ball = Ball{};
	world.SetLastTouch(-1);
	for (std::size_t i = 0; i < world.bodies.size(); ++i) {
		Body& body = world.bodies[i];
		if (!body.on_field) continue;
		const int side = Side(body.team);
		const Vec2 p = body.pose.Position();
		const bool in_opponent_half = side * p.x > 0.05;
		const bool in_circle = body.team != kicking_team_ && p.Norm() < field::kCentreCircleRadius;
		const bool outside = !field::InsideField(p);
		if (only_illegal && !in_opponent_half && !in_circle && !outside) continue;
		body.Place(ready_poses[i]);
		events.push_back({RefereeEvent::Type::Placed, body.team, static_cast<int>(i), "kick-off position"});
	}
}

void Referee::Penalise(World& world, int index, int type, double seconds, std::vector<RefereeEvent>& events) {
	Body& body = world.bodies[static_cast<std::size_t>(index)];
	body.on_field = false;
	body.Place({body.pose.x, std::copysign(field::kHalfWidth + 0.6, body.pose.y), body.pose.theta});
	penalised_.push_back({index, type, seconds});
	events.push_back({RefereeEvent::Type::Penalty, body.team, index,
	                  type == penalty::kLeavingTheField ? "leaving the field" : type == penalty::kPlayerPushing ? "pushing" : "penalised"});
}

void Referee::Unpenalise(World& world, int index, std::vector<RefereeEvent>& events) {
	Body& body = world.bodies[static_cast<std::size_t>(index)];
	body.on_field = true;
	body.Place(ReturnPose(world, index));
	penalised_.erase(std::remove_if(penalised_.begin(), penalised_.end(), [index](const Penalised& p) { return p.body == index; }),
	                 penalised_.end());
	events.push_back({RefereeEvent::Type::Unpenalised, body.team, index, "back on the field"});
}

void Referee::BallOut(World& world, std::vector<RefereeEvent>& events) {
	Ball& ball = world.ball;
	const int touched_by = world.LastTouch() >= 0 ? world.bodies[static_cast<std::size_t>(world.LastTouch())].team : -1;
	std::string what;
	if (std::fabs(ball.position.y) > field::kHalfWidth + field::kLineWidth / 2 + field::kBallRadius) {
		ball.position = {Clamp(ball.position.x, -field::kHalfLength, field::kHalfLength), std::copysign(field::kHalfWidth, ball.position.y)};
		set_play_ = SetPlay::KickIn;
		what = "kick-in";
	} else {
		const int end = ball.position.x > 0 ? 1 : -1;
		const bool defenders_touched = touched_by >= 0 && Side(touched_by) != end;
		if (defenders_touched) {
			ball.position = {end * field::kHalfLength, std::copysign(field::kHalfWidth, ball.position.y)};
			set_play_ = SetPlay::CornerKick;
			what = "corner kick";
		} else {
			ball.position = {end * (field::kHalfLength - field::kGoalAreaLength), std::copysign(field::kGoalAreaWidth / 2, ball.position.y)};
			set_play_ = SetPlay::GoalKick;
			what = "goal kick";
		}
	}
	ball.velocity = {};
	secondary_time_ = 30;
	world.SetLastTouch(-1);
	events.push_back({RefereeEvent::Type::BallOut, touched_by >= 0 ? 1 - touched_by : -1, -1, what});
}

std::vector<RefereeEvent> Referee::StartPlaying(World& world, const std::vector<Pose2>& ready_poses) {
	std::vector<RefereeEvent> events;
	PlaceForKickOff(world, ready_poses, false, events);
	if (first_half_kicking_team_ < 0) first_half_kicking_team_ = kicking_team_;
	Enter(GameState::Playing, events);
	return events;
}

std::vector<RefereeEvent> Referee::Step(double dt, World& world, const std::vector<Pose2>& ready_poses) {
	std::vector<RefereeEvent> events;
	in_state_ += dt;
	if (state_ == GameState::Ready || state_ == GameState::Set || state_ == GameState::Playing) {
		for (std::size_t i = 0; i < penalised_.size();) {
			auto& entry = penalised_[i];
			if (!following_) entry.remaining -= dt;
			if (!following_ && Reached(0, entry.remaining)) {
				Unpenalise(world, entry.body, events);  // erases the entry
			} else {
				++i;
			}
		}
	}
	if (following_) return events;

	switch (state_) {
		case GameState::Initial:
			if (Reached(in_state_, config_.initial_seconds)) Enter(GameState::Ready, events);
			break;
		case GameState::Ready: {
			secondary_time_ = std::max(0.0, config_.ready_seconds - in_state_);
			bool all_in_place = config_.end_ready_early && in_state_ >= 3.0;
			for (std::size_t i = 0; all_in_place && i < world.bodies.size(); ++i) {
				const Body& body = world.bodies[i];
				if (!body.on_field) continue;
				all_in_place = (body.pose.Position() - ready_poses[i].Position()).Norm() < kInPlace && body.motion == Motion::Stand;
			}
			if (Reached(in_state_, config_.ready_seconds) || all_in_place) {
				PlaceForKickOff(world, ready_poses, true, events);
				Enter(GameState::Set, events);
			}
			break;
		}
		case GameState::Set:
			secondary_time_ = 0;
			if (Reached(in_state_, config_.set_seconds)) {
				if (first_half_kicking_team_ < 0) first_half_kicking_team_ = kicking_team_;
				untouched_ = 0;
				set_play_ = SetPlay::None;
				Enter(GameState::Playing, events);
			}
			break;
		case GameState::Playing: {
			secs_remaining_ -= dt;
			secondary_time_ = std::max(0.0, secondary_time_ - dt);
			if (secondary_time_ <= 0) set_play_ = SetPlay::None;
			const bool touched = std::any_of(world.Events().begin(), world.Events().end(), [](const PhysicsEvent& event) {
				return event.type == PhysicsEvent::Type::Touch || event.type == PhysicsEvent::Type::Kick;
			});
			untouched_ = touched ? 0 : untouched_ + dt;
			for (int end : {1, -1}) {
				if (!field::InGoal(world.ball.position, end)) continue;
				const int scorer = Side(0) == end ? 0 : 1;
				++score_[static_cast<std::size_t>(scorer)];
				events.push_back({RefereeEvent::Type::Goal, scorer, world.LastTouch(), std::to_string(score_[0]) + ":" + std::to_string(score_[1])});
				kicking_team_ = 1 - scorer;
				Enter(GameState::Ready, events);
				return events;
			}
			if (field::BallOut(world.ball.position)) BallOut(world, events);
			for (std::size_t i = 0; i < world.bodies.size(); ++i) {
				const Body& body = world.bodies[i];
				if (!body.on_field) continue;
				if (!field::InsideField(body.pose.Position(), kOutOfFieldMargin)) {
					Penalise(world, static_cast<int>(i), penalty::kLeavingTheField, config_.penalty_seconds, events);
				} else if (Reached(body.pushing_time, config_.pushing_seconds)) {
					Penalise(world, static_cast<int>(i), penalty::kPlayerPushing, config_.penalty_seconds, events);
				}
			}
			if (config_.game_stuck_seconds > 0 && Reached(untouched_, config_.game_stuck_seconds)) {
				events.push_back({RefereeEvent::Type::GameStuck, -1, -1, "nobody touched the ball"});
				kicking_team_ = 1 - kicking_team_;
				untouched_ = 0;
				Enter(GameState::Ready, events);
				return events;
			}
			if (Reached(0, secs_remaining_)) {
				secs_remaining_ = 0;
				if (half_ < config_.halves) {
					++half_;
					secs_remaining_ = config_.half_seconds;
					kicking_team_ = 1 - first_half_kicking_team_;
					events.push_back({RefereeEvent::Type::HalfTime, -1, -1, "teams change ends"});
					Enter(GameState::Initial, events);
				} else {
					Enter(GameState::Finished, events);
				}
			}
			break;
		}
		case GameState::Finished:
		case GameState::Standby:
			break;
	}
	return events;
}

std::vector<RefereeEvent> Referee::Follow(const gc::GameControlData& packet, const std::array<int, 2>& team_numbers, World& world,
                                          const std::vector<Pose2>& ready_poses) {
	std::vector<RefereeEvent> events;
	const gc::TeamInfo* teams[2] = {gc::FindTeam(packet, static_cast<std::uint8_t>(team_numbers[0])),
	                                gc::FindTeam(packet, static_cast<std::uint8_t>(team_numbers[1]))};
	if (!teams[0] && !teams[1]) return events;  // a packet for another game
	following_ = true;
	half_ = packet.firstHalf ? 1 : 2;
	secs_remaining_ = packet.secsRemaining;
	secondary_time_ = packet.secondaryTime;
	set_play_ = packet.setPlay <= 5 ? static_cast<SetPlay>(packet.setPlay) : SetPlay::None;
	// 255 (or another team's number) means that neither of our teams kicks off
	kicking_team_ = packet.kickingTeam == team_numbers[0] ? 0 : packet.kickingTeam == team_numbers[1] ? 1 : -1;
	for (std::size_t t = 0; t < 2; ++t) {
		if (teams[t]) score_[t] = teams[t]->score;
	}
	const auto next = packet.state <= 5 ? static_cast<GameState>(packet.state) : state_;
	if (next != state_) {
		if (next == GameState::Set) PlaceForKickOff(world, ready_poses, true, events);
		Enter(next, events);
	}
	for (std::size_t i = 0; i < world.bodies.size(); ++i) {
		const Body& body = world.bodies[i];
		const gc::TeamInfo* team = teams[body.team];
		if (!team || body.number < 1 || body.number > static_cast<int>(team->players.size())) continue;
		const auto& player = team->players[static_cast<std::size_t>(body.number - 1)];
		const int index = static_cast<int>(i);
		const bool penalised = Find(index).body == index;
		if (player.penalty != penalty::kNone && !penalised) {
			Penalise(world, index, player.penalty, player.secsTillUnpenalised, events);
		} else if (player.penalty == penalty::kNone && penalised) {
			Unpenalise(world, index, events);
		}
	}
	return events;
}

}  // namespace kse::sim
