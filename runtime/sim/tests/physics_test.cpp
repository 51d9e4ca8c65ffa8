// The simulated world's physics: the ball rolls and stops, kicks send it as far as a Nao's,
// posts and goalkeepers stop it, the walk keeps to the Nao's limits.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <kse/sim/World.h>

using namespace kse::sim;

namespace {

constexpr double kDt = 0.01;

World OneRobot(std::uint64_t seed = 1, Pose2 pose = {}) {
	World world{Random(seed)};
	Body body;
	body.pose = pose;
	world.bodies.push_back(body);
	return world;
}

void Advance(World& world, double seconds) {
	for (int i = 0; i < static_cast<int>(std::lround(seconds / kDt)); ++i) world.Step(kDt);
}

kse::robot::MotionCommands Action(const std::string& name) {
	kse::robot::MotionCommands commands;
	commands.actions.push_back(name);
	return commands;
}

kse::robot::MotionCommands Walk(float vx, float vy, float vtheta) {
	kse::robot::MotionCommands commands;
	commands.walk = true;
	commands.vx = vx;
	commands.vy = vy;
	commands.vtheta = vtheta;
	return commands;
}

/** Kicks a ball lying at {@code ball} (robot frame) and returns how far it rolled, or -1 for a miss. */
double KickDistance(const std::string& kick, Vec2 ball, std::uint64_t seed, double* direction = nullptr) {
	World world = OneRobot(seed);
	world.ball.position = ball;
	world.bodies[0].Command(Action(kick));
	Advance(world, 10);
	for (const auto& body : world.bodies) EXPECT_EQ(body.motion, Motion::Stand);
	const Vec2 moved = world.ball.position - ball;
	if (direction) *direction = moved.Angle();
	return moved.Norm() < 0.2 ? -1 : moved.Norm();
}

}  // namespace

TEST(Ball, RollsToAStopAsFarAsItsDecelerationAllows) {
	World world{Random(1)};
	world.ball.velocity = {2.0, 0};
	Advance(world, 3);
	EXPECT_GT(world.ball.velocity.Norm(), 0.0) << "still rolling after 3 s";
	Advance(world, 5);
	EXPECT_EQ(world.ball.velocity.Norm(), 0.0);
	EXPECT_NEAR(world.ball.position.x, 2.0 * 2.0 / (2 * field::kBallDeceleration), 0.02);
	EXPECT_EQ(world.ball.position.y, 0.0);
}

TEST(Ball, BouncesOffAPostAndStopsInTheNet) {
	World world{Random(1)};
	world.ball.position = {3.5, field::kPostY};
	world.ball.velocity = {2.0, 0};
	bool post = false;
	for (int i = 0; i < 200; ++i) {
		world.Step(kDt);
		for (const auto& event : world.Events()) post = post || event.type == PhysicsEvent::Type::Post;
	}
	EXPECT_TRUE(post);
	EXPECT_LT(world.ball.position.x, field::kPostX - 0.5) << "came back from the post";

	world.ball = Ball{{4.0, 0.0}, {2.5, 0}};
	Advance(world, 5);
	EXPECT_TRUE(field::InGoal(world.ball.position, 1));
	EXPECT_LE(world.ball.position.x, field::kPostX + field::kGoalDepth - field::kBallRadius + 1e-9) << "the net holds it";
}

TEST(Ball, GoalAndOutLinesAreWhereTheRulesPutThem) {
	const double behind = field::kHalfLength + field::kLineWidth / 2 + field::kBallRadius;
	EXPECT_TRUE(field::InGoal({behind + 0.01, 0.7}, 1));
	EXPECT_FALSE(field::InGoal({behind - 0.01, 0.0}, 1)) << "on the line is not in";
	EXPECT_FALSE(field::InGoal({behind + 0.01, 0.76}, 1)) << "wide of the post";
	EXPECT_TRUE(field::InGoal({-behind - 0.01, -0.7}, -1));
	EXPECT_FALSE(field::InGoal({-behind - 0.01, 0.0}, 1));
	EXPECT_TRUE(field::BallOut({0, 3.08}));
	EXPECT_FALSE(field::BallOut({0, 3.07}));
	EXPECT_TRUE(field::BallOut({4.58, 2.0}));
}

