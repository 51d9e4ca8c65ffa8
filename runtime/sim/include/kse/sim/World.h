#pragma once
// The physical side of the simulation: the ball, the robots' bodies and what happens when
// they meet. Deterministic: the same commands and the same Random give the same world.

#include <string>
#include <vector>

#include <kse/robot/Robot.h>
#include <kse/sim/Field.h>
#include <kse/sim/Geometry.h>
#include <kse/sim/Random.h>

namespace kse::sim {

struct Ball {
	Vec2 position;
	Vec2 velocity;
};

/** What a body's legs are doing. */
enum class Motion { Stand, Walk, Kick, Dive, Fallen, GettingUp, Pose };
const char* ToString(Motion motion);

/** A named kick: when the foot meets the ball and where the ball goes. Robot frame. */
struct KickSpec {
	const char* name;
	double duration;      // s
	double contact;       // s after the start
	Vec2 sweet_spot;      // ball position that gives the best kick
	double reach;         // the ball must be this close to the sweet spot
	double direction;     // rad, relative to the robot's heading
	double min_distance;  // m the ball rolls, worst contact
	double max_distance;  // m, best contact
	double direction_sigma;
	bool in_walk;         // the walk goes on during the kick
};
/** The kicks a behaviour may command (MotionActionMessage), or nullptr. */
const KickSpec* FindKick(const std::string& name);

struct Body {
	int team = 0;    // 0 home, 1 away
	int number = 1;  // player number, 1 = goalkeeper
	bool on_field = true;
	Pose2 pose;
	Vec2 velocity;        // robot frame, m/s
	double turn_rate = 0; // rad/s
	double head_yaw = 0;
	double head_pitch = 0;

	Motion motion = Motion::Stand;
	double motion_time = 0;  // s since the motion started
	const KickSpec* kick = nullptr;
	bool kick_done = false;
	int dive_side = 0;  // 1 left, -1 right

	// what the behaviour asked for
	enum class WalkMode { None, Velocity, Target } walk_mode = WalkMode::None;
	Vec2 walk_velocity;      // normalised, robot frame
	double walk_turn = 0;    // normalised
	Pose2 walk_target;       // field frame
	double head_yaw_target = 0;
	double head_pitch_target = 0;

	double pushing_time = 0;  // s of pushing another robot without a break

	bool Upright() const { return on_field && (motion == Motion::Stand || motion == Motion::Walk || motion == Motion::Kick || motion == Motion::Pose); }
	bool Fallen() const { return motion == Motion::Fallen || motion == Motion::GettingUp; }
	bool LegsFree() const { return motion == Motion::Stand || motion == Motion::Walk; }
	/** Field-frame velocity of the body. */
	Vec2 FieldVelocity() const { return velocity.Rotated(pose.theta); }
	/** How far the dived goalkeeper's body reaches sideways now (0 when not diving). */
	double DiveExtent() const;

	/** Takes a cycle's motion commands; a kick, dive or fall in progress is not interrupted. */
	void Command(const robot::MotionCommands& commands);
	/** Puts the body down somewhere (manual placement), standing still. */
	void Place(const Pose2& where);
};

/** Something that happened in the last step, for the referee and the log. */
struct PhysicsEvent {
	enum class Type { Touch, Kick, MissedKick, Fall, Post } type;
	int body = -1;
	std::string what;  // kick name
	double value = 0;  // kick distance
};

class World {
public:
	explicit World(Random random) : random_(random) {}

	Ball ball;
	std::vector<Body> bodies;

	/** Advances by dt seconds: bodies, kicks, the ball, collisions. */
	void Step(double dt);

	const std::vector<PhysicsEvent>& Events() const { return events_; }
	/** The body that touched the ball last, or -1. */
	int LastTouch() const { return last_touch_; }
	void SetLastTouch(int body) { last_touch_ = body; }

	/** Starts the ball rolling as a kick of this distance would (used by scenarios and tests). */
	static Vec2 KickVelocity(double distance, double direction);

private:
	void MoveBody(Body& body, double dt);
	void Kick(int index, Body& body);
	void MoveBall(double dt);
	void CollideBallWithBodies();
	void CollideBodies(double dt);
	void CollideBallWithGoals();

	Random random_;
	std::vector<PhysicsEvent> events_;
	int last_touch_ = -1;
};

}  // namespace kse::sim
