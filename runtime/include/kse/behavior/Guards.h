#ifndef KSE_BEHAVIOR_GUARDS_H
#define KSE_BEHAVIOR_GUARDS_H

// Guard helpers that generated conditions call unqualified (docs/original-kse.md §9), e.g.
// `[... && readyToKick(worldstate.Data.WorldInfo)]`. Global functions.
//
// All bounds are inclusive, with kse::behavior::kGuardSlack (1e-6 m or rad) of slack so that
// values stored as float at exactly the documented edge still count as inside. The ball is
// the first entry of WorldInfo::balls; with no ball, readyToKick and ballAway are false.
// robotInPosition is false when WorldInfo has no myPosition.

#include <memory>

#include "kse/messages/Behavior.pb.h"
#include "kse/messages/WorldInfo.pb.h"

namespace kse::behavior {

constexpr double kKickBallX = 0.122;          ///< m, ideal ball distance in front of the robot
constexpr double kKickBallXTolerance = 0.012;  ///< m
constexpr double kKickBallY = 0.03;           ///< m, ideal |y| of the ball (in front of a foot)
constexpr double kKickBallYTolerance = 0.03;   ///< m
constexpr double kBallAwayDistance = 0.8;      ///< m, "away" means strictly farther than this
constexpr double kPositionTolerance = 0.1;     ///< m, per axis
constexpr double kAngleTolerance = 0.39269908169872414;  ///< rad, pi / 8
constexpr double kGuardSlack = 1e-6;

/// Normalises an angle to [-pi, pi).
double NormalizeAngle(double radians);

}  // namespace kse::behavior

/// The first ball is ready to be kicked: x within 0.122 ± 0.012 m and |y| within 0.03 ± 0.03 m.
bool readyToKick(const WorldInfo& world);
/// The first ball is farther than 0.8 m from the robot.
bool ballAway(const WorldInfo& world);
/// The robot is within ±0.1 m (x and y) and ±π/8 (heading) of the target pose.
bool robotInPosition(const WorldInfo& world, const PositionMessage& target);

// Pointer forms, as read from a blackboard: false when a message is missing.
bool readyToKick(const std::shared_ptr<const WorldInfo>& world);
bool ballAway(const std::shared_ptr<const WorldInfo>& world);
bool robotInPosition(const std::shared_ptr<const WorldInfo>& world,
                     const std::shared_ptr<const PositionMessage>& target);

#endif
