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

// Subscribes the statechart's blackboard to what a robot publishes and never refreshes it, so
// that a test sees exactly what arrived in its inbox.
class Listen : public statechart_engine::IActivity {
public:
	void UserInit() override {
		_blk->Subscribe("worldstate");
		_blk->Subscribe("behavior");
	}
	int Execute() override { return 0; }
	std::string GetName() override { return "Listen"; }
};

class ListenerChart : public statechart_engine::IStatechart {
public:
	ListenerChart(kse::messaging::MessageHub& hub, const statechart_engine::Options& options) : chart_("Node_listener", hub, options) {
		using namespace statechart_engine;
		auto* start = chart_.Add<StartState>("Node_0_1", &chart_);
		auto* listen = chart_.Add<BasicState>("Node_Listen", &chart_, std::make_unique<Listen>());
		chart_.AddTransition(start, listen);
	}
	void Start() override { chart_.Start(); }
	void Stop() override { chart_.Stop(); }
	statechart_engine::Statechart& Chart() override { return chart_; }

private:
	statechart_engine::Statechart chart_;
};

const statechart_engine::StatechartRegistrar<ListenerChart> listener_registrar("RobotTestListener");

kse::robot::Perception InGame() {
	kse::robot::Perception p;
	p.player_state = 3;
	p.game_state = 3;
	p.team_number = 7;
	p.player_number = 2;
	p.secs_remaining = 600;
	p.estimate = {1.0f, -2.0f, 0.5f};
	p.ready_position = {-3.0f, 1.0f, 0.0f};
	return p;
}

TEST(Robot, StateMessagesArePublishedWhenTheyChangeAndWorldInfoEveryCycle) {
	kse::messaging::ManualClock clock;
	kse::robot::Robot robot("RobotTestListener", clock);
	auto& board = robot.Chart().RootBlackboard();
	kse::robot::Perception p = InGame();
	robot.Step(p);
	EXPECT_EQ(board.PendingMessages(), 4U) << "the first cycle: GameStateMessage, WorldInfo, HeadToBMessage, PositionMessage";
	board.ProcessMessages();
	EXPECT_EQ(board.ReadState<GameStateMessage>("worldstate")->secs_remaining(), 600);
	EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), 0);
	EXPECT_FLOAT_EQ(board.ReadState<PositionMessage>("behavior")->posx(), -3.0f);

	p.estimate.x = 1.5f;
	robot.Step(p);
	EXPECT_EQ(board.PendingMessages(), 1U) << "only the WorldInfo: no State message changed";
	board.ProcessMessages();
	EXPECT_FLOAT_EQ(board.ReadData<WorldInfo>("worldstate")->myposition().x(), 1.5f);
	EXPECT_EQ(board.ReadState<GameStateMessage>("worldstate")->secs_remaining(), 600) << "a State message stands";

	p.secs_remaining = 599;
	p.ball.seen = true;
	p.ball.x = 0.4f;
	robot.Step(p);
	EXPECT_EQ(board.PendingMessages(), 3U) << "GameStateMessage and HeadToBMessage changed";
	board.ProcessMessages();
	EXPECT_EQ(board.ReadState<GameStateMessage>("worldstate")->secs_remaining(), 599);
	EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), 1);
	ASSERT_EQ(board.ReadData<WorldInfo>("worldstate")->balls_size(), 1);
	EXPECT_FLOAT_EQ(board.ReadData<WorldInfo>("worldstate")->balls(0).relativex(), 0.4f);

	p.ready_position.y = -1.0f;
	robot.Step(p);
	EXPECT_EQ(board.PendingMessages(), 2U) << "PositionMessage changed";
	board.ProcessMessages();
	EXPECT_FLOAT_EQ(board.ReadState<PositionMessage>("behavior")->posy(), -1.0f);
}

