// The robot bridge: perception reaches the statechart as the standard messages, and what
// activities command comes back as motion commands.
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include <kse/messages/all.h>
#include <kse/robot/Robot.h>
#include <statechart_engine/Factories.h>
#include <statechart_engine/Statechart.h>
#include <statechart_engine/TimeoutAction.h>

using namespace std::chrono_literals;
using kse::messaging::Kind;

namespace {

// Echoes what it reads into motion: walk (ball x, ball y, player state), head (my x, ready
// x), and an action naming the HeadToBMessage it saw.
class Echo : public statechart_engine::IActivity {
public:
	void UserInit() override {
		_blk->Subscribe("worldstate");
		_blk->Subscribe("behavior");
	}
	int Execute() override {
		_blk->ProcessMessages();
		const auto game = _blk->ReadState<GameStateMessage>("worldstate");
		const auto world = _blk->ReadData<WorldInfo>("worldstate");
		const auto head = _blk->ReadState<HeadToBMessage>("behavior");
		const auto position = _blk->ReadState<PositionMessage>("behavior");
		MotionWalkMessage walk;
		walk.set_command("setWalkTargetVelocity");
		walk.add_parameter(world && world->balls_size() ? world->balls(0).relativex() : -1.0f);
		walk.add_parameter(world && world->balls_size() ? world->balls(0).relativey() : -1.0f);
		walk.add_parameter(game ? static_cast<float>(game->player_state()) : -1.0f);
		_blk->Publish("motion", Kind::Signal, walk);
		MotionHeadMessage look;
		look.set_command("setHead");
		look.add_parameter(world ? world->myposition().x() : -1.0f);
		look.add_parameter(position ? position->posx() : -1.0f);
		_blk->Publish("motion", Kind::Signal, look);
		MotionActionMessage action;
		action.set_command(head && head->ballfound() ? "seen" : "unseen");
		_blk->Publish("motion", Kind::Signal, action);
		return 0;
	}
	std::string GetName() override { return "Echo"; }
};

// START -> Echo, and Echo loops once per 10 ms of clock.
class EchoChart : public statechart_engine::IStatechart {
public:
	EchoChart(kse::messaging::MessageHub& hub, const statechart_engine::Options& options) : chart_("Node_echo", hub, options) {
		using namespace statechart_engine;
		auto* start = chart_.Add<StartState>("Node_0_1", &chart_);
		auto* echo = chart_.Add<BasicState>("Node_Echo", &chart_, std::make_unique<Echo>());
		chart_.AddTransition(start, echo, nullptr, std::make_unique<TimeoutAction>("tick", 10));
		chart_.AddTransition(echo, echo, std::make_unique<TimeoutCondition>("tick"), std::make_unique<TimeoutAction>("tick", 10));
	}
	void Start() override { chart_.Start(); }
	void Stop() override { chart_.Stop(); }
	statechart_engine::Statechart& Chart() override { return chart_; }

private:
	statechart_engine::Statechart chart_;
};

const statechart_engine::StatechartRegistrar<EchoChart> registrar("EchoChart");

kse::robot::Perception Playing() {
	kse::robot::Perception perception;
	perception.player_state = 3;
	perception.estimate = {1.5f, -0.5f, 0.2f};
	perception.confidence = 0.8f;
	perception.ball = {true, 0.7f, -0.1f, 0.0f, 0.0f};
	perception.ready_position = {-2.0f, 1.0f, 0.0f};
	return perception;
}

TEST(Robot, PerceptionReachesTheStatechartAsMessages) {
	kse::messaging::ManualClock clock;
	kse::robot::Robot robot("EchoChart", clock);
	clock.Advance(20ms);
	const auto commands = robot.Step(Playing());
	ASSERT_TRUE(commands.walk);
	EXPECT_FLOAT_EQ(commands.vx, 0.7f);
	EXPECT_FLOAT_EQ(commands.vy, -0.1f);
	EXPECT_FLOAT_EQ(commands.vtheta, 3.0f);
	ASSERT_TRUE(commands.head);
	EXPECT_FLOAT_EQ(commands.yaw, 1.5f);
	EXPECT_FLOAT_EQ(commands.pitch, -2.0f);
	ASSERT_EQ(commands.actions.size(), 1u);
	EXPECT_EQ(commands.actions[0], "seen");
}

TEST(Robot, EachCycleGivesTheCommandsOfThatCycleOnly) {
	kse::messaging::ManualClock clock;
	kse::robot::Robot robot("EchoChart", clock);
	auto perception = Playing();
	clock.Advance(20ms);
	robot.Step(perception);
	perception.ball.seen = false;
	clock.Advance(20ms);
	auto commands = robot.Step(perception);
	ASSERT_EQ(commands.actions.size(), 1u);
	EXPECT_EQ(commands.actions[0], "unseen");
	EXPECT_FLOAT_EQ(commands.vx, -1.0f) << "no ball in WorldInfo when it is not seen";
	commands = robot.Step(perception);  // no time passed: the loop does not run again
	EXPECT_FALSE(commands.walk);
	EXPECT_TRUE(commands.actions.empty());
}

TEST(Robot, AnUnknownBehaviourIsRefused) {
	kse::messaging::ManualClock clock;
	EXPECT_THROW(kse::robot::Robot("NoSuchBehaviour", clock), std::invalid_argument);
}

}  // namespace
