#pragma once
// One robot's behaviour process: a generated statechart on the engine, fed with what the
// robot perceives through the standard messages (docs/robot-messages.md) and giving back
// the motion its activities command. The simulator (or a real robot) owns the loop.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <kse/messaging/Blackboard.h>
#include <kse/messaging/Clock.h>
#include <kse/messaging/MessageHub.h>
#include <statechart_engine/Factories.h>
#include <statechart_engine/Statechart.h>

namespace kse::robot {

struct Pose {
	float x = 0;
	float y = 0;
	float theta = 0;
};

/** The ball as the robot sees it, in the robot frame (x forward, y left). */
struct BallPercept {
	bool seen = false;
	float x = 0;
	float y = 0;
	float vx = 0;
	float vy = 0;
};

/** Everything the robot knows this cycle. */
struct Perception {
	int player_state = 0;  // PLAYER_* of BehaviorConst.h
	int game_state = 0;
	int team_number = 0;
	int team_color = 0;
	int player_number = 1;
	bool kickoff = false;
	int our_score = 0;
	int their_score = 0;
	int secs_remaining = 0;
	Pose estimate;  // localisation, field coordinates, own goal at negative x
	float confidence = 0;
	BallPercept ball;
	Pose ready_position;  // where to stand for the kick-off
};

/** What the activities commanded since the previous cycle; the last command of each kind wins. */
struct MotionCommands {
	bool walk = false;  // setWalkTargetVelocity, each in [-1, 1] of the walk's limits
	float vx = 0;
	float vy = 0;
	float vtheta = 0;
	bool walk_to = false;  // walkTo, relative to the robot
	float to_x = 0;
	float to_y = 0;
	float to_theta = 0;
	bool head = false;
	float yaw = 0;
	float pitch = 0;
	std::vector<std::string> actions;  // kicks, dives, poses, in order
};

class Robot {
public:
	/** The transitions one decision cycle may take before the robot counts as failed. */
	static constexpr std::size_t kTransitionsPerCycle = 10000;

	/**
	 * Runs the statechart registered as {@code behaviour}; activities run inline, so stepping is
	 * deterministic, and each run lasts until the next decision cycle, as a run on a robot's
	 * worker takes time: a loop through an activity goes round once per cycle. The engine's
	 * reports (failures, watchdog overruns) go to {@code reporter} (standard error when empty).
	 */
	Robot(const std::string& behaviour, const messaging::Clock& clock, statechart_engine::Reporter reporter = {});
	~Robot();
	Robot(const Robot&) = delete;
	Robot& operator=(const Robot&) = delete;

	/**
	 * Publishes the perception, runs the statechart to a stable state and collects the motion
	 * commands. A statechart that takes kTransitionsPerCycle transitions in one cycle goes round
	 * a loop without waiting for anything: the robot is then failed (Failed()), stands still and
	 * no longer runs its statechart.
	 */
	MotionCommands Step(const Perception& perception);

	/** Whether the robot stopped for good, and why ("" while it runs). */
	bool Failed() const { return !failure_.empty(); }
	const std::string& Failure() const { return failure_; }

	statechart_engine::Statechart& Chart() { return statechart_->Chart(); }
	/** The robot's hub: the monitor shows the State messages it keeps. */
	const messaging::MessageHub& Hub() const { return hub_; }
	const std::string& Behaviour() const { return behaviour_; }

private:
	// The messages a robot publishes every cycle, used again once nobody else holds them.
	struct Recycling;

	std::string behaviour_;
	messaging::MessageHub hub_;
	messaging::Blackboard motion_;
	std::unique_ptr<Recycling> recycling_;
	std::unique_ptr<statechart_engine::IStatechart> statechart_;
	std::string failure_;
};

}  // namespace kse::robot
