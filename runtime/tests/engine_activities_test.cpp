// BASIC states and their activities, inline and on the worker pool; the regions' running flags;
// END; failing activities.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_support.h"

namespace kse_test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

class Activities : public ::testing::TestWithParam<bool> {
 protected:
  bool Inlined() const { return GetParam(); }
  Options Mode() const { return Inlined() ? Inline() : Pooled(); }

  ManualClock clock;
  MessageHub hub{clock};
  Log log;
};

INSTANTIATE_TEST_SUITE_P(Modes, Activities, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& mode) {
                           return mode.param ? "Inline" : "Pooled";
                         });

TEST_P(Activities, ActivityRunsOncePerEntry) {
  Statechart chart("Root", hub, Mode());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto runs = Counter();
  auto* x = chart.Add<BasicState>("X", &chart, std::make_unique<CountingActivity>(runs));
  auto* y = chart.Add<BasicState>("Y", &chart);
  chart.AddTransition(start, x);
  chart.AddTransition(x, y, Never());
  chart.RunUntilStable();
  for (int i = 0; i < 5; ++i) {
    chart.Step();
  }
  chart.RunUntilStable();
  EXPECT_EQ(runs->load(), 1);
  EXPECT_EQ(chart.Launches(x), 1U);
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "X"));
}

TEST_P(Activities, SelfLoopRunsTheActivityAgain) {
  Statechart chart("Root", hub, Mode());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto runs = Counter();
  auto* x = chart.Add<BasicState>("X", &chart, std::make_unique<CountingActivity>(runs));
  auto* end = chart.Add<EndState>("Root_3", &chart);
  chart.AddTransition(start, x);
  // x+ : loop while fewer than 3 runs, then leave.
  chart.AddTransition(x, x, If([runs](Blackboard&) { return runs->load() < 3; }));
  chart.AddTransition(x, end);
  chart.RunUntilStable();
  EXPECT_EQ(runs->load(), 3);
  EXPECT_EQ(chart.Launches(x), 3U);
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Root_3"));
}

TEST_P(Activities, ActivityUsesTheBlackboardOfItsScope) {
  Statechart chart("Root", hub, Mode());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  class Publisher : public IActivity {
   public:
    int Execute() override {
      HeadToBMessage message;
      message.set_ballfound(7);
      _blk->Publish("behavior", Kind::State, message);
      return 0;
    }
    void UserInit() override { _blk->Subscribe("behavior"); }
    std::string GetName() override { return "Publisher"; }
  };
  auto* x = chart.Add<BasicState>("X", &chart, std::make_unique<Publisher>());
  auto* seen = chart.Add<BasicState>("Seen", &chart);
  chart.AddTransition(start, x);
  chart.AddTransition(x, seen, If([](Blackboard& blk) {
                        auto m = blk.ReadState<HeadToBMessage>("behavior");
                        return m != nullptr && m->ballfound() == 7;
                      }));
  chart.RunUntilStable();
  EXPECT_EQ(chart.ActivityOf(x)->GetBlackboard(), &chart.RootBlackboard());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Seen"));
}

TEST_P(Activities, ThrowingActivityIsCountedAndTheEngineKeepsGoing) {
  Statechart chart("Root", hub, Mode());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* bad = chart.Add<BasicState>("Bad", &chart, std::make_unique<ThrowingActivity>());
  auto runs = Counter();
  auto* good = chart.Add<BasicState>("Good", &chart, std::make_unique<CountingActivity>(runs));
  chart.AddTransition(start, bad);
  chart.AddTransition(bad, good);
  ::testing::internal::CaptureStderr();
  chart.RunUntilStable();
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(chart.ActivityFailures(), 1U);
  EXPECT_EQ(runs->load(), 1);
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Good"));
  EXPECT_THAT(err, HasSubstr("activity 'Throwing' of state 'Bad' threw"));
  EXPECT_THAT(err, HasSubstr("activity failure for the test"));
}

TEST_P(Activities, NullActivityFinishesAtOnce) {
  Statechart chart("Root", hub, Mode());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  ::testing::internal::CaptureStderr();
  auto* x = chart.Add<BasicState>("X", &chart, ActivityFactory::Instance().Create("NoSuchActivity_"));
  EXPECT_THAT(::testing::internal::GetCapturedStderr(), HasSubstr("unknown activity 'NoSuchActivity_'"));
  EXPECT_EQ(chart.ActivityOf(x), nullptr);
  auto* y = chart.Add<BasicState>("Y", &chart);
  chart.AddTransition(start, x);
  chart.AddTransition(x, y);
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Y"));
  EXPECT_EQ(chart.ActivityFailures(), 0U);
}

