// What a simulated Nao sees: the camera's field of view and range, occlusion, noise; the ball
// model's memory and the localisation estimate.
#include <cmath>

#include <gtest/gtest.h>

#include <kse/sim/Perception.h>

using namespace kse::sim;

namespace {

constexpr double kDegree = kPi / 180;

World Viewer(Pose2 pose = {}, double yaw = 0, double pitch = 0.3) {
	World world{Random(1)};
	Body body;
	body.pose = pose;
	body.head_yaw = body.head_yaw_target = yaw;
	body.head_pitch = body.head_pitch_target = pitch;
	world.bodies.push_back(body);
	return world;
}

int TimesSeen(World& world, Sighting::Kind kind, bool top, int looks = 200, std::uint64_t seed = 3) {
	Random random(seed);
	int seen = 0;
	for (int i = 0; i < looks; ++i) {
		const Image image = camera::Look(world, 0, top, random);
		for (const auto& sighting : image.seen) seen += sighting.kind == kind;
	}
	return seen;
}

}  // namespace

TEST(Camera, HorizontalFieldOfViewEdges) {
	const World world = Viewer();
	const double half = nao::kHorizontalFov / 2;
	const double distance = 2.0;
	EXPECT_TRUE(camera::InView(world.bodies[0], true, FromPolar(distance, half - 0.3 * kDegree), 0, 0.1));
	EXPECT_FALSE(camera::InView(world.bodies[0], true, FromPolar(distance, half + 0.3 * kDegree), 0, 0.1));
	EXPECT_TRUE(camera::InView(world.bodies[0], true, FromPolar(distance, -half + 0.3 * kDegree), 0, 0.1));
	EXPECT_FALSE(camera::InView(world.bodies[0], true, FromPolar(distance, -half - 0.3 * kDegree), 0, 0.1));

	const World turned = Viewer({}, 1.0);
	EXPECT_TRUE(camera::InView(turned.bodies[0], true, FromPolar(distance, 1.0 + half - 0.3 * kDegree), 0, 0.1)) << "the head turns the view";
	EXPECT_FALSE(camera::InView(turned.bodies[0], true, FromPolar(distance, 0.0), 0, 0.1));

	const World rotated = Viewer({1, 1, kPi / 2});
	EXPECT_TRUE(camera::InView(rotated.bodies[0], true, {1, 3}, 0, 0.1)) << "and so does the body";
	EXPECT_FALSE(camera::InView(rotated.bodies[0], true, {3, 1}, 0, 0.1));
}

TEST(Camera, VerticalFieldOfViewSplitsNearAndFarBetweenTheCameras) {
	const World world = Viewer({}, 0, 0.0);
	// the lowest ground point the top camera sees is where the ray at (pitch + offset + vfov/2) meets the carpet
	const double lowest_top = nao::kTopCameraHeight / std::tan(nao::kTopCameraPitch + nao::kVerticalFov / 2);
	EXPECT_TRUE(camera::InView(world.bodies[0], true, {lowest_top + 0.02, 0}, 0, 0));
	EXPECT_FALSE(camera::InView(world.bodies[0], true, {lowest_top - 0.02, 0}, 0, 0));
	EXPECT_TRUE(camera::InView(world.bodies[0], false, {lowest_top - 0.1, 0}, 0, 0)) << "the bottom camera sees the feet";
	const double farthest_bottom = nao::kBottomCameraHeight / std::tan(nao::kBottomCameraPitch - nao::kVerticalFov / 2);
	EXPECT_TRUE(camera::InView(world.bodies[0], false, {farthest_bottom - 0.02, 0}, 0, 0));
	EXPECT_FALSE(camera::InView(world.bodies[0], false, {farthest_bottom + 0.02, 0}, 0, 0));

	const World up = Viewer({}, 0, -0.3);
	EXPECT_FALSE(camera::InView(up.bodies[0], true, {1.0, 0}, 0, 0.1)) << "looking up, the carpet nearby is out of view";
	EXPECT_TRUE(camera::InView(up.bodies[0], true, {4.0, 0}, 0, field::kPostHeight)) << "a goal post is tall";
}

