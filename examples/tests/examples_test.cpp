// The example behaviours with their hand-written activities, driven by scripted worlds
// (no simulator): what they command is read from the motion topic.
#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <kse/behavior/BehaviorConst.h>
#include <kse/messages/all.h>
#include <kse/messaging/Blackboard.h>
#include <kse/messaging/Clock.h>
#include <kse/messaging/MessageHub.h>
#include <statechart_engine/Factories.h>
#include <statechart_engine/Statechart.h>

using kse::messaging::Kind;
using namespace std::chrono_literals;

namespace {

class Behaviour {
public:
	explicit Behaviour(const std::string& name) : motion_(hub_) {
		motion_.Subscribe("motion");
		statechart_engine::Options options;
		options.inline_activities = true;
		chart_ = statechart_engine::StatechartFactory::Instance().Create(name, hub_, options);
		chart_->Chart().SetObserver([this](const statechart_engine::TransitionSegmentBase& transition) {
			entered_.push_back(transition.Target()->Name());
		});
		// activate first: Data reaches only blackboards already subscribed
		chart_->Chart().Activate();
	}

	void Playing(int state = PLAYER_PLAYING) {
		auto game = std::make_shared<GameStateMessage>();
		game->set_player_state(state);
		hub_.Publish("worldstate", Kind::State, game);
	}

	// The robot at (x, y) facing +x; the ball at (bx, by) relative to it, moving (vx, vy).
	void World(float x, float y, bool ball, float bx = 0, float by = 0, float vx = 0, float vy = 0) {
		auto info = std::make_shared<WorldInfo>();
		info->mutable_myposition()->set_x(x);
		info->mutable_myposition()->set_y(y);
		info->mutable_myposition()->set_confidence(0.9f);
		if (ball) {
			auto* seen = info->add_balls();
			seen->set_relativex(bx);
			seen->set_relativey(by);
			seen->set_relativexspeed(vx);
			seen->set_relativeyspeed(vy);
		}
		hub_.Publish("worldstate", Kind::Data, info);
		auto head = std::make_shared<HeadToBMessage>();
		head->set_ballfound(ball ? 1 : 0);
		hub_.Publish("behavior", Kind::State, head);
	}

	void Run(std::chrono::milliseconds time) {
		for (auto passed = 0ms; passed < time; passed += 50ms) {
			clock_.Advance(50ms);
			chart_->Chart().RunUntilStable();
		}
	}

	bool Entered(const std::string& state) const {
		return std::find(entered_.begin(), entered_.end(), state) != entered_.end();
	}

	std::vector<std::string> Actions() {
		motion_.ProcessMessages();
		std::vector<std::string> commands;
		while (auto action = motion_.ReadSignal<MotionActionMessage>("motion")) commands.push_back(action->command());
		return commands;
	}

	std::shared_ptr<const MotionWalkMessage> LastWalk() {
		motion_.ProcessMessages();
		std::shared_ptr<const MotionWalkMessage> last;
		while (auto walk = motion_.ReadSignal<MotionWalkMessage>("motion")) last = walk;
		return last;
	}

	int HeadCommands() {
		motion_.ProcessMessages();
		int count = 0;
		while (motion_.ReadSignal<MotionHeadMessage>("motion")) ++count;
		return count;
	}

	statechart_engine::Statechart& Chart() { return chart_->Chart(); }