TEST_P(Activities, UserInitRunsOnceForEveryPartBeforeTheFirstStep) {
  struct Counts {
    std::atomic<int> activity{0}, condition{0}, action{0};
  };
  auto counts = std::make_shared<Counts>();
  class A : public IActivity {
   public:
    explicit A(std::shared_ptr<Counts> c) : c_(std::move(c)) {}
    void UserInit() override { ++c_->activity; }
    int Execute() override { return 0; }
    std::string GetName() override { return "A"; }
    std::shared_ptr<Counts> c_;
  };
  class C : public ICondition {
   public:
    explicit C(std::shared_ptr<Counts> c) : c_(std::move(c)) {}
    void UserInit() override {
      ++c_->condition;
      _blk->Subscribe("worldstate");
    }
    bool Eval() override { return true; }
    std::shared_ptr<Counts> c_;
  };
  class Act : public IAction {
   public:
    explicit Act(std::shared_ptr<Counts> c) : c_(std::move(c)) {}
    void UserInit() override { ++c_->action; }
    void Execute() override {}
    std::shared_ptr<Counts> c_;
  };
  Statechart chart("Root", hub, Mode());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* x = chart.Add<BasicState>("X", &chart, std::make_unique<A>(counts));
  chart.AddTransition(start, x, std::make_unique<C>(counts), std::make_unique<Act>(counts));
  chart.Activate();
  EXPECT_EQ(counts->activity.load(), 1);
  EXPECT_EQ(counts->condition.load(), 1);
  EXPECT_EQ(counts->action.load(), 1);
  EXPECT_TRUE(chart.RootBlackboard().IsSubscribed("worldstate"));
  chart.RunUntilStable();
  chart.Activate();
  EXPECT_EQ(counts->activity.load(), 1);
}

// -- pooled only ---------------------------------------------------------------------------

class PooledActivities : public ::testing::Test {
 protected:
  ManualClock clock;
  MessageHub hub{clock};
};

TEST_F(PooledActivities, TransitionsLeavingABusyStateAreNotTried) {
  Statechart chart("Root", hub, Pooled());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto gate = std::make_shared<Gate>();
  auto started = Counter();
  auto* x = chart.Add<BasicState>("X", &chart, std::make_unique<BlockingActivity>(gate, started));
  auto* y = chart.Add<BasicState>("Y", &chart);
  auto evals = Counter();
  chart.AddTransition(start, x);
  chart.AddTransition(x, y, When(Flag(true), evals));

  chart.Activate();
  ASSERT_TRUE(chart.Step());
  ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }));
  EXPECT_TRUE(chart.IsRunning(x));
  EXPECT_EQ(chart.RunningActivities(), 1U);
  for (int i = 0; i < 10; ++i) {
    EXPECT_FALSE(chart.Step());
  }
  EXPECT_EQ(evals->load(), 0);
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "X"));

  gate->Open();
  chart.RunUntilStable();  // waits for the activity, then steps
  EXPECT_EQ(evals->load(), 1);
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Y"));
  EXPECT_FALSE(chart.IsRunning(x));
  EXPECT_EQ(chart.RunningActivities(), 0U);
}

TEST_F(PooledActivities, OtherRegionsKeepSteppingWhileOneActivityRuns) {
  Statechart chart("Root", hub, Pooled(2));
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* both = chart.Add<AndState>("Both", &chart);
  auto* r1 = chart.Add<OrState>("R1", both);
  auto* r1Start = chart.Add<StartState>("R1_1", r1);
  auto gate = std::make_shared<Gate>();
  auto started = Counter();
  auto* slow = chart.Add<BasicState>("Slow", r1, std::make_unique<BlockingActivity>(gate, started));
  auto* r1End = chart.Add<EndState>("R1_3", r1);
  auto* r2 = chart.Add<OrState>("R2", both);
  auto* r2Start = chart.Add<StartState>("R2_1", r2);
  auto* a = chart.Add<BasicState>("A", r2);
  auto* b = chart.Add<BasicState>("B", r2);
  chart.AddTransition(start, both);
  chart.AddTransition(r1Start, slow);
  chart.AddTransition(slow, r1End);
  chart.AddTransition(r2Start, a);
  chart.AddTransition(a, b);

  chart.Activate();
  ASSERT_TRUE(chart.Step());
  ASSERT_TRUE(chart.Step());
  ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }));
  ASSERT_TRUE(chart.Step());  // R2 moves on while Slow runs
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "Slow", "R2", "B"));
  gate->Open();
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "R1_3", "R2", "B"));
}

