#include <kse/sim/Match.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include <kse/behavior/BehaviorConst.h>
#include <kse/sim/GameControlData.h>
#include <kse/sim/GameControllerLink.h>

namespace kse::sim {

namespace {

/** The highest-numbered field player takes the kick-off; a lone goalkeeper stays in goal. */
int KickOffTaker(const TeamConfig& team) {
	int taker = 0;
	for (const auto& player : team.players) {
		if (player.number > 1) taker = std::max(taker, player.number);
	}
	return taker;
}

const char* EventName(RefereeEvent::Type type) {
	switch (type) {
		case RefereeEvent::Type::State: return "state";
		case RefereeEvent::Type::Goal: return "goal";
		case RefereeEvent::Type::BallOut: return "ball-out";
		case RefereeEvent::Type::Penalty: return "penalty";
		case RefereeEvent::Type::Unpenalised: return "unpenalised";
		case RefereeEvent::Type::Placed: return "placed";
		case RefereeEvent::Type::HalfTime: return "half-time";
		case RefereeEvent::Type::GameStuck: return "game-stuck";
		case RefereeEvent::Type::PenaltyShootOut: return "penalty-shoot-out";
		case RefereeEvent::Type::Notice: return "gamecontroller";
	}
	return "?";
}

// The robot whose behaviour runs now, for a crash handler: an atomic pointer it may read.
std::atomic<const char*> thinking_robot{nullptr};

}  // namespace

const char* Match::ThinkingRobot() noexcept { return thinking_robot.load(std::memory_order_relaxed); }

Pose2 DefaultReadyPose(int number, bool takes_kick_off) {
	if (takes_kick_off) return {-0.5, 0, 0};
	switch (number) {
		case 1: return {-4.35, 0, 0};  // on the goal line, as goalkeepers stand
		case 2: return {-3.0, -1.0, 0};
		case 3: return {-3.0, 1.0, 0};
		case 4: return {-1.6, 1.5, 0};
		case 5: return {-1.6, -1.5, 0};
		case 6: return {-2.2, 0, 0};
		default: return {-1.0, number % 2 == 0 ? 2.2 : -2.2, 0};
	}
}

Match::Match(MatchConfig config)
	: config_(std::move(config)), random_(config_.seed), world_(random_.Fork()), referee_(config_.referee, config_.kicking_team) {
	for (int team = 0; team < 2; ++team) {
		const TeamConfig& team_config = Team(team);
		int slot = 0;
		for (const auto& player_config : team_config.players) {
			auto player = std::make_unique<Player>(player_config, std::string(team == 0 ? "home-" : "away-") + std::to_string(player_config.number),
			                                       random_.Fork());
			player->label = player->id + " " + player_config.behaviour;
			if (!player_config.controller) {
				player->robot = std::make_unique<robot::Robot>(player_config.behaviour, clock_, reports_.For(player->id, player_config.behaviour));
				Player* raw = player.get();
				const std::size_t index = players_.size();
				player->robot->Chart().SetObserver([this, raw, index](const statechart_engine::TransitionSegmentBase& transition) {
					raw->taken.push_back(&transition.Name());
					raw->last_transition = Time();
					for (auto* observer : observers_) observer->OnTransition(*this, index, transition);
				});
			}
			Body body;
			body.team = team;
			body.number = player_config.number;
			// robots wait at the sideline of their own half until READY
			body.pose = TeamFrame(team, {-0.6 - 0.7 * slot, -field::kHalfWidth, kPi / 2});
			player->last_position = body.pose.Position();
			world_.bodies.push_back(body);
			players_.push_back(std::move(player));
			++slot;
		}
	}
	camera_random_ = random_.Fork();
}

Match::~Match() = default;

Pose2 Match::TeamFrame(int team, const Pose2& pose) const {
	if (referee_.Side(team) > 0) return pose;
	return {-pose.x, -pose.y, NormalizeAngle(pose.theta + kPi)};
}

Pose2 Match::ReadyPose(std::size_t robot) const {
	const Player& player = *players_[robot];
	const int team = world_.bodies[robot].team;
	const Pose2 pose = player.config.ready ? *player.config.ready
	                                       : DefaultReadyPose(player.config.number, team == referee_.KickingTeam() &&
	                                                                                   player.config.number == KickOffTaker(Team(team)));
	return TeamFrame(team, pose);
}

const std::vector<Pose2>& Match::ReadyPoses() const {
	// Asked every tick, changed only by a kick-off for the other team or the teams changing ends:
	// computed again (the same way) when one of those differs from the last time.
	const std::array<int, 3> key{referee_.KickingTeam(), referee_.Side(0), referee_.Side(1)};
	if (key != ready_key_ || ready_poses_.size() != players_.size()) {
		ready_poses_.clear();
		for (std::size_t i = 0; i < players_.size(); ++i) ready_poses_.push_back(ReadyPose(i));
		ready_key_ = key;
	}
	return ready_poses_;
}

std::vector<std::string> Match::ActiveStates(std::size_t robot) const {
	const auto& player = *players_[robot];
	if (!player.robot) return {};
	return player.robot->Chart().ActiveStates();
}

std::size_t Match::Failures() const {
	std::size_t failures = 0;
	for (const auto& player : players_) {
		if (!player->robot) continue;
		const auto& chart = player->robot->Chart();
		failures += chart.ActivityFailures() + chart.GuardFailures() + chart.ActionFailures();
	}
	return failures;
}

void Match::Listen(gc::GameControllerLink& link) {
	link_ = &link;
	referee_.ListenToGameController();
}

void Match::Follow(const gc::GameControlData& packet) {
	Apply(referee_.Follow(packet, {config_.home.number, config_.away.number}, world_, ReadyPoses()));
}

void Match::Emit(MatchEvent event) {
	event.time = Time();
	events_.push_back(event);
	for (auto* observer : observers_) observer->OnEvent(*this, events_.back());
}

void Match::Apply(const std::vector<RefereeEvent>& events) {
	for (const auto& event : events) {
		if (event.type == RefereeEvent::Type::HalfTime) {
			// carried to the other end during the break
			for (std::size_t i = 0; i < players_.size(); ++i) {
				if (!world_.bodies[i].on_field) continue;
				world_.bodies[i].Place(ReadyPose(i));
				players_[i]->sense.Kidnapped(0.1);
			}
		}
		if (event.body >= 0 && (event.type == RefereeEvent::Type::Unpenalised || event.type == RefereeEvent::Type::Placed)) {
			players_[static_cast<std::size_t>(event.body)]->sense.Kidnapped(event.type == RefereeEvent::Type::Placed ? 0.1 : 0.3);
		}
		Emit({0, EventName(event.type), event.team, event.body, event.detail});
	}
}

void Match::Start() {
	started_ = true;
	for (auto* observer : observers_) observer->OnStart(*this);
	if (config_.start_playing) {
		Apply(referee_.StartPlaying(world_, ReadyPoses()));
	} else {
		Emit({0, "state", -1, -1, ToString(referee_.State())});
	}
}

void Match::Think(std::size_t index) {
	Player& player = *players_[index];
	Body& body = world_.bodies[index];
	const int team = body.team;
	const bool top_camera = ((ticks_ + index) / kTicksPerFrame) % 2 == 0;
	if (body.on_field) {
		const Image image = camera::Look(world_, static_cast<int>(index), top_camera, camera_random_);
		player.sense.Update(world_, static_cast<int>(index), image, Time());
	}

	robot::Perception& p = player.perception;
	const GameState state = referee_.State();
	const bool penalised = referee_.Penalty(static_cast<int>(index)) != penalty::kNone;
	p.game_state = static_cast<int>(state);
	p.player_state = penalised ? PLAYER_PENALISED : (state == GameState::Standby ? PLAYER_INITIAL : static_cast<int>(state));
	p.team_number = Team(team).number;
	p.team_color = team;
	p.player_number = body.number;
	p.kickoff = referee_.KickingTeam() == team;
	p.our_score = referee_.Score()[static_cast<std::size_t>(team)];
	p.their_score = referee_.Score()[static_cast<std::size_t>(1 - team)];
	p.secs_remaining = static_cast<int>(std::ceil(referee_.SecsRemaining()));
	const Pose2 estimate = TeamFrame(team, player.sense.Estimate(body));
	p.estimate = {static_cast<float>(estimate.x), static_cast<float>(estimate.y), static_cast<float>(estimate.theta)};
	p.confidence = static_cast<float>(player.sense.Confidence());
	p.ball = player.sense.BallPercept(body, Time());
	const Pose2 ready = TeamFrame(team, ReadyPoses()[index]);
	p.ready_position = {static_cast<float>(ready.x), static_cast<float>(ready.y), static_cast<float>(ready.theta)};

	const auto started = std::chrono::steady_clock::now();
	thinking_robot.store(player.label.c_str(), std::memory_order_relaxed);
	const robot::MotionCommands commands = player.robot ? player.robot->Step(p) : player.config.controller(p);
	thinking_robot.store(nullptr, std::memory_order_relaxed);
	engine_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
	if (player.robot && player.robot->Failed() && !player.failed) {
		player.failed = true;
		++failed_;
		Emit({0, "failed", team, static_cast<int>(index), player.robot->Failure()});
	}
	if (!body.on_field) return;
	const Motion before = body.motion;
	body.Command(commands);
	if (body.motion == Motion::Dive && before != Motion::Dive) Emit({0, "dive", team, static_cast<int>(index), body.dive_side > 0 ? "left" : "right"});
}

void Match::WatchForStuck(std::size_t index) {
	Player& player = *players_[index];
	const Body& body = world_.bodies[index];
	const Vec2 position = body.pose.Position();
	const double moved = (position - player.last_position).Norm();
	player.last_position = position;
	// a failed robot has said why already
	const bool watched = player.robot && !player.failed && referee_.State() == GameState::Playing && body.on_field;
	if (!watched) {
		player.last_transition = Time();
		player.pinned = 0;
		return;
	}
	const bool wants_to_walk = (body.walk_mode == Body::WalkMode::Velocity && body.walk_velocity.Norm() > 0.3) ||
	                           (body.walk_mode == Body::WalkMode::Target && (body.walk_target.Position() - position).Norm() > 0.1);
	player.pinned = body.LegsFree() && wants_to_walk && moved < 0.02 * kTick ? player.pinned + kTick : 0;
	const bool silent = Time() - player.last_transition > config_.stuck_seconds;
	const bool pinned = player.pinned > config_.stuck_seconds;
	if ((silent || pinned) && !player.stuck) {
		player.stuck = true;
		++stuck_;
		Emit({0, "stuck", body.team, static_cast<int>(index), silent ? "no transition" : "pinned while walking"});
	} else if (!silent && !pinned) {
		player.stuck = false;
	}
}

void Match::ExchangeWithGameController() {
	// every packet in order: each one's state is followed, and the end of the game is counted in packets
	for (const auto& packet : link_->Receive()) Follow(packet);
	for (auto& notice : link_->TakeNotices()) Emit({0, "gamecontroller", -1, -1, std::move(notice)});
	if (ticks_ % 50 != 0) return;  // robots answer twice a second
	for (std::size_t i = 0; i < players_.size(); ++i) {
		const Body& body = world_.bodies[i];
		const Player& player = *players_[i];
		gc::ReturnData status;
		status.playerNum = static_cast<std::uint8_t>(body.number);
		status.teamNum = static_cast<std::uint8_t>(Team(body.team).number);
		status.fallen = body.Fallen() ? 1 : 0;
		const Pose2 estimate = TeamFrame(body.team, player.sense.Estimate(body));
		status.pose = {static_cast<float>(estimate.x * 1000), static_cast<float>(estimate.y * 1000), static_cast<float>(estimate.theta)};
		const double age = Time() - player.sense.LastBallSeen();
		status.ballAge = age > 1e6 ? -1.0f : static_cast<float>(age);
		status.ball = {player.perception.ball.x * 1000, player.perception.ball.y * 1000};
		link_->SendReturn(status);
	}
}

void Match::Step() {
	if (!started_) Start();
	if (link_) ExchangeWithGameController();
	for (std::size_t i = 0; i < players_.size(); ++i) {
		if ((ticks_ + i) % kTicksPerFrame == 0) {
			Think(i);
			for (auto* observer : observers_) observer->OnDecision(*this, i);
		}
	}
	world_.Step(kTick);
	for (const auto& event : world_.Events()) {
		// touches and post hits are too many for the log; the referee reads them from the world
		const char* type = event.type == PhysicsEvent::Type::Kick         ? "kick"
		                   : event.type == PhysicsEvent::Type::MissedKick ? "missed-kick"
		                   : event.type == PhysicsEvent::Type::Fall       ? "fall"
		                                                                  : nullptr;
		if (type) Emit({0, type, world_.bodies[static_cast<std::size_t>(event.body)].team, event.body, event.what});
	}
	Apply(referee_.Step(kTick, world_, ReadyPoses()));
	for (std::size_t i = 0; i < players_.size(); ++i) WatchForStuck(i);
	++ticks_;
	clock_.Advance(std::chrono::milliseconds(10));
	const auto frame_ticks = static_cast<std::uint64_t>(std::llround(config_.frame_period / kTick));
	if (frame_ticks > 0 && ticks_ % frame_ticks == 0) {
		for (auto* observer : observers_) observer->OnFrame(*this);
		for (auto& player : players_) player->taken.clear();
	}
	for (auto* observer : observers_) observer->OnTick(*this);
}

void Match::Run(double seconds, const std::function<void(const Match&)>& progress, double speed) {
	const std::uint64_t end = seconds > 0 ? ticks_ + static_cast<std::uint64_t>(std::llround(seconds / kTick)) : UINT64_MAX;
	const auto wall_start = std::chrono::steady_clock::now();
	const std::uint64_t first = ticks_;
	// wall time of a tick at this speed; each tick waits for its own point from the start, so a
	// late tick does not push back the rest
	const std::chrono::duration<double> tick_wall(speed > 0 ? kTick / speed : 0);
	while (ticks_ < end && !(started_ && referee_.GameOver())) {
		Step();
		if (speed > 0) {
			std::this_thread::sleep_until(wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(tick_wall * static_cast<double>(ticks_ - first)));
		}
		if (progress && ticks_ % 100 == 0) progress(*this);
	}
	End();
}

void Match::End() {
	if (ended_) return;
	ended_ = true;
	reports_.Flush();
	for (auto* observer : observers_) observer->OnEnd(*this);
}

}  // namespace kse::sim
