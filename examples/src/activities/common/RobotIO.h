#pragma once
// What the example activities share: reading the world (docs/robot-messages.md) and
// commanding the legs and the head. Header-only, used by every activity of the examples.

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include <kse/behavior/BehaviorConst.h>
#include <kse/messages/all.h>
#include <kse/messaging/Blackboard.h>

namespace examples {

constexpr float kPi = 3.14159265f;
constexpr float kOpponentGoalX = 4.5f;
constexpr float kOwnGoalX = -4.5f;

inline float Clamp(float value, float limit = 1.0f) { return std::max(-limit, std::min(limit, value)); }

inline float NormalizeAngle(float angle) {
	while (angle > kPi) angle -= 2 * kPi;
	while (angle < -kPi) angle += 2 * kPi;
	return angle;
}

/** The behaviour's view of the world, read once per activity run. */
struct World {
	std::shared_ptr<const GameStateMessage> game;
	std::shared_ptr<const WorldInfo> info;
	std::shared_ptr<const HeadToBMessage> head;
	std::shared_ptr<const PositionMessage> position;

	/** Refreshes the blackboard (as every Monas activity did first) and reads it. */
	static World Read(kse::messaging::Blackboard& blackboard) {
		blackboard.ProcessMessages();
		World world;
		world.game = blackboard.ReadState<GameStateMessage>("worldstate");
		world.info = blackboard.ReadData<WorldInfo>("worldstate");
		world.head = blackboard.ReadState<HeadToBMessage>("behavior");
		world.position = blackboard.ReadState<PositionMessage>("behavior");
		return world;
	}

	int PlayerState() const { return game ? game->player_state() : PLAYER_INITIAL; }
	bool BallSeen() const { return head && head->ballfound() > 0 && info && info->balls_size() > 0; }
	const Ball& TheBall() const { return info->balls(0); }
	float BallDistance() const { return BallSeen() ? std::hypot(TheBall().relativex(), TheBall().relativey()) : 1e9f; }
	float BallBearing() const { return BallSeen() ? std::atan2(TheBall().relativey(), TheBall().relativex()) : 0.0f; }
	bool Localised() const { return info && info->has_myposition(); }

	/** Bearing from the robot to a field point, in the robot frame. */
	float BearingTo(float x, float y) const {
		if (!Localised()) return 0.0f;
		const auto& me = info->myposition();
		return NormalizeAngle(std::atan2(y - me.y(), x - me.x()) - me.phi());
	}
};

inline void Subscribe(kse::messaging::Blackboard& blackboard) {
	blackboard.Subscribe("worldstate");
	blackboard.Subscribe("behavior");
}

/** Walk with velocities normalised to the walk's limits. */
inline void Walk(kse::messaging::Blackboard& blackboard, float vx, float vy, float vtheta) {
	// made as the message to publish (PublishMessage), not copied into one: an activity commands the legs at every run
	auto walk = std::make_shared<MotionWalkMessage>();
	walk->set_command("setWalkTargetVelocity");
	walk->add_parameter(Clamp(vx));
	walk->add_parameter(Clamp(vy));
	walk->add_parameter(Clamp(vtheta));
	walk->add_parameter(1.0f);
	blackboard.PublishMessage("motion", kse::messaging::Kind::Signal, std::move(walk));
}

inline void Stop(kse::messaging::Blackboard& blackboard) { Walk(blackboard, 0, 0, 0); }

inline void Head(kse::messaging::Blackboard& blackboard, float yaw, float pitch) {
	auto head = std::make_shared<MotionHeadMessage>();
	head->set_command("setHead");
	head->add_parameter(yaw);
	head->add_parameter(pitch);
	blackboard.PublishMessage("motion", kse::messaging::Kind::Signal, std::move(head));
}

inline void Action(kse::messaging::Blackboard& blackboard, const std::string& command) {
	auto action = std::make_shared<MotionActionMessage>();
	action->set_command(command);
	blackboard.PublishMessage("motion", kse::messaging::Kind::Signal, std::move(action));
}

/** Walk towards a field pose: turn to it, walk, then turn to the wanted heading. */
inline void WalkToFieldPose(kse::messaging::Blackboard& blackboard, const World& world, float x, float y, float theta) {
	if (!world.Localised()) {
		Stop(blackboard);
		return;
	}
	const auto& me = world.info->myposition();
	const float dx = x - me.x();
	const float dy = y - me.y();
	const float distance = std::hypot(dx, dy);
	if (distance < 0.1f) {
		Walk(blackboard, 0, 0, 2.0f * NormalizeAngle(theta - me.phi()));
		return;
	}
	const float bearing = NormalizeAngle(std::atan2(dy, dx) - me.phi());
	const float forward = std::cos(bearing) * std::min(1.0f, distance);
	const float sideways = std::sin(bearing) * std::min(1.0f, distance);
	Walk(blackboard, forward, sideways, 1.5f * bearing);
}

/**
 * Where a ball rolling at the robot crosses its line (y in the robot frame, metres), when it
 * comes faster than {@code min_speed} m/s: what a goalkeeper dives for.
 */
inline std::optional<float> ShotCrossing(const World& world, float min_speed = 0.4f) {
	if (!world.BallSeen()) return std::nullopt;
	const auto& ball = world.TheBall();
	if (ball.relativexspeed() >= -min_speed || ball.relativex() <= 0) return std::nullopt;
	const float time = ball.relativex() / -ball.relativexspeed();
	return ball.relativey() + ball.relativeyspeed() * time;
}

/** The side to dive to for a shot crossing at {@code crossing}: 1 left, -1 right, 0 none (at the body, or out of reach). */
inline int DiveSide(float crossing, float reach = 0.7f) {
	if (std::fabs(crossing) <= 0.15f || std::fabs(crossing) >= reach + 0.4f) return 0;
	return crossing > 0 ? 1 : -1;
}

inline bool IsGoalkeeper(const World& world) { return world.game && world.game->player_number() == 1; }

/** Keep the ball in the middle of the image when it is seen. */
inline void TrackBall(kse::messaging::Blackboard& blackboard, const World& world) {
	if (world.BallSeen()) Head(blackboard, Clamp(world.BallBearing(), 2.0f), 0.3f);
}

}  // namespace examples
