#pragma once
// Small statecharts written against the engine for the simulator's own tests (the real
// behaviours live in examples/): a Chaser that walks to the ball and kicks it towards the
// opponent goal, a Runner that chases in a loop with nothing to wait on but its activity, a
// Spinner that loops without even that, a Sleeper whose statechart stops after its first state, and chasers that go
// wrong after a while: a Thrower (throws in every cycle from its second), a Hanger (never
// returns, after 2 s of play) and a Crasher (writes through a null pointer after 3 s).

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include <kse/messages/all.h>
#include <kse/robot/Robot.h>
#include <statechart_engine/Factories.h>
#include <statechart_engine/Statechart.h>
#include <statechart_engine/TimeoutAction.h>

namespace sim_test {

class Chase : public statechart_engine::IActivity {
public:
	void UserInit() override { _blk->Subscribe("worldstate"); }
	int Execute() override {
		_blk->ProcessMessages();
		const auto game = _blk->ReadState<GameStateMessage>("worldstate");
		const auto world = _blk->ReadData<WorldInfo>("worldstate");
		MotionWalkMessage walk;
		walk.set_command("setWalkTargetVelocity");
		float vx = 0, vy = 0, vt = 0;
		if (game && game->player_state() == 3 && world && world->balls_size() > 0) {
			const auto& ball = world->balls(0);
			const auto& me = world->myposition();
			const float goal = std::atan2(-me.y(), 4.5f - me.x()) - me.phi();
			if (std::hypot(ball.relativex() - 0.13f, ball.relativey() - 0.04f) < 0.05f && std::fabs(goal) < 0.5f) {
				MotionActionMessage kick;
				kick.set_command("KickForwardLeft");
				_blk->Publish("motion", kse::messaging::Kind::Signal, kick);
			}
			vx = 3 * (ball.relativex() - 0.13f);
			vy = 3 * (ball.relativey() - 0.04f);
			vt = std::hypot(ball.relativex(), ball.relativey()) < 0.4f ? goal : std::atan2(ball.relativey(), ball.relativex());
		} else if (game && game->player_state() == 3) {
			vt = 0.5f;  // look for the ball
		}
		walk.add_parameter(vx);
		walk.add_parameter(vy);
		walk.add_parameter(vt);
		_blk->Publish("motion", kse::messaging::Kind::Signal, walk);
		MotionHeadMessage head;
		head.set_command("setHead");
		head.add_parameter(0);
		head.add_parameter(0.35f);
		_blk->Publish("motion", kse::messaging::Kind::Signal, head);
		return 0;
	}
	std::string GetName() override { return "Chase"; }
};

class Idle : public statechart_engine::IActivity {
public:
	int Execute() override { return 0; }
	std::string GetName() override { return "Idle"; }
};

// START -> Chase, and Chase again every 100 ms
class ChaserChart : public statechart_engine::IStatechart {
public:
	ChaserChart(kse::messaging::MessageHub& hub, const statechart_engine::Options& options) : chart_("Node_chaser", hub, options) {
		using namespace statechart_engine;
		auto* start = chart_.Add<StartState>("Node_0_1", &chart_);
		auto* chase = chart_.Add<BasicState>("Node_Chase", &chart_, std::make_unique<Chase>());
		chart_.AddTransition(start, chase, nullptr, std::make_unique<TimeoutAction>("tick", 100));
		chart_.AddTransition(chase, chase, std::make_unique<TimeoutCondition>("tick"), std::make_unique<TimeoutAction>("tick", 100));
	}
	void Start() override { chart_.Start(); }
	void Stop() override { chart_.Stop(); }
	statechart_engine::Statechart& Chart() override { return chart_; }

private:
	statechart_engine::Statechart chart_;
};

// START -> Idle, then nothing: a behaviour that is stuck
class SleeperChart : public statechart_engine::IStatechart {
public:
	SleeperChart(kse::messaging::MessageHub& hub, const statechart_engine::Options& options) : chart_("Node_sleeper", hub, options) {
		using namespace statechart_engine;
		auto* start = chart_.Add<StartState>("Node_0_1", &chart_);
		auto* idle = chart_.Add<BasicState>("Node_Idle", &chart_, std::make_unique<Idle>());
		chart_.AddTransition(start, idle);
	}
	void Start() override { chart_.Start(); }
	void Stop() override { chart_.Stop(); }
	statechart_engine::Statechart& Chart() override { return chart_; }

private:
	statechart_engine::Statechart chart_;
};

// A Chase that goes wrong at its n-th run (runs come every 100 ms).
template <class Failure>
class FailingChase : public Chase {
public:
	int Execute() override {
		if (++runs_ >= Failure::kFromRun) Failure::Fail();
		return Chase::Execute();
	}
	std::string GetName() override { return Failure::kName; }

private:
	int runs_ = 0;
};

struct Throws {
	static constexpr int kFromRun = 2;
	static constexpr const char* kName = "Throw";
	static void Fail() { throw std::runtime_error("the ball is not where it should be"); }
};

struct Hangs {
	static constexpr int kFromRun = 20;
	static constexpr const char* kName = "Hang";
	[[noreturn]] static void Fail() {
		for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
	}
};

// Through a pointer the compiler cannot see is null: a real SIGSEGV, not a trap it put there.
inline volatile int* volatile nowhere = nullptr;
struct Crashes {
	static constexpr int kFromRun = 30;
	static constexpr const char* kName = "Crash";
	static void Fail() { *nowhere = 1; }
};

// START -> the failing chase, again every 100 ms (as the Chaser)
template <class Failure>
class FailingChart : public statechart_engine::IStatechart {
public:
	FailingChart(kse::messaging::MessageHub& hub, const statechart_engine::Options& options)
		: chart_(std::string("Node_") + Failure::kName, hub, options) {
		using namespace statechart_engine;
		auto* start = chart_.Add<StartState>("Node_0_1", &chart_);
		auto* act = chart_.Add<BasicState>(std::string("Node_") + Failure::kName, &chart_, std::make_unique<FailingChase<Failure>>());
		act->SetLabel("0.2");
		chart_.AddTransition(start, act, nullptr, std::make_unique<TimeoutAction>("tick", 100));
		chart_.AddTransition(act, act, std::make_unique<TimeoutCondition>("tick"), std::make_unique<TimeoutAction>("tick", 100));
	}
	void Start() override { chart_.Start(); }
	void Stop() override { chart_.Stop(); }
	statechart_engine::Statechart& Chart() override { return chart_; }

private:
	statechart_engine::Statechart chart_;
};

// runner = Wake.Chase~ as the formula's transformation makes it: nothing waits in the loop but
// the Chase activity's run (on a robot, its time on a worker).
class RunnerChart : public statechart_engine::IStatechart {
public:
	RunnerChart(kse::messaging::MessageHub& hub, const statechart_engine::Options& options) : chart_("Node_runner", hub, options) {
		using namespace statechart_engine;
		auto* start = chart_.Add<StartState>("Node_0_1", &chart_);
		auto* wake = chart_.Add<BasicState>("Node_Wake", &chart_, std::make_unique<Idle>());
		auto* loop = chart_.Add<OrState>("Node_0_3", &chart_);
		auto* loop_start = chart_.Add<StartState>("Node_0_3_1", loop);
		auto* chase = chart_.Add<BasicState>("Node_Chase", loop, std::make_unique<Chase>());
		auto* again = chart_.Add<ConditionConnector>("Node_0_3_3", loop);
		chart_.AddTransition(start, wake);
		chart_.AddTransition(wake, loop);
		chart_.AddTransition(loop_start, chase);
		chart_.AddTransition(chase, again);
		chart_.AddTransition(again, chase);
	}
	void Start() override { chart_.Start(); }
	void Stop() override { chart_.Stop(); }
	statechart_engine::Statechart& Chart() override { return chart_; }

private:
	statechart_engine::Statechart chart_;
};

// START -> Look, then round Look and a connector for ever: no activity, no timer, nothing waits.
class SpinnerChart : public statechart_engine::IStatechart {
public:
	SpinnerChart(kse::messaging::MessageHub& hub, const statechart_engine::Options& options) : chart_("Node_spinner", hub, options) {
		using namespace statechart_engine;
		auto* start = chart_.Add<StartState>("Node_0_1", &chart_);
		auto* look = chart_.Add<BasicState>("Node_Look", &chart_);
		auto* decide = chart_.Add<ConditionConnector>("Node_0_3", &chart_);
		look->SetLabel("0.2");
		decide->SetLabel("0.3");
		chart_.AddTransition(start, look);
		chart_.AddTransition(look, decide);
		chart_.AddTransition(decide, look);
	}
	void Start() override { chart_.Start(); }
	void Stop() override { chart_.Stop(); }
	statechart_engine::Statechart& Chart() override { return chart_; }

private:
	statechart_engine::Statechart chart_;
};

// A chaser with labels, a nested state and two transitions between the same pair of states
// (the same name, told apart only by their index): what the live monitor's records are tested on.
//   0.1 -> 0.2 /tock 250;  0.2 = { 0.2.1 -> 0.2.2 /tick 100;  0.2.2 -> 0.2.2 [tick]/tick 100;  0.2.2 -> 0.2.2 [tock]/tock 250 }
class PatrollerChart : public statechart_engine::IStatechart {
public:
	PatrollerChart(kse::messaging::MessageHub& hub, const statechart_engine::Options& options) : chart_("Node_patroller", hub, options) {
		using namespace statechart_engine;
		auto* start = chart_.Add<StartState>("Node_0_1", &chart_);
		auto* patrol = chart_.Add<OrState>("Node_patrol", &chart_);
		auto* patrol_start = chart_.Add<StartState>("Node_0_2_1", patrol);
		auto* chase = chart_.Add<BasicState>("Node_Chase", patrol, std::make_unique<Chase>());
		chart_.Root()->SetLabel("0");
		start->SetLabel("0.1");
		patrol->SetLabel("0.2");
		patrol_start->SetLabel("0.2.1");
		chase->SetLabel("0.2.2");
		chart_.AddTransition(start, patrol, nullptr, std::make_unique<TimeoutAction>("tock", 250));
		chart_.AddTransition(patrol_start, chase, nullptr, std::make_unique<TimeoutAction>("tick", 100));
		// the expressions a model would have written, as generated code gives them to the monitor
		chart_.AddTransition(chase, chase, std::make_unique<TimeoutCondition>("tick"), std::make_unique<TimeoutAction>("tick", 100))
			->SetText("[TimeoutCheck(tick)]/TimeoutAction.tick.100");
		chart_.AddTransition(chase, chase, std::make_unique<TimeoutCondition>("tock"), std::make_unique<TimeoutAction>("tock", 250))
			->SetText("[TimeoutCheck(tock)]/TimeoutAction.tock.250");
	}
	void Start() override { chart_.Start(); }
	void Stop() override { chart_.Stop(); }
	statechart_engine::Statechart& Chart() override { return chart_; }

private:
	statechart_engine::Statechart chart_;
};

inline const statechart_engine::StatechartRegistrar<ChaserChart> chaser_registrar("Chaser");
inline const statechart_engine::StatechartRegistrar<PatrollerChart> patroller_registrar("Patroller");
inline const statechart_engine::StatechartRegistrar<RunnerChart> runner_registrar("Runner");
inline const statechart_engine::StatechartRegistrar<SpinnerChart> spinner_registrar("Spinner");
inline const statechart_engine::StatechartRegistrar<FailingChart<Throws>> thrower_registrar("Thrower");
inline const statechart_engine::StatechartRegistrar<FailingChart<Hangs>> hanger_registrar("Hanger");
inline const statechart_engine::StatechartRegistrar<FailingChart<Crashes>> crasher_registrar("Crasher");
inline const statechart_engine::StatechartRegistrar<SleeperChart> sleeper_registrar("Sleeper");

}  // namespace sim_test