TEST(Robot, WorldInfoMessagesInTheHistoryKeepTheirValuesWhileTheRobotReusesOldOnes) {
	// The robot reuses a WorldInfo once nobody else holds it: what a blackboard still keeps
	// (the Data history of 100) must never change under it.
	kse::messaging::ManualClock clock;
	kse::robot::Robot robot("RobotTestListener", clock);
	auto& board = robot.Chart().RootBlackboard();
	kse::robot::Perception p = InGame();
	std::shared_ptr<const WorldInfo> kept;
	for (int cycle = 0; cycle < 400; ++cycle) {
		p.estimate.x = static_cast<float>(cycle);
		p.ball.seen = cycle % 3 == 0;
		p.ball.x = static_cast<float>(cycle);
		robot.Step(p);
		clock.Advance(std::chrono::milliseconds(30));
		if (cycle % 7 == 0) board.ProcessMessages();  // a statechart refreshes now and then
		if (cycle == 150) {
			board.ProcessMessages();
			kept = board.ReadData<WorldInfo>("worldstate");  // held by a reader for the rest of the test
		}
	}
	board.ProcessMessages();
	const auto history = board.ReadDataHistory<WorldInfo>("worldstate", kse::messaging::TimePoint{});
	ASSERT_EQ(history.size(), kse::messaging::Blackboard::kDataHistoryLimit);
	for (std::size_t i = 0; i < history.size(); ++i) {
		const int cycle = 300 + static_cast<int>(i);
		const WorldInfo& info = *history[i].message;
		EXPECT_FLOAT_EQ(info.myposition().x(), static_cast<float>(cycle));
		ASSERT_EQ(info.balls_size(), cycle % 3 == 0 ? 1 : 0) << "cycle " << cycle;
		if (cycle % 3 == 0) EXPECT_FLOAT_EQ(info.balls(0).relativex(), static_cast<float>(cycle));
	}
	ASSERT_NE(kept, nullptr);
	EXPECT_FLOAT_EQ(kept->myposition().x(), 150.0f) << "a message someone holds is not reused";
	ASSERT_EQ(kept->balls_size(), 1);
	EXPECT_FLOAT_EQ(kept->balls(0).relativex(), 150.0f);
}

TEST(Robot, AWorldInfoUsedAgainIsTheMessageANewOneWouldBe) {
	// A reused WorldInfo is written over, not cleared first: whatever it said before (a ball,
	// then none, then one again) must not show, byte for byte and field by field.
	kse::messaging::ManualClock clock;
	kse::robot::Robot robot("RobotTestListener", clock);
	auto& board = robot.Chart().RootBlackboard();
	kse::robot::Perception p = InGame();
	for (int cycle = 0; cycle < 500; ++cycle) {
		p.estimate = {0.01f * cycle, -0.02f * cycle, 0.003f * cycle};
		p.confidence = cycle % 4 == 0 ? 0.0f : 0.25f * (cycle % 4);
		p.ball.seen = (cycle / 5) % 3 != 0;  // runs of cycles with and without a ball
		p.ball.x = 0.1f * cycle;
		p.ball.y = cycle % 2 == 0 ? 0.0f : -0.5f;
		p.ball.vx = -0.01f * cycle;
		p.ball.vy = 0.0f;
		robot.Step(p);
		clock.Advance(std::chrono::milliseconds(30));
		board.ProcessMessages();
		WorldInfo expected;
		auto* me = expected.mutable_myposition();
		me->set_x(p.estimate.x);
		me->set_y(p.estimate.y);
		me->set_phi(p.estimate.theta);
		me->set_confidence(p.confidence);
		if (p.ball.seen) {
			auto* ball = expected.add_balls();
			ball->set_relativex(p.ball.x);
			ball->set_relativey(p.ball.y);
			ball->set_relativexspeed(p.ball.vx);
			ball->set_relativeyspeed(p.ball.vy);
		}
		const auto published = board.ReadData<WorldInfo>("worldstate");
		ASSERT_NE(published, nullptr);
		ASSERT_EQ(published->SerializeAsString(), expected.SerializeAsString()) << "cycle " << cycle;
		ASSERT_EQ(published->DebugString(), expected.DebugString()) << "cycle " << cycle;
		ASSERT_EQ(published->has_myposition(), true);
		if (p.ball.seen) {
			EXPECT_FALSE(published->balls(0).has_absolutex()) << "cycle " << cycle << ": never set by the robot";
			EXPECT_FALSE(published->balls(0).has_confidence()) << "cycle " << cycle;
		}
	}
}

}  // namespace