TEST_F(PooledActivities, ActivitiesRunOnWorkerThreads) {
  Statechart chart("Root", hub, Pooled(1));
  auto* start = chart.Add<StartState>("Root_1", &chart);
  class WhereAmI : public IActivity {
   public:
    explicit WhereAmI(std::thread::id* id) : id_(id) {}
    int Execute() override {
      *id_ = std::this_thread::get_id();
      return 0;
    }
    std::string GetName() override { return "WhereAmI"; }
    std::thread::id* id_;
  };
  std::thread::id ran;
  chart.AddTransition(start, chart.Add<BasicState>("X", &chart, std::make_unique<WhereAmI>(&ran)));
  chart.RunUntilStable();
  EXPECT_NE(ran, std::thread::id());
  EXPECT_NE(ran, std::this_thread::get_id());
}

TEST_F(PooledActivities, InlineModeRunsOnTheCallingThread) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  std::thread::id ran;
  class WhereAmI : public IActivity {
   public:
    explicit WhereAmI(std::thread::id* id) : id_(id) {}
    int Execute() override {
      *id_ = std::this_thread::get_id();
      return 0;
    }
    std::string GetName() override { return "WhereAmI"; }
    std::thread::id* id_;
  };
  chart.AddTransition(start, chart.Add<BasicState>("X", &chart, std::make_unique<WhereAmI>(&ran)));
  chart.RunUntilStable();
  EXPECT_EQ(ran, std::this_thread::get_id());
}

TEST_F(PooledActivities, DestroyingTheChartWaitsForRunningActivities) {
  auto finished = Counter();
  {
    Statechart chart("Root", hub, Pooled());
    auto* start = chart.Add<StartState>("Root_1", &chart);
    chart.AddTransition(start, chart.Add<BasicState>("X", &chart,
                                                     std::make_unique<SleepingActivity>(
                                                         std::chrono::milliseconds(30), finished)));
    chart.Activate();
    ASSERT_TRUE(chart.Step());
  }
  EXPECT_EQ(finished->load(), 1);
}

TEST_F(PooledActivities, ARunningActivityStopsItsWholeRegionOnly) {
  // Root: START -> Both (AND: R1 runs Slow inside a composite with an unguarded exit; R2 goes
  // START -> Quick). While Slow runs, neither the composite's exit nor anything else in R1
  // steps; R2 goes on.
  Statechart chart("Root", hub, Pooled());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* both = chart.Add<AndState>("Both", &chart);
  auto* r1 = chart.Add<OrState>("R1", both);
  auto* r1Start = chart.Add<StartState>("R1_1", r1);
  auto* comp = chart.Add<OrState>("Comp", r1);
  auto* compStart = chart.Add<StartState>("Comp_1", comp);
  auto gate = std::make_shared<Gate>();
  auto started = Counter();
  auto* slow = chart.Add<BasicState>("Slow", comp, std::make_unique<BlockingActivity>(gate, started));
  auto* left = chart.Add<BasicState>("Left", r1);
  auto* r2 = chart.Add<OrState>("R2", both);
  auto* r2Start = chart.Add<StartState>("R2_1", r2);
  auto* quick = chart.Add<BasicState>("Quick", r2);
  chart.AddTransition(start, both);
  chart.AddTransition(r1Start, comp);
  chart.AddTransition(compStart, slow);
  chart.AddTransition(comp, left);
  chart.AddTransition(r2Start, quick);
  chart.RunIfWoken();
  ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }));
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "Comp", "Slow", "R2", "Quick"));
  EXPECT_TRUE(chart.IsRunning(r1));
  EXPECT_FALSE(chart.IsRunning(r2));
  EXPECT_FALSE(chart.IsRunning(chart.Root())) << "the root's own region runs nothing";
  EXPECT_EQ(slow->Region(), r1);
  EXPECT_EQ(comp->Region(), r1);
  EXPECT_EQ(both->Region(), chart.Root());
  EXPECT_FALSE(chart.Step());
  gate->Open();
  ASSERT_TRUE(WaitUntil([&] { return chart.RunningActivities() == 0U; }));
  chart.RunIfWoken();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "Left", "R2", "Quick"));
}

