// Guard helpers of docs/original-kse.md §9 at their tolerance edges, and the PLAYER_* constants.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "kse/behavior/BehaviorConst.h"
#include "kse/behavior/Guards.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

WorldInfo BallAt(double x, double y) {
  WorldInfo world;
  Ball* ball = world.add_balls();
  ball->set_relativex(static_cast<float>(x));
  ball->set_relativey(static_cast<float>(y));
  return world;
}

WorldInfo RobotAt(double x, double y, double phi) {
  WorldInfo world;
  RobotPose* pose = world.mutable_myposition();
  pose->set_x(static_cast<float>(x));
  pose->set_y(static_cast<float>(y));
  pose->set_phi(static_cast<float>(phi));
  pose->set_confidence(1.0F);
  return world;
}

PositionMessage Target(double x, double y, double theta) {
  PositionMessage target;
  target.set_posx(static_cast<float>(x));
  target.set_posy(static_cast<float>(y));
  target.set_theta(static_cast<float>(theta));
  return target;
}

TEST(BehaviorConst, PlayerStatesAreUsableUnqualified) {
  static_assert(PLAYER_INITIAL == 0 && PLAYER_READY == 1 && PLAYER_SET == 2);
  static_assert(PLAYER_PLAYING == 3 && PLAYER_FINISHED == 4 && PLAYER_PENALISED == 5);
  constexpr int state = PLAYER_PLAYING;
  EXPECT_EQ(state, kse::behavior::PLAYER_PLAYING);
}

TEST(ReadyToKick, CentreOfTheWindow) {
  EXPECT_TRUE(readyToKick(BallAt(0.122, 0.03)));
  EXPECT_TRUE(readyToKick(BallAt(0.122, -0.03)));
  EXPECT_TRUE(readyToKick(BallAt(0.122, 0.0)));
}

TEST(ReadyToKick, XEdgesAreInclusive) {
  EXPECT_TRUE(readyToKick(BallAt(0.110, 0.03)));
  EXPECT_TRUE(readyToKick(BallAt(0.134, 0.03)));
  EXPECT_FALSE(readyToKick(BallAt(0.1099, 0.03)));
  EXPECT_FALSE(readyToKick(BallAt(0.1341, 0.03)));
}

TEST(ReadyToKick, YEdgesAreInclusiveOnBothSides) {
  EXPECT_TRUE(readyToKick(BallAt(0.122, 0.06)));
  EXPECT_TRUE(readyToKick(BallAt(0.122, -0.06)));
  EXPECT_FALSE(readyToKick(BallAt(0.122, 0.0601)));
  EXPECT_FALSE(readyToKick(BallAt(0.122, -0.0601)));
}

TEST(ReadyToKick, CornersAndFarBalls) {
  EXPECT_TRUE(readyToKick(BallAt(0.110, -0.06)));
  EXPECT_TRUE(readyToKick(BallAt(0.134, 0.06)));
  EXPECT_FALSE(readyToKick(BallAt(0.5, 0.0)));
  EXPECT_FALSE(readyToKick(BallAt(-0.122, 0.03)));
}

TEST(ReadyToKick, UsesTheFirstBallAndNeedsOne) {
  EXPECT_FALSE(readyToKick(WorldInfo()));
  WorldInfo world = BallAt(0.122, 0.03);
  Ball* second = world.add_balls();
  second->set_relativex(2.0F);
  EXPECT_TRUE(readyToKick(world));
  WorldInfo other = BallAt(2.0, 0.0);
  Ball* ready = other.add_balls();
  ready->set_relativex(0.122F);
  EXPECT_FALSE(readyToKick(other));
}

TEST(BallAway, StrictlyFartherThan80Centimetres) {
  EXPECT_FALSE(ballAway(BallAt(0.8, 0.0)));
  EXPECT_FALSE(ballAway(BallAt(0.48, 0.64)));  // exactly 0.8 m
  EXPECT_TRUE(ballAway(BallAt(0.8001, 0.0)));
  EXPECT_TRUE(ballAway(BallAt(0.49, 0.64)));
  EXPECT_TRUE(ballAway(BallAt(-0.9, 0.0)));
  EXPECT_TRUE(ballAway(BallAt(0.0, -0.81)));
  EXPECT_FALSE(ballAway(BallAt(0.7999, 0.0)));
  EXPECT_FALSE(ballAway(BallAt(0.0, 0.0)));
}

