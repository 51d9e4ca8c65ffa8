#pragma once
// What a simulated Nao perceives: camera images with the Nao's field of view, range limits,
// occlusion and noise, a localisation estimate, and a ball model that remembers the ball for a
// second. The behaviour gets it as a kse::robot::Perception.

#include <vector>

#include <kse/robot/Robot.h>
#include <kse/sim/Random.h>
#include <kse/sim/World.h>

namespace kse::sim {

struct Sighting {
	enum class Kind { Ball, Post, Robot } kind;
	Vec2 relative;  // robot frame, with noise
	int body = -1;  // the robot seen
};

/** One camera image: the camera it came from and what is in it. */
struct Image {
	bool top = true;
	std::vector<Sighting> seen;
};

namespace camera {

/** Ranges beyond which things are too small to detect, per camera. */
constexpr double kBallRange = 5.5;
constexpr double kBallRangeBottom = 1.5;
constexpr double kPostRange = 8.0;
constexpr double kRobotRange = 6.0;

/**
 * Whether the vertical extent [low, high] (m above the carpet) of something at a field point
 * falls in the camera's field of view, ignoring range and occlusion.
 */
bool InView(const Body& body, bool top_camera, Vec2 point, double low, double high);

/** The image the robot's camera takes now: nothing while it lies on the ground. */
Image Look(const World& world, int body, bool top_camera, Random& random);

}  // namespace camera

/** One robot's belief: its pose (localisation error in the field frame) and the ball. */
class RobotSense {
public:
	explicit RobotSense(Random random) : random_(random) {}

	/** Takes this frame's image and the robot's motion since the last frame. */
	void Update(const World& world, int body, const Image& image, double now);
	/** After the robot was carried (penalty, placement): it is less sure where it is. */
	void Kidnapped(double error);

	Pose2 Estimate(const Body& body) const;
	double Confidence() const;
	/** The ball in the robot frame, seen within the last second; nullopt-like `seen` = false otherwise. */
	robot::BallPercept BallPercept(const Body& body, double now) const;
	double LastBallSeen() const { return ball_seen_at_; }

private:
	Random random_;
	Vec2 position_error_;
	double heading_error_ = 0;
	Pose2 last_pose_;
	bool has_last_pose_ = false;
	Vec2 ball_field_;      // where the robot believes the ball was, field frame
	Vec2 ball_velocity_;   // field frame
	double ball_seen_at_ = -1e9;
};

}  // namespace kse::sim