TEST_F(PooledActivities, AStateEnteredAgainWhileItsActivityRunsRunsItAgainAfterwards) {
  // Root: START -> Outer; Outer: START -> Both (AND; R1: START -> Work). While Work runs, R1
  // stands still, but Outer (in the root's region) may move: its transition straight into Work
  // leaves and enters Work again. The one IActivity object is never run twice at once: the
  // second run starts when the first returns, and R1 runs until both are over.
  Statechart chart("Root", hub, Pooled(4));
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* outer = chart.Add<OrState>("Outer", &chart);
  auto* outerStart = chart.Add<StartState>("Outer_1", outer);
  auto* both = chart.Add<AndState>("Both", outer);
  auto* r1 = chart.Add<OrState>("R1", both);
  auto* r1Start = chart.Add<StartState>("R1_1", r1);
  auto gate = std::make_shared<Gate>();
  auto started = Counter();
  auto* work = chart.Add<BasicState>("Work", r1, std::make_unique<BlockingActivity>(gate, started));
  auto once = Counter();
  chart.AddTransition(start, outer);
  chart.AddTransition(outerStart, both);
  chart.AddTransition(r1Start, work);
  chart.AddTransition(outer, work, If([once](Blackboard&) { return once->fetch_add(1) == 0; }));
  while (chart.Step()) {
  }
  ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }));
  EXPECT_EQ(once->load(), 2) << "tried twice: fired once, then false";
  EXPECT_EQ(chart.Launches(work), 2U);
  EXPECT_TRUE(chart.IsRunning(r1));
  EXPECT_EQ(chart.RunningActivities(), 2U);
  gate->Open();
  ASSERT_TRUE(WaitUntil([&] { return chart.RunningActivities() == 0U; }));
  EXPECT_EQ(started->load(), 2);
  EXPECT_FALSE(chart.IsRunning(work));
  EXPECT_FALSE(chart.IsRunning(r1));
}

}  // namespace
}  // namespace kse_test