TEST(Kick, ForwardKicksSendTheBallBetweenOnePointSixAndFourPointFiveMetres) {
	const KickSpec* kick = FindKick("KickForwardLeft");
	ASSERT_NE(kick, nullptr);
	double sum = 0, shortest = 1e9, longest = 0;
	for (std::uint64_t seed = 0; seed < 100; ++seed) {
		double direction = 0;
		const double distance = KickDistance("KickForwardLeft", kick->sweet_spot, seed, &direction);
		ASSERT_GT(distance, 0) << "seed " << seed;
		shortest = std::min(shortest, distance);
		longest = std::max(longest, distance);
		sum += distance;
		EXPECT_LT(std::fabs(direction), 0.3) << "forward, seed " << seed;
	}
	EXPECT_GE(shortest, 1.6 - 0.03);
	EXPECT_LE(longest, 4.5 + 0.03);
	EXPECT_GT(sum / 100, 4.0) << "a ball on the sweet spot goes far";

	double off_sum = 0;
	for (std::uint64_t seed = 0; seed < 100; ++seed) {
		const double distance = KickDistance("KickForwardLeft", kick->sweet_spot + Vec2{0.0, 0.07}, seed);
		ASSERT_GT(distance, 0);
		EXPECT_GE(distance, 1.6 - 0.03);
		off_sum += distance;
	}
	EXPECT_LT(off_sum / 100, sum / 100 - 1.0) << "a ball off the foot's centre goes less far";
}

TEST(Kick, MissesABallOutOfReachAndTakesItsTime) {
	World world = OneRobot();
	world.ball.position = {0.4, 0.0};
	world.bodies[0].Command(Action("KickForwardRight"));
	bool missed = false;
	for (int i = 0; i < 149; ++i) {
		world.Step(kDt);
		for (const auto& event : world.Events()) missed = missed || event.type == PhysicsEvent::Type::MissedKick;
		ASSERT_EQ(world.bodies[0].motion, Motion::Kick) << "a standing kick takes 1.5 s, at " << i;
	}
	Advance(world, 0.02);
	EXPECT_EQ(world.bodies[0].motion, Motion::Stand);
	EXPECT_TRUE(missed);
	EXPECT_EQ(world.ball.velocity.Norm(), 0.0);
	EXPECT_EQ(world.ball.position.x, 0.4);
}

TEST(Kick, SideAndInWalkKicks) {
	double direction = 0;
	const double side = KickDistance("KickSideLeft", FindKick("KickSideLeft")->sweet_spot, 3, &direction);
	EXPECT_GE(side, 1.0 - 0.03);
	EXPECT_LE(side, 2.5 + 0.03);
	EXPECT_NEAR(direction, 1.4, 0.4) << "to the left";

	World world = OneRobot();
	const KickSpec* in_walk = FindKick("InWalkKickRight");
	world.ball.position = in_walk->sweet_spot;
	world.bodies[0].Command(Walk(0.5f, 0, 0));
	world.bodies[0].Command(Action("InWalkKickRight"));
	Advance(world, 0.41);
	EXPECT_EQ(world.bodies[0].motion, Motion::Walk) << "an in-walk kick is over in 0.4 s and the walk goes on";
	EXPECT_GT(world.ball.velocity.Norm(), std::sqrt(2 * field::kBallDeceleration * 0.9));
	EXPECT_LT(world.ball.velocity.Norm(), std::sqrt(2 * field::kBallDeceleration * 2.6));
}

TEST(Walk, KeepsToTheNaoSpeedAndAccelerationLimits) {
	World world = OneRobot();
	world.bodies[0].Command(Walk(1, 0, 0));
	Advance(world, 0.2);
	EXPECT_NEAR(world.bodies[0].velocity.x, 0.2 * nao::kLinearAcceleration, 1e-9);
	Advance(world, 2);
	EXPECT_NEAR(world.bodies[0].velocity.x, nao::kMaxForward, 1e-9);
	const double x = world.bodies[0].pose.x;
	Advance(world, 4);
	EXPECT_NEAR(world.bodies[0].pose.x - x, 4 * nao::kMaxForward, 1e-6);

	World backwards = OneRobot();
	backwards.bodies[0].Command(Walk(-1, 0, 0));
	Advance(backwards, 2);
	EXPECT_NEAR(backwards.bodies[0].velocity.x, -nao::kMaxBackward, 1e-9);

	World turning = OneRobot();
	turning.bodies[0].Command(Walk(0, 0, 1));
	Advance(turning, 1);
	EXPECT_NEAR(turning.bodies[0].turn_rate, nao::kMaxTurn, 1e-9);

	World diagonal = OneRobot();
	diagonal.bodies[0].Command(Walk(1, 1, 0));
	Advance(diagonal, 2);
	EXPECT_NEAR(diagonal.bodies[0].velocity.x, nao::kMaxForward / std::sqrt(2.0), 1e-9) << "a combined request stays within the walk's ellipsoid";
	EXPECT_NEAR(diagonal.bodies[0].velocity.y, nao::kMaxSideways / std::sqrt(2.0), 1e-9);
}

