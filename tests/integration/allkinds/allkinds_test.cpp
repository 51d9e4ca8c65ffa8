// Every node kind and action kind of the generator, compiled and run: the AND state's
// regions, the publishing action (seen on the hub), the timeouts.
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

bool Active(statechart_engine::Statechart& chart, const std::string& state) {
	const auto states = chart.ActiveStates();
	return std::find(states.begin(), states.end(), state) != states.end();
}

TEST(AllKinds, SearchesThenLeavesAndPublishes) {
	kse::messaging::ManualClock clock;
	kse::messaging::MessageHub hub(clock);
	kse::messaging::Blackboard observer(hub);
	observer.Subscribe("motion");
	statechart_engine::Options options;
	options.inline_activities = true;
	auto chart = statechart_engine::StatechartFactory::Instance().Create("AllKinds", hub, options);
	ASSERT_NE(chart, nullptr);
	auto& engine = chart->Chart();
	std::vector<std::string> entered;
	engine.SetObserver([&](const statechart_engine::TransitionSegmentBase& segment) { entered.push_back(segment.Target()->Label()); });
	auto game = std::make_shared<GameStateMessage>();
	game->set_player_state(PLAYER_READY);
	hub.Publish("worldstate", Kind::State, game);
	engine.Activate();
	engine.RunUntilStable();
	// No HeadToBMessage: the connector's msg == NULL branch leads to Search, whose activity
	// refreshes the blackboard; then its exit [player_state() != PLAYER_PLAYING] holds, and
	// publishes MotionActionMessage("InitPose") on motion as a Signal.
	EXPECT_EQ(entered, (std::vector<std::string>{"0.2", "0.3", "0.5"}));
	EXPECT_TRUE(Active(engine, "Node_0_5"));
	observer.ProcessMessages();
	auto command = observer.ReadSignal<MotionActionMessage>("motion");
	ASSERT_NE(command, nullptr);
	EXPECT_EQ(command->command(), "InitPose");
}

TEST(AllKinds, ABallLeadsIntoBothRegionsOfTheAndState) {
	kse::messaging::ManualClock clock;
	kse::messaging::MessageHub hub(clock);
	statechart_engine::Options options;
	options.inline_activities = true;
	auto chart = statechart_engine::StatechartFactory::Instance().Create("AllKinds", hub, options);
	auto& engine = chart->Chart();
	auto head = std::make_shared<HeadToBMessage>();
	head->set_ballfound(1);
	hub.Publish("behavior", Kind::State, head);
	engine.Activate();
	// !ballAway(WorldInfo) is false while no WorldInfo exists: a world without a ball lets it
	// hold. The connector decides on the root blackboard's snapshot: refresh it, as an activity
	// of the root's region would have.
	hub.Publish("worldstate", Kind::Data, std::make_shared<WorldInfo>());
	engine.RootBlackboard().ProcessMessages();
	engine.RunUntilStable();
	EXPECT_TRUE(Active(engine, "Node_Together"));
	EXPECT_TRUE(Active(engine, "Node_0_4_1_3"));  // Track ran and its region ended
	EXPECT_TRUE(Active(engine, "Node_Walk"));     // Walk waits for a confident position
	// Walk's exit reads its region's blackboard, refreshed only when Walk runs again; nothing in
	// the model polls, so a confident position alone changes nothing.
	auto world = std::make_shared<WorldInfo>();
	world->mutable_myposition()->set_confidence(0.9f);
	hub.Publish("worldstate", Kind::Data, world);
	clock.Advance(100ms);
	engine.RunUntilStable();
	EXPECT_TRUE(Active(engine, "Node_Walk"));
	const auto states = engine.States();
	const auto walk = std::find_if(states.begin(), states.end(), [](auto* state) { return state->Name() == "Node_Walk"; });
	ASSERT_NE(walk, states.end());
	engine.ScopeOf(*walk)->ProcessMessages();
	EXPECT_TRUE(engine.Step());
	EXPECT_TRUE(Active(engine, "Node_0_4_2_3"));
}

}  // namespace