namespace kse_test {
namespace {

// Options::inline_activities_last_until_next_run, as the simulated robot runs its chart: one
// RunUntilStable() per decision cycle, an activity's run lasting until the next one.
Options OneRunPerCall() {
  Options options = Inline();
  options.inline_activities_last_until_next_run = true;
  return options;
}

TEST(InlineRunsLastACall, AnUnguardedLoopThroughAnActivityGoesOnceRoundPerCall) {
  // runner = Wake.Chase~ : the loop back into Chase has no guard.
  ManualClock clock;
  MessageHub hub{clock};
  Log log;
  Statechart chart("Runner", hub, OneRunPerCall());
  auto* start = chart.Add<StartState>("Runner_1", &chart);
  auto wakes = Counter();
  auto chases = Counter();
  auto* wake = chart.Add<BasicState>("Wake", &chart, std::make_unique<CountingActivity>(wakes, &log, "Wake"));
  auto* chase = chart.Add<BasicState>("Chase", &chart, std::make_unique<CountingActivity>(chases, &log, "Chase"));
  chart.AddTransition(start, wake);
  chart.AddTransition(wake, chase);
  chart.AddTransition(chase, chase);
  ::testing::internal::CaptureStderr();
  EXPECT_TRUE(chart.RunUntilStable(1000));  // enters Wake, which runs
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Runner", "Wake"));
  EXPECT_TRUE(chart.RunUntilStable(1000));  // Wake's run ends: into Chase, which runs
  for (int cycle = 0; cycle < 5; ++cycle) EXPECT_TRUE(chart.RunUntilStable(1000));
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(wakes->load(), 1);
  EXPECT_EQ(chases->load(), 6);  // one run per call after Wake's
  EXPECT_EQ(chart.TransitionsTaken(), 7U);
  EXPECT_EQ(chart.RunningActivities(), 0U);  // nothing to wait for: the runs are over
  EXPECT_EQ(chart.UnsettledLoop(), "");
}

TEST(InlineRunsLastACall, TheTransitionsAreThoseOfAWorkerPool) {
  // x+ then a choice: the same segments in the same order whether a worker runs the activity
  // or the run lasts until the next call; only when differs.
  auto build = [](Statechart& chart, std::shared_ptr<std::atomic<int>> runs) {
    auto* start = chart.Add<StartState>("Root_1", &chart);
    auto* x = chart.Add<BasicState>("X", &chart, std::make_unique<CountingActivity>(runs));
    auto* y = chart.Add<BasicState>("Y", &chart, std::make_unique<CountingActivity>(runs));
    auto* end = chart.Add<EndState>("Root_4", &chart);
    chart.AddTransition(start, x);
    chart.AddTransition(x, x, If([runs](Blackboard&) { return runs->load() < 3; }));
    chart.AddTransition(x, y);
    chart.AddTransition(y, end);
  };
  auto trace = [](Statechart& chart) {
    auto taken = std::make_shared<std::vector<std::string>>();
    chart.SetObserver([taken](const TransitionSegmentBase& segment) {
      taken->push_back(segment.Source()->Name() + "->" + segment.Target()->Name());
    });
    return taken;
  };
  ManualClock clock;
  MessageHub hub{clock};
  Statechart pooled("Root", hub, Pooled());
  build(pooled, Counter());
  auto pooled_trace = trace(pooled);
  pooled.RunUntilStable();
  Statechart cycled("Root", hub, OneRunPerCall());
  build(cycled, Counter());
  auto cycled_trace = trace(cycled);
  std::size_t calls = 0;
  do {
    cycled.RunUntilStable();
    ++calls;
  } while (!HasState(cycled.ActiveStates(), "Root_4") && calls < 100);
  EXPECT_THAT(*pooled_trace, ElementsAre("Root_1->X", "X->X", "X->X", "X->Y", "Y->Root_4"));
  EXPECT_EQ(*cycled_trace, *pooled_trace);
  EXPECT_EQ(calls, 5U);  // four runs of an activity, each over at the next call
}

TEST(InlineRunsLastACall, ARunningRegionWaitsWhileTheOtherRegionSteps) {
  ManualClock clock;
  MessageHub hub{clock};
  Statechart chart("Root", hub, OneRunPerCall());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* both = chart.Add<AndState>("Both", &chart);
  auto* left = chart.Add<OrState>("Left", both);
  auto* right = chart.Add<OrState>("Right", both);
  auto* left_start = chart.Add<StartState>("Left_1", left);
  auto* right_start = chart.Add<StartState>("Right_1", right);
  auto runs = Counter();
  auto* busy = chart.Add<BasicState>("Busy", left, std::make_unique<CountingActivity>(runs));
  auto* after = chart.Add<BasicState>("After", left);
  auto* a = chart.Add<BasicState>("A", right);
  auto* b = chart.Add<BasicState>("B", right);
  chart.AddTransition(start, both);
  chart.AddTransition(left_start, busy);
  chart.AddTransition(busy, after);
  chart.AddTransition(right_start, a);
  chart.AddTransition(a, b);
  chart.RunUntilStable();
  EXPECT_TRUE(HasState(chart.ActiveStates(), "Busy"));  // its run lasts until the next call
  EXPECT_TRUE(HasState(chart.ActiveStates(), "B"));     // the other region went on
  chart.RunUntilStable();
  EXPECT_TRUE(HasState(chart.ActiveStates(), "After"));
}

TEST(InlineRunsLastACall, ALoopWithoutAnActivityIsStoppedAndNamedByItsStates) {
  ManualClock clock;
  MessageHub hub{clock};
  std::vector<EngineReport> reports;
  Options options = OneRunPerCall();
  options.reporter = [&reports](const EngineReport& report) { reports.push_back(report); };
  Statechart chart("Spinner", hub, options);
  auto* start = chart.Add<StartState>("Spinner_1", &chart);
  auto* look = chart.Add<BasicState>("Look", &chart);
  auto* decide = chart.Add<ConditionConnector>("Spinner_3", &chart);
  look->SetLabel("0.2");
  decide->SetLabel("0.3");
  chart.AddTransition(start, look);
  chart.AddTransition(look, decide);
  chart.AddTransition(decide, look);
  EXPECT_FALSE(chart.RunUntilStable(1000));
  EXPECT_EQ(chart.UnsettledLoop(), "0.2 'Look' -> 0.3 'Spinner_3' -> 0.2 'Look'");
  ASSERT_EQ(reports.size(), 1U);
  EXPECT_EQ(reports[0].kind, EngineReport::Kind::Warning);
  EXPECT_THAT(reports[0].text, HasSubstr("stopped after 1000 transitions"));
  EXPECT_THAT(reports[0].text, HasSubstr("0.2 'Look' -> 0.3 'Spinner_3' -> 0.2 'Look'"));
}

TEST(InlineRunsLastACall, AChartThatSettlesHasNoUnsettledLoop) {
  ManualClock clock;
  MessageHub hub{clock};
  Statechart chart("Root", hub, OneRunPerCall());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* x = chart.Add<BasicState>("X", &chart);
  chart.AddTransition(start, x);
  EXPECT_TRUE(chart.RunUntilStable(1000));
  EXPECT_EQ(chart.UnsettledLoop(), "");
}

}  // namespace
}  // namespace kse_test
