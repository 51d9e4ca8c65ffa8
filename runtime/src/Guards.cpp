#include "kse/behavior/Guards.h"

#include <cmath>

namespace kse::behavior {

double NormalizeAngle(double radians) {
  constexpr double kPi = 3.14159265358979323846;
  double a = std::fmod(radians + kPi, 2.0 * kPi);
  if (a < 0.0) {
    a += 2.0 * kPi;
  }
  return a - kPi;
}

namespace {

bool Within(double value, double centre, double tolerance) {
  return std::fabs(value - centre) <= tolerance + kGuardSlack;
}

}  // namespace

}  // namespace kse::behavior

using namespace kse::behavior;

bool readyToKick(const WorldInfo& world) {
  if (world.balls_size() == 0) {
    return false;
  }
  const Ball& ball = world.balls(0);
  const double x = ball.relativex();
  const double y = ball.relativey();
  return Within(x, kKickBallX, kKickBallXTolerance) &&
         Within(std::fabs(y), kKickBallY, kKickBallYTolerance);
}

bool ballAway(const WorldInfo& world) {
  if (world.balls_size() == 0) {
    return false;
  }
  const Ball& ball = world.balls(0);
  const double distance = std::hypot(static_cast<double>(ball.relativex()),
                                     static_cast<double>(ball.relativey()));
  return distance > kBallAwayDistance + kGuardSlack;
}

bool robotInPosition(const WorldInfo& world, const PositionMessage& target) {
  if (!world.has_myposition()) {
    return false;
  }
  const RobotPose& pose = world.myposition();
  return Within(pose.x(), target.posx(), kPositionTolerance) &&
         Within(pose.y(), target.posy(), kPositionTolerance) &&
         Within(NormalizeAngle(static_cast<double>(pose.phi()) - target.theta()), 0.0,
                kAngleTolerance);
}

bool readyToKick(const std::shared_ptr<const WorldInfo>& world) {
  return world != nullptr && readyToKick(*world);
}

bool ballAway(const std::shared_ptr<const WorldInfo>& world) {
  return world != nullptr && ballAway(*world);
}

bool robotInPosition(const std::shared_ptr<const WorldInfo>& world,
                     const std::shared_ptr<const PositionMessage>& target) {
  return world != nullptr && target != nullptr && robotInPosition(*world, *target);
}
