#pragma once
// What the example activities share: reading the world (docs/robot-messages.md) and
// commanding the legs and the head. Header-only, used by every activity of the examples: each
// keeps a RobotIO as a member and binds it to its blackboard in UserInit().

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <kse/behavior/BehaviorConst.h>
#include <kse/messages/all.h>
#include <kse/messaging/Blackboard.h>
#include <kse/messaging/Recycled.h>

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

/**
 * What an activity reads and commands: the world through readers bound once to its blackboard
 * (kse::messaging::Reader, no topic looked up per read), and the motion commands published
 * straight to the hub, for the robot's body, as messages used again (kse::messaging::Recycled).
 *
 * A command goes to the blackboards subscribed to `motion` (the robot's), not into the
 * activity's own blackboard: published through it, each would also wait there as an unread
 * signal (a thousand of each kind kept), so every command would be a message made new or taken
 * back a thousand commands later, long out of the caches, and the activity's blackboard would
 * hold thousands of messages nobody reads. A guard that reacts to commands subscribes its
 * blackboard to `motion` and sees them after its next refresh, as it sees those of other regions.
 *
 * An activity keeps one as a member and calls Bind(*_blk) in UserInit().
 */
class RobotIO {
public:
	/** Subscribes the blackboard to what Read() reads and binds the reads to it. */
	void Bind(kse::messaging::Blackboard& blackboard) {
		blackboard.Subscribe(Worldstate());
		blackboard.Subscribe(Behavior());
		game_.Bind(blackboard, Worldstate());
		info_.Bind(blackboard, Worldstate());
		head_.Bind(blackboard, Behavior());
		position_.Bind(blackboard, Behavior());
		blackboard_ = &blackboard;
	}

	/** Refreshes the blackboard (as every Monas activity did first) and reads it. */
	World Read() {
		Board().ProcessMessages();
		World world;
		world.game = game_.ReadState();
		world.info = info_.ReadData();
		world.head = head_.ReadState();
		world.position = position_.ReadState();
		return world;
	}

	/** Walk with velocities normalised to the walk's limits. */
	void Walk(float vx, float vy, float vtheta) {
		static const std::string kCommand = "setWalkTargetVelocity";
		MotionWalkMessage& walk = walks_.Next();
		walk.Clear();
		walk.set_command(kCommand);
		walk.add_parameter(Clamp(vx));
		walk.add_parameter(Clamp(vy));
		walk.add_parameter(Clamp(vtheta));
		walk.add_parameter(1.0f);
		Command(walks_.Last());
	}

	void Stop() { Walk(0, 0, 0); }

	void Head(float yaw, float pitch) {
		static const std::string kCommand = "setHead";
		MotionHeadMessage& head = heads_.Next();
		head.Clear();
		head.set_command(kCommand);
		head.add_parameter(yaw);
		head.add_parameter(pitch);
		Command(heads_.Last());
	}

	void Action(const std::string& command) {
		MotionActionMessage& action = actions_.Next();
		action.Clear();
		action.set_command(command);
		Command(actions_.Last());
	}

	/** Walk towards a field pose: turn to it, walk, then turn to the wanted heading. */
	void WalkToFieldPose(const World& world, float x, float y, float theta) {
		if (!world.Localised()) {
			Stop();
			return;
		}
		const auto& me = world.info->myposition();
		const float dx = x - me.x();
		const float dy = y - me.y();
		const float distance = std::hypot(dx, dy);
		if (distance < 0.1f) {
			Walk(0, 0, 2.0f * NormalizeAngle(theta - me.phi()));
			return;
		}
		const float bearing = NormalizeAngle(std::atan2(dy, dx) - me.phi());
		const float forward = std::cos(bearing) * std::min(1.0f, distance);
		const float sideways = std::sin(bearing) * std::min(1.0f, distance);
		Walk(forward, sideways, 1.5f * bearing);
	}

	/** Keep the ball in the middle of the image when it is seen. */
	void TrackBall(const World& world) {
		if (world.BallSeen()) Head(Clamp(world.BallBearing(), 2.0f), 0.3f);
	}

private:
	// Topics as the blackboard takes them, made once.
	static const std::string& Worldstate() {
		static const std::string topic = "worldstate";
		return topic;
	}
	static const std::string& Behavior() {
		static const std::string topic = "behavior";
		return topic;
	}
	static const std::string& Motion() {
		static const std::string topic = "motion";
		return topic;
	}

	template <class T>
	void Command(const std::shared_ptr<T>& command) {
		Board().Hub().Publish(Motion(), kse::messaging::Kind::Signal, std::shared_ptr<const T>(command));
	}

	kse::messaging::Blackboard& Board() const {
		if (blackboard_ == nullptr) throw std::logic_error("examples::RobotIO used before Bind(blackboard) (bind it in UserInit())");
		return *blackboard_;
	}

	// The robot reads every command of a cycle, so one or two are out at a time; a blackboard of
	// the behaviour subscribed to `motion` keeps up to a thousand unread ones, and then so many.
	static constexpr std::size_t kCommandsOut = kse::messaging::Blackboard::kSignalQueueLimit + 16;

	kse::messaging::Blackboard* blackboard_ = nullptr;
	kse::messaging::Reader<GameStateMessage> game_;
	kse::messaging::Reader<WorldInfo> info_;
	kse::messaging::Reader<HeadToBMessage> head_;
	kse::messaging::Reader<PositionMessage> position_;
	kse::messaging::Recycled<MotionWalkMessage> walks_{kCommandsOut};
	kse::messaging::Recycled<MotionHeadMessage> heads_{kCommandsOut};
	kse::messaging::Recycled<MotionActionMessage> actions_{kCommandsOut};
};

}  // namespace examples