TEST(Camera, SeesTheBallOnlyInRangeAndNotBehindARobot) {
	World world = Viewer({}, 0, 0.0);
	world.ball.position = {camera::kBallRange - 0.1, 0};
	EXPECT_GT(TimesSeen(world, Sighting::Kind::Ball, true), 150);
	world.ball.position = {camera::kBallRange + 0.1, 0};
	EXPECT_EQ(TimesSeen(world, Sighting::Kind::Ball, true), 0);

	world.ball.position = {2.0, 0};
	EXPECT_GT(TimesSeen(world, Sighting::Kind::Ball, true), 170);
	Body blocker;
	blocker.pose = {1.0, 0.05, kPi};
	world.bodies.push_back(blocker);
	EXPECT_EQ(TimesSeen(world, Sighting::Kind::Ball, true), 0) << "occluded";
	EXPECT_GT(TimesSeen(world, Sighting::Kind::Robot, true), 120) << "but the robot is seen";

	world.bodies.pop_back();
	world.bodies[0].motion = Motion::Fallen;
	EXPECT_EQ(TimesSeen(world, Sighting::Kind::Ball, true), 0) << "a fallen robot sees nothing";
}

TEST(Camera, MeasurementsAreNoisyButUnbiased) {
	World world = Viewer({}, 0, 0.1);
	world.ball.position = {3.0, 1.0};
	Random random(9);
	double sum_x = 0, sum_y = 0, sum_sq = 0;
	int count = 0;
	for (int i = 0; i < 4000; ++i) {
		for (const auto& sighting : camera::Look(world, 0, true, random).seen) {
			if (sighting.kind != Sighting::Kind::Ball) continue;
			sum_x += sighting.relative.x;
			sum_y += sighting.relative.y;
			sum_sq += std::pow((sighting.relative - world.ball.position).Norm(), 2);
			++count;
		}
	}
	ASSERT_GT(count, 3000);
	EXPECT_NEAR(sum_x / count, 3.0, 0.02);
	EXPECT_NEAR(sum_y / count, 1.0, 0.02);
	const double rms = std::sqrt(sum_sq / count);
	EXPECT_GT(rms, 0.05) << "noisy";
	EXPECT_LT(rms, 0.25);
}

TEST(Camera, SeesGoalPostsWhenLookingAtTheGoal) {
	World world = Viewer({2.0, 0, 0}, 0, 0.0);
	EXPECT_GT(TimesSeen(world, Sighting::Kind::Post, true, 100), 150) << "both posts of the goal ahead";
	world.bodies[0].pose.theta = kPi / 2;
	EXPECT_EQ(TimesSeen(world, Sighting::Kind::Post, true, 100), 0);
}

TEST(BallModel, RemembersTheBallForASecond) {
	World world = Viewer({}, 0, 0.1);
	world.ball.position = {2.0, 0.5};
	RobotSense sense(Random(4));
	Image image;
	image.seen.push_back({Sighting::Kind::Ball, {2.0, 0.5}, -1});
	sense.Update(world, 0, image, 10.0);
	auto ball = sense.BallPercept(world.bodies[0], 10.0);
	ASSERT_TRUE(ball.seen);
	EXPECT_NEAR(ball.x, 2.0, 0.05);
	EXPECT_NEAR(ball.y, 0.5, 0.05);
	EXPECT_TRUE(sense.BallPercept(world.bodies[0], 10.95).seen);
	EXPECT_FALSE(sense.BallPercept(world.bodies[0], 11.05).seen);

	// after the robot turned, the remembered ball is where it was on the field
	world.bodies[0].pose.theta = kPi / 2;
	sense.Update(world, 0, Image{}, 10.5);
	ball = sense.BallPercept(world.bodies[0], 10.5);
	ASSERT_TRUE(ball.seen);
	EXPECT_NEAR(ball.x, 0.5, 0.2);
	EXPECT_NEAR(ball.y, -2.0, 0.2);
}

TEST(Localisation, DriftsWhileWalkingAndRecoversWithGoalPosts) {
	World world = Viewer({-3, 0, 0}, 0, 0.0);
	RobotSense sense(Random(8));
	sense.Kidnapped(0.5);
	const double before = (sense.Estimate(world.bodies[0]).Position() - world.bodies[0].pose.Position()).Norm();
	Random random(2);
	for (int frame = 0; frame < 300; ++frame) {
		world.bodies[0].pose.x += 0.002;  // walking slowly towards the goal ahead
		sense.Update(world, 0, camera::Look(world, 0, frame % 2 == 0, random), frame / 30.0);
	}
	const double after = (sense.Estimate(world.bodies[0]).Position() - world.bodies[0].pose.Position()).Norm();
	EXPECT_GT(before, 0.1);
	EXPECT_LT(after, 0.05);
	EXPECT_GT(sense.Confidence(), 0.8);
}