TEST(Walk, WalkToReachesARelativeTarget) {
	World world = OneRobot(1, {1, 1, kPi / 2});
	kse::robot::MotionCommands commands;
	commands.walk_to = true;
	commands.to_x = 1.0f;  // one metre ahead: +y on the field
	commands.to_y = 0;
	commands.to_theta = 0;
	world.bodies[0].Command(commands);
	Advance(world, 10);
	EXPECT_NEAR(world.bodies[0].pose.x, 1.0, 0.05);
	EXPECT_NEAR(world.bodies[0].pose.y, 2.0, 0.05);
}

TEST(Goalkeeper, ADiveCoversTheSideItFallsTo) {
	auto shot = [](bool dive) {
		World world = OneRobot(1, {-4.2, 0, 0});
		world.ball = Ball{{-3.0, 0.5}, {-2.0, 0}};
		if (dive) world.bodies[0].Command(Action("goalieLeft"));
		Advance(world, 3);
		return world.ball.position;
	};
	EXPECT_TRUE(field::InGoal(shot(false), -1)) << "a standing goalkeeper does not reach 0.5 m";
	const Vec2 saved = shot(true);
	EXPECT_FALSE(field::InGoal(saved, -1));
	EXPECT_GT(saved.x, -4.2) << "the ball bounced off the lying goalkeeper";

	World world = OneRobot();
	world.bodies[0].Command(Action("goalieRight"));
	Advance(world, 0.2);
	EXPECT_NEAR(world.bodies[0].DiveExtent(), 0.5 * nao::kDiveReach, 0.03);
	Advance(world, 0.3);
	EXPECT_NEAR(world.bodies[0].DiveExtent(), nao::kDiveReach, 1e-9);
	Advance(world, 3.6);
	EXPECT_EQ(world.bodies[0].motion, Motion::Stand) << "up again after the dive";
}

TEST(Bodies, RobotsDoNotWalkThroughEachOther) {
	World world{Random(5)};
	Body a, b;
	a.pose = {-1, 0, 0};
	b.pose = {1, 0, kPi};
	world.bodies = {a, b};
	world.bodies[0].Command(Walk(1, 0, 0));
	world.bodies[1].Command(Walk(1, 0, 0));
	for (int i = 0; i < 1500; ++i) {
		world.Step(kDt);
		ASSERT_GE((world.bodies[0].pose.Position() - world.bodies[1].pose.Position()).Norm(), 2 * nao::kBodyRadius - 0.01);
	}
	EXPECT_TRUE(world.bodies[0].pushing_time > 0 || world.bodies[1].pushing_time > 0 || world.bodies[0].Fallen() || world.bodies[1].Fallen())
	    << "walking into each other is pushing, and pushing makes robots fall";
}

TEST(Determinism, TheSameSeedAndCommandsGiveTheSameWorld) {
	auto play = [](std::uint64_t seed) {
		World world{Random(seed)};
		for (int i = 0; i < 4; ++i) {
			Body body;
			body.pose = {-2.0 + i, 0.3 * i, 0};
			world.bodies.push_back(body);
		}
		world.ball.position = {0.13, 0.04};
		for (int step = 0; step < 3000; ++step) {
			for (std::size_t i = 0; i < world.bodies.size(); ++i) {
				world.bodies[i].Command(Walk(1, 0.2f * static_cast<float>(i) - 0.3f, 0.1f));
			}
			if (step == 5) world.bodies[2].Command(Action("KickForwardLeft"));
			world.Step(kDt);
		}
		std::vector<double> state{world.ball.position.x, world.ball.position.y};
		for (const auto& body : world.bodies) {
			state.push_back(body.pose.x);
			state.push_back(body.pose.y);
			state.push_back(body.pose.theta);
		}
		return state;
	};
	EXPECT_EQ(play(11), play(11));
}
