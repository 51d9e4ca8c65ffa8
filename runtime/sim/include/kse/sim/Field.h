#pragma once
// The RoboCup SPL field and the Nao's numbers (docs/original-kse.md §10). Field frame: origin at the
// centre mark, x along the long side, goals at x = ±kHalfLength.

#include <kse/sim/Geometry.h>

namespace kse::sim::field {

constexpr double kHalfLength = 4.5;         // 9.0 m inside the lines
constexpr double kHalfWidth = 3.0;          // 6.0 m
constexpr double kCarpetHalfLength = 5.2;   // 10.4 m carpet
constexpr double kCarpetHalfWidth = 3.7;    // 7.4 m
constexpr double kLineWidth = 0.05;
constexpr double kGoalAreaLength = 0.6;
constexpr double kGoalAreaWidth = 2.2;
constexpr double kPenaltyAreaLength = 1.65;
constexpr double kPenaltyAreaWidth = 4.0;
constexpr double kPenaltyMarkDistance = 1.3;  // from the goal line
constexpr double kCentreCircleRadius = 0.75;
constexpr double kGoalInnerHalfWidth = 0.75;
constexpr double kPostRadius = 0.05;
constexpr double kGoalDepth = 0.5;
constexpr double kPostX = kHalfLength + kLineWidth / 2;
constexpr double kPostY = kGoalInnerHalfWidth + kPostRadius;
constexpr double kPostHeight = 0.8;

constexpr double kBallRadius = 0.05;
constexpr double kBallMass = 0.044;
/** Rolling deceleration on the carpet: a ball sent at 2.3 m/s stops after about 4.5 m. */
constexpr double kBallDeceleration = 0.6;

/** The ball is in a goal when it is wholly behind the goal line between the posts. */
inline bool InGoal(Vec2 ball, int side) {
	return side * ball.x > kHalfLength + kLineWidth / 2 + kBallRadius && ball.y > -kGoalInnerHalfWidth &&
	       ball.y < kGoalInnerHalfWidth && side * ball.x < kPostX + kGoalDepth;
}

/** The ball has left the field when it is wholly outside the lines (and not in a goal). */
inline bool BallOut(Vec2 ball) {
	const double margin = kLineWidth / 2 + kBallRadius;
	return std::fabs(ball.x) > kHalfLength + margin || std::fabs(ball.y) > kHalfWidth + margin;
}

inline bool InsideField(Vec2 point, double margin = 0) {
	return std::fabs(point.x) <= kHalfLength + margin && std::fabs(point.y) <= kHalfWidth + margin;
}

}  // namespace kse::sim::field

namespace kse::sim::nao {

// Walk (a typical SPL walk engine)
constexpr double kMaxForward = 0.25;    // m/s
constexpr double kMaxBackward = 0.15;   // m/s
constexpr double kMaxSideways = 0.2;    // m/s
constexpr double kMaxTurn = 120.0 * kPi / 180.0;  // rad/s
constexpr double kLinearAcceleration = 0.5;       // m/s²
constexpr double kAngularAcceleration = 6.0;      // rad/s²
constexpr double kStepPeriod = 0.25;              // s

// Head joints and their speed
constexpr double kMaxHeadYaw = 2.0857;
constexpr double kMinHeadPitch = -0.672;
constexpr double kMaxHeadPitch = 0.515;
constexpr double kHeadSpeed = 5.0;  // rad/s

// Cameras (Nao v6): one image a frame, top and bottom in turn
constexpr double kHorizontalFov = 56.3 * kPi / 180.0;
constexpr double kVerticalFov = 43.7 * kPi / 180.0;
constexpr double kTopCameraHeight = 0.51;
constexpr double kTopCameraPitch = 1.2 * kPi / 180.0;
constexpr double kBottomCameraHeight = 0.46;
constexpr double kBottomCameraPitch = 39.7 * kPi / 180.0;
constexpr double kHeight = 0.57;

// Bodies: the feet meet the ball (a capsule across the feet), the body meets other robots.
constexpr double kFeetHalfWidth = 0.05;
constexpr double kFeetRadius = 0.065;
constexpr double kBodyRadius = 0.15;
constexpr double kDiveReach = 0.6;     // a goalkeeper lying on its side covers this far
constexpr double kLyingRadius = 0.08;

}  // namespace kse::sim::nao
