#include <kse/sim/Referee.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <kse/sim/GameControlData.h>

namespace kse::sim {

namespace {
constexpr double kOutOfFieldMargin = 0.15;  // a robot this far beyond the lines has left the field
constexpr double kInPlace = 0.3;            // m from its kick-off pose counts as in place
// sums of 10 ms ticks fall a hair short of round durations
bool Reached(double elapsed, double duration) { return elapsed >= duration - 1e-6; }
// what Follow says once about a GameController's packets
enum NoticeKind : unsigned {
	kNoticeOtherGame, kNoticeHomeMissing, kNoticeAwayMissing, kNoticeState, kNoticePenalty, kNoticeSecsRemaining,
	kNoticeSecondaryTime, kNoticeSetPlay, kNoticeGamePhase, kNoticeFirstHalf
};
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
	body.Place(shoot_out_ ? PenaltyShotPose(body.team) : ReturnPose(world, index));
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
	in_state_ += dt;
	if (listening_) return Listen(dt);
	std::vector<RefereeEvent> events;
	if (state_ == GameState::Ready || state_ == GameState::Set || state_ == GameState::Playing) {
		for (std::size_t i = 0; i < penalised_.size();) {
			auto& entry = penalised_[i];
			entry.remaining -= dt;
			if (Reached(0, entry.remaining)) {
				Unpenalise(world, entry.body, events);  // erases the entry
			} else {
				++i;
			}
		}
	}
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

std::vector<RefereeEvent> Referee::Listen(double dt) {
	std::vector<RefereeEvent> events;
	since_packet_ += dt;
	if (final_finished_) finished_seconds_ += dt;
	if (!silence_reported_ && Reached(since_packet_, config_.silence_seconds)) {
		silence_reported_ = true;
		std::ostringstream text;
		if (following_) {
			text << "no packet from the GameController for " << config_.silence_seconds << " s: the robots keep " << ToString(state_);
		} else {
			text << "no packet from a GameController in " << config_.silence_seconds << " s: is one running and sending to this machine?";
		}
		events.push_back({RefereeEvent::Type::Notice, -1, -1, text.str()});
	}
	return events;
}

void Referee::NoticeOnce(unsigned kind, int team, int body, std::string detail, std::vector<RefereeEvent>& events) {
	const std::uint32_t bit = 1u << kind;
	if (noticed_ & bit) return;
	noticed_ |= bit;
	events.push_back({RefereeEvent::Type::Notice, team, body, std::move(detail)});
}

double Referee::Bounded(const char* field, int value, unsigned kind, std::vector<RefereeEvent>& events) {
	const double bounded = Clamp(value, 0, kLongestTime);
	if (bounded != value) {
		NoticeOnce(kind, -1, -1,
		           std::string(field) + " " + std::to_string(value) + " is outside 0 to " + std::to_string(static_cast<int>(kLongestTime)) +
		               " s: the robots are told " + std::to_string(static_cast<int>(bounded)),
		           events);
	}
	return bounded;
}

bool Referee::GameOver() const {
	if (!listening_) return state_ == GameState::Finished;
	const double wait = shoot_out_may_follow_ ? config_.shoot_out_wait_seconds : config_.game_over_seconds;
	return final_finished_ && finished_packets_ >= 2 && Reached(finished_seconds_, wait);
}

Pose2 Referee::PenaltyShotPose(int body_team) const {
	const int end = kicking_team_ >= 0 ? Side(kicking_team_) : 1;  // of the goal the shot is taken on
	if (body_team == kicking_team_) return {end * (field::kHalfLength - field::kPenaltyMarkDistance - 1.0), 0, end > 0 ? 0 : kPi};
	return {end * field::kHalfLength, 0, end > 0 ? kPi : 0};
}

void Referee::PlaceForPenaltyShot(World& world, std::vector<RefereeEvent>& events) {
	const int end = kicking_team_ >= 0 ? Side(kicking_team_) : 1;
	world.ball = Ball{};
	world.ball.position = {end * (field::kHalfLength - field::kPenaltyMarkDistance), 0};
	world.SetLastTouch(-1);
	for (std::size_t i = 0; i < world.bodies.size(); ++i) {
		Body& body = world.bodies[i];
		if (!body.on_field) continue;
		body.Place(PenaltyShotPose(body.team));
		events.push_back({RefereeEvent::Type::Placed, body.team, static_cast<int>(i), "penalty shot position"});
	}
}

std::vector<RefereeEvent> Referee::Follow(const gc::GameControlData& packet, const std::array<int, 2>& team_numbers, World& world,
                                          const std::vector<Pose2>& ready_poses) {
	std::vector<RefereeEvent> events;
	listening_ = true;
	since_packet_ = 0;
	silence_reported_ = false;
	const gc::TeamInfo* teams[2] = {gc::FindTeam(packet, static_cast<std::uint8_t>(team_numbers[0])),
	                                gc::FindTeam(packet, static_cast<std::uint8_t>(team_numbers[1]))};
	const std::string theirs =
	    "teams " + std::to_string(packet.teams[0].teamNumber) + " and " + std::to_string(packet.teams[1].teamNumber);
	if (!teams[0] && !teams[1]) {
		NoticeOnce(kNoticeOtherGame, -1, -1,
		           "the GameController's packets are for " + theirs + ", not for ours (home " + std::to_string(team_numbers[0]) + ", away " +
		               std::to_string(team_numbers[1]) + "): the robots wait until packets name them (kse-match --home-number, --away-number)",
		           events);
		return events;
	}
	for (int t = 0; t < 2; ++t) {
		if (teams[t]) continue;
		const gc::TeamInfo& other = teams[1 - t] == &packet.teams[0] ? packet.teams[1] : packet.teams[0];
		const std::string side = t == 0 ? "home" : "away";
		std::string detail = "team " + std::to_string(team_numbers[static_cast<std::size_t>(t)]) + " (" + side +
		                     ") is not in the GameController's packets (" + theirs + "): its robots follow the game but get no score or penalties";
		if (other.teamNumber != team_numbers[static_cast<std::size_t>(1 - t)]) {
			detail += " (kse-match --" + side + "-number " + std::to_string(other.teamNumber) + " names it)";
		}
		NoticeOnce(kNoticeHomeMissing + static_cast<unsigned>(t), t, -1, detail, events);
	}
	following_ = true;

	if (packet.firstHalf > 1) {
		NoticeOnce(kNoticeFirstHalf, -1, -1, "firstHalf " + std::to_string(packet.firstHalf) + " is neither 0 nor 1: taken as 1", events);
	}
	std::uint8_t phase = packet.gamePhase;
	if (phase > gc::kGamePhaseTimeout) {
		NoticeOnce(kNoticeGamePhase, -1, -1, "gamePhase " + std::to_string(phase) + " is not a GameController game phase: taken as normal", events);
		phase = gc::kGamePhaseNormal;
	}
	const int half = packet.firstHalf ? 1 : 2;
	const bool shoot_out = phase == gc::kGamePhasePenaltyShoot;
	if (half == 2 && half_ == 1 && !shoot_out) events.push_back({RefereeEvent::Type::HalfTime, -1, -1, "teams change ends"});
	half_ = half;
	if (shoot_out && !shoot_out_) events.push_back({RefereeEvent::Type::PenaltyShootOut, -1, -1, "penalty shoot-out"});
	shoot_out_ = shoot_out;
	// GameController3 lets its clocks run below zero; robots are told a time they can count down
	secs_remaining_ = Bounded("secsRemaining", packet.secsRemaining, kNoticeSecsRemaining, events);
	secondary_time_ = Bounded("secondaryTime", packet.secondaryTime, kNoticeSecondaryTime, events);
	if (packet.setPlay > gc::kSetPlayPenaltyKick) {
		NoticeOnce(kNoticeSetPlay, -1, -1, "setPlay " + std::to_string(packet.setPlay) + " is not a GameController set play: taken as none", events);
	}
	set_play_ = packet.setPlay <= gc::kSetPlayPenaltyKick ? static_cast<SetPlay>(packet.setPlay) : SetPlay::None;
	// 255 (or another team's number) means that neither of our teams kicks off
	kicking_team_ = packet.kickingTeam == team_numbers[0] ? 0 : packet.kickingTeam == team_numbers[1] ? 1 : -1;
	for (std::size_t t = 0; t < 2; ++t) {
		if (teams[t]) score_[t] = teams[t]->score;
	}

	GameState next = state_;
	if (packet.state <= gc::kStateStandby) {
		next = static_cast<GameState>(packet.state);
	} else {
		NoticeOnce(kNoticeState, -1, -1,
		           "state " + std::to_string(packet.state) + " is not a GameController state: the robots keep " + ToString(state_), events);
	}
	if (next != state_) {
		if (next == GameState::Set && shoot_out_) PlaceForPenaltyShot(world, events);
		if (next == GameState::Set && !shoot_out_) PlaceForKickOff(world, ready_poses, true, events);
		Enter(next, events);
	}

	for (std::size_t i = 0; i < world.bodies.size(); ++i) {
		const Body& body = world.bodies[i];
		const gc::TeamInfo* team = teams[body.team];
		if (!team || body.number < 1 || body.number > static_cast<int>(team->players.size())) continue;
		const auto& player = team->players[static_cast<std::size_t>(body.number - 1)];
		const int index = static_cast<int>(i);
		int type = player.penalty;
		if (type != penalty::kNone && !gc::IsPenalty(player.penalty)) {
			NoticeOnce(kNoticePenalty, body.team, index,
			           "penalty " + std::to_string(type) + " is not a GameController penalty: taken as " + std::to_string(penalty::kManual) + " (manual)",
			           events);
			type = penalty::kManual;
		}
		const auto entry = std::find_if(penalised_.begin(), penalised_.end(), [index](const Penalised& p) { return p.body == index; });
		if (type != penalty::kNone && entry == penalised_.end()) {
			Penalise(world, index, type, player.secsTillUnpenalised, events);
		} else if (type != penalty::kNone) {
			entry->type = type;  // GameController3 may turn one penalty into another (a substitute picked up)
			entry->remaining = player.secsTillUnpenalised;
		} else if (entry != penalised_.end()) {
			Unpenalise(world, index, events);
		}
	}

	// the end of the game is a state held, never one packet (GameOver)
	const bool final_finished = packet.state == gc::kStateFinished && half_ == 2;
	if (final_finished && !final_finished_) finished_seconds_ = 0;
	finished_packets_ = final_finished ? finished_packets_ + 1 : 0;
	final_finished_ = final_finished;
	// GameController3 offers a shoot-out after a drawn second half, and another shot after each one
	shoot_out_may_follow_ = shoot_out_ || packet.teams[0].score == packet.teams[1].score;
	return events;
}

}  // namespace kse::sim
