// Every node kind and action kind of the generator, compiled and run: the AND state's
// regions, the publishing action (seen on the hub), the timeouts.
#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

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

TEST(AllKinds, RunsThroughSearchAndTheParallelRegionsAndPublishes) {
	kse::messaging::ManualClock clock;
	kse::messaging::MessageHub hub(clock);
	kse::messaging::Blackboard observer(hub);
	observer.Subscribe("motion");
	statechart_engine::Options options;
	options.inline_activities = true;
	auto chart = statechart_engine::StatechartFactory::Instance().Create("AllKinds", hub, options);
	ASSERT_NE(chart, nullptr);
	auto& engine = chart->Chart();
	engine.Activate();
	engine.RunUntilStable();
	// no HeadToBMessage yet: the connector's first guard (msg == NULL) leads to Search
	EXPECT_TRUE(Active(engine, "Node_Search"));

	auto game = std::make_shared<GameStateMessage>();
	game->set_player_state(PLAYER_READY);
	hub.Publish("worldstate", Kind::State, game);
	engine.RunUntilStable();
	// Search -> END publishes MotionActionMessage("InitPose") on motion as a Signal
	EXPECT_TRUE(Active(engine, "Node_0_5"));
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
	// !ballAway(WorldInfo) is false while no WorldInfo exists: a world without a ball lets it hold
	hub.Publish("worldstate", Kind::Data, std::make_shared<WorldInfo>());
	engine.Activate();
	engine.RunUntilStable();
	EXPECT_TRUE(Active(engine, "Node_Together"));
	EXPECT_TRUE(Active(engine, "Node_0_4_1_3"));  // Track ran and its region ended
	EXPECT_TRUE(Active(engine, "Node_Walk"));     // Walk waits for a confident position
	auto world = std::make_shared<WorldInfo>();
	world->mutable_myposition()->set_confidence(0.9f);
	hub.Publish("worldstate", Kind::Data, world);
	engine.RunUntilStable();
	EXPECT_TRUE(Active(engine, "Node_0_4_2_3"));
}

}  // namespace
