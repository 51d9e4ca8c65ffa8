// Transitions per second of the legacy Goalie (generated, no-op activities run inline),
// driven through a game: playing without a ball, a far ball, a ball at the kicking spot,
// READY, each with time passing so the 250 ms loops fire.
#include <chrono>
#include <memory>

#include <benchmark/benchmark.h>

#include <kse/behavior/BehaviorConst.h>
#include <kse/messages/all.h>
#include <kse/messaging/Clock.h>
#include <kse/messaging/MessageHub.h>
#include <statechart_engine/Factories.h>
#include <statechart_engine/Statechart.h>

using kse::messaging::Kind;
using namespace std::chrono_literals;

static void GoalieThroughAGame(benchmark::State& state) {
	kse::messaging::ManualClock clock;
	kse::messaging::MessageHub hub(clock);
	statechart_engine::Options options;
	options.inline_activities = true;
	auto goalie = statechart_engine::StatechartFactory::Instance().Create("Goalie", hub, options);
	auto& chart = goalie->Chart();
	chart.Activate();
	auto game = std::make_shared<GameStateMessage>();
	auto head = std::make_shared<HeadToBMessage>();
	auto far = std::make_shared<WorldInfo>();
	far->add_balls()->set_relativex(2.0f);
	auto spot = std::make_shared<WorldInfo>();
	auto* ball = spot->add_balls();
	ball->set_relativex(0.122f);
	ball->set_relativey(0.03f);
	const std::size_t before = chart.TransitionsTaken();
	int phase = 0;
	for (auto _ : state) {
		switch (phase++ % 4) {
			case 0: game->set_player_state(PLAYER_PLAYING); head->set_ballfound(0); break;
			case 1: head->set_ballfound(1); hub.Publish("worldstate", Kind::Data, far); break;
			case 2: hub.Publish("worldstate", Kind::Data, spot); break;
			default: game->set_player_state(PLAYER_READY); break;
		}
		hub.Publish("worldstate", Kind::State, std::make_shared<GameStateMessage>(*game));
		hub.Publish("behavior", Kind::State, std::make_shared<HeadToBMessage>(*head));
		for (int tick = 0; tick < 8; ++tick) {
			clock.Advance(50ms);
			chart.RunUntilStable();
		}
	}
	state.SetItemsProcessed(static_cast<int64_t>(chart.TransitionsTaken() - before));
	state.counters["transitions/round"] = benchmark::Counter(static_cast<double>(chart.TransitionsTaken() - before) / static_cast<double>(state.iterations()));
}
BENCHMARK(GoalieThroughAGame);

BENCHMARK_MAIN();