	std::string Trace() const {
		std::string trace = "entered:";
		for (const auto& state : entered_) trace += " " + state;
		trace += "\nactive:";
		for (const auto& state : chart_->Chart().ActiveStates()) trace += " " + state;
		return trace;
	}

private:
	kse::messaging::ManualClock clock_;
	kse::messaging::MessageHub hub_{clock_};
	kse::messaging::Blackboard motion_;
	std::unique_ptr<statechart_engine::IStatechart> chart_;
	std::vector<std::string> entered_;
};

TEST(Attacker, ScansWithoutABallThenWalksToItAndKicksTowardsTheGoal) {
	Behaviour attacker("Attacker");
	attacker.Playing();
	attacker.World(0, 0, false);
	attacker.Run(600ms);
	EXPECT_TRUE(attacker.Entered("Node_Scan"));
	EXPECT_GT(attacker.HeadCommands(), 1) << "the head sweeps while scanning";

	attacker.World(0, 0, true, 1.0f, 0.2f);
	attacker.Run(400ms);
	EXPECT_TRUE(attacker.Entered("Node_ApproachBall"));
	auto walk = attacker.LastWalk();
	ASSERT_NE(walk, nullptr);
	EXPECT_EQ(walk->command(), "setWalkTargetVelocity");
	EXPECT_GT(walk->parameter(0), 0.5f) << "walks forward to a ball 1 m ahead";

	attacker.Actions();
	attacker.World(0, 0, true, 0.122f, 0.03f);
	attacker.Run(400ms);
	EXPECT_TRUE(attacker.Entered("Node_Kick"));
	const auto actions = attacker.Actions();
	EXPECT_NE(std::find(actions.begin(), actions.end(), "KickForwardLeft"), actions.end()) << "goal ahead, ball on the left foot";
}

TEST(Attacker, StandsStillOutsidePlay) {
	Behaviour attacker("Attacker");
	attacker.Playing(PLAYER_SET);
	attacker.World(-1, 0, true, 1.0f, 0.0f);
	attacker.Run(400ms);
	EXPECT_TRUE(attacker.Entered("Node_NoPlay"));
	EXPECT_FALSE(attacker.Entered("Node_ApproachBall"));
	auto walk = attacker.LastWalk();
	ASSERT_NE(walk, nullptr);
	EXPECT_EQ(walk->parameter(0), 0.0f);
}

TEST(Defender, GuardsWhileTheBallIsFarAndClearsItWhenNear) {
	Behaviour defender("Defender");
	defender.Playing();
	defender.World(-3.0f, 0, true, 3.0f, 0.0f);
	defender.Run(400ms);
	EXPECT_TRUE(defender.Entered("Node_Guard")) << defender.Trace();
	EXPECT_FALSE(defender.Entered("Node_ApproachBall"));

	defender.World(-3.0f, 0, true, 0.5f, 0.1f);
	defender.Run(600ms);
	EXPECT_TRUE(defender.Entered("Node_ApproachBall")) << defender.Trace();
	defender.World(-3.0f, 0, true, 0.122f, -0.03f);
	defender.Run(600ms);
	EXPECT_TRUE(defender.Entered("Node_Kick")) << defender.Trace();
}

TEST(Goalie, DivesTowardsAShotItSeesComing) {
	Behaviour goalie("Goalie");
	goalie.Playing();
	goalie.World(-4.3f, 0, true, 2.5f, 0.2f);
	goalie.Run(600ms);
	EXPECT_TRUE(goalie.Entered("Node_Stare")) << "a far ball is watched\n" << goalie.Trace();
	goalie.Actions();
	goalie.World(-4.3f, 0, true, 1.5f, 0.3f, -2.0f, 0.1f);  // coming fast, crossing at about +0.38 m
	goalie.Run(800ms);
	EXPECT_TRUE(goalie.Entered("Node_SpecialAction")) << goalie.Trace();
	const auto actions = goalie.Actions();
	EXPECT_NE(std::find(actions.begin(), actions.end(), "goalieLeft"), actions.end());
}

TEST(Activities, CommandTheRobotWithoutKeepingTheirCommandsOnTheirOwnBlackboard) {
	// RobotIO publishes to the hub: the robot's blackboard gets every command, the activity's own
	// keeps none of them as unread signals (a thousand of each kind would wait there otherwise).
	Behaviour attacker("Attacker");
	attacker.Playing();
	attacker.World(0, 0, true, 1.0f, 0.2f);
	attacker.Run(400ms);
	ASSERT_TRUE(attacker.Entered("Node_ApproachBall")) << attacker.Trace();
	auto& own = attacker.Chart().RootBlackboard();
	own.ProcessMessages();
	EXPECT_EQ(own.PendingSignals("motion", "MotionWalkMessage"), 0U);
	EXPECT_EQ(own.PendingSignals("motion", "MotionHeadMessage"), 0U);
	EXPECT_EQ(own.ReadSignal<MotionWalkMessage>("motion"), nullptr);
	const auto walk = attacker.LastWalk();
	ASSERT_NE(walk, nullptr) << "the robot's blackboard got the walk";
	EXPECT_EQ(walk->command(), "setWalkTargetVelocity");
	EXPECT_EQ(walk->parameter_size(), 4);

	// a command kept by a reader stays as it was while the activity goes on commanding
	const std::string kept = walk->DebugString();
	attacker.World(0, 0, true, 0.5f, -0.3f);
	attacker.Run(400ms);
	const auto next = attacker.LastWalk();
	ASSERT_NE(next, nullptr);
	EXPECT_NE(next, walk);
	EXPECT_EQ(walk->DebugString(), kept);
}

}  // namespace