TEST(BallAway, NoBallIsNotAway) { EXPECT_FALSE(ballAway(WorldInfo())); }

TEST(RobotInPosition, PositionEdgesAreInclusive) {
  const PositionMessage target = Target(1.0, -2.0, 0.5);
  EXPECT_TRUE(robotInPosition(RobotAt(1.0, -2.0, 0.5), target));
  EXPECT_TRUE(robotInPosition(RobotAt(1.1, -2.0, 0.5), target));
  EXPECT_TRUE(robotInPosition(RobotAt(0.9, -2.0, 0.5), target));
  EXPECT_TRUE(robotInPosition(RobotAt(1.0, -1.9, 0.5), target));
  EXPECT_TRUE(robotInPosition(RobotAt(1.0, -2.1, 0.5), target));
  EXPECT_TRUE(robotInPosition(RobotAt(1.1, -2.1, 0.5), target));
  EXPECT_FALSE(robotInPosition(RobotAt(1.1001, -2.0, 0.5), target));
  EXPECT_FALSE(robotInPosition(RobotAt(0.8999, -2.0, 0.5), target));
  EXPECT_FALSE(robotInPosition(RobotAt(1.0, -1.8999, 0.5), target));
  EXPECT_FALSE(robotInPosition(RobotAt(1.0, -2.1001, 0.5), target));
}

TEST(RobotInPosition, HeadingEdgesAreInclusive) {
  const PositionMessage target = Target(0.0, 0.0, 1.0);
  EXPECT_TRUE(robotInPosition(RobotAt(0.0, 0.0, 1.0 + kPi / 8), target));
  EXPECT_TRUE(robotInPosition(RobotAt(0.0, 0.0, 1.0 - kPi / 8), target));
  EXPECT_FALSE(robotInPosition(RobotAt(0.0, 0.0, 1.0 + kPi / 8 + 0.001), target));
  EXPECT_FALSE(robotInPosition(RobotAt(0.0, 0.0, 1.0 - kPi / 8 - 0.001), target));
}

TEST(RobotInPosition, HeadingWrapsAroundPi) {
  EXPECT_TRUE(robotInPosition(RobotAt(0.0, 0.0, kPi - 0.1), Target(0.0, 0.0, -kPi + 0.1)));
  EXPECT_TRUE(robotInPosition(RobotAt(0.0, 0.0, -kPi + 0.05), Target(0.0, 0.0, kPi - 0.05)));
  EXPECT_FALSE(robotInPosition(RobotAt(0.0, 0.0, kPi - 0.3), Target(0.0, 0.0, -kPi + 0.3)));
  EXPECT_TRUE(robotInPosition(RobotAt(0.0, 0.0, 0.1), Target(0.0, 0.0, 0.1 + 2 * kPi)));
}

TEST(RobotInPosition, NeedsTheRobotPose) {
  EXPECT_FALSE(robotInPosition(WorldInfo(), Target(0.0, 0.0, 0.0)));
}

TEST(Guards, PointerFormsAreFalseForMissingMessages) {
  const auto ready = std::make_shared<const WorldInfo>(BallAt(0.122, 0.0));
  const auto far = std::make_shared<const WorldInfo>(BallAt(2.0, 0.0));
  const auto pose = std::make_shared<const WorldInfo>(RobotAt(0.0, 0.0, 0.0));
  const auto target = std::make_shared<const PositionMessage>(Target(0.0, 0.0, 0.0));
  EXPECT_TRUE(readyToKick(ready));
  EXPECT_FALSE(readyToKick(std::shared_ptr<const WorldInfo>()));
  EXPECT_TRUE(ballAway(far));
  EXPECT_FALSE(ballAway(std::shared_ptr<const WorldInfo>()));
  EXPECT_TRUE(robotInPosition(pose, target));
  EXPECT_FALSE(robotInPosition(pose, nullptr));
  EXPECT_FALSE(robotInPosition(nullptr, target));
}

TEST(Guards, NormalizeAngle) {
  EXPECT_NEAR(kse::behavior::NormalizeAngle(0.0), 0.0, 1e-12);
  EXPECT_NEAR(kse::behavior::NormalizeAngle(2 * kPi + 0.25), 0.25, 1e-12);
  EXPECT_NEAR(kse::behavior::NormalizeAngle(-2 * kPi - 0.25), -0.25, 1e-12);
  EXPECT_NEAR(std::fabs(kse::behavior::NormalizeAngle(kPi)), kPi, 1e-12);
}

}  // namespace
