// The watchdog and Stop()'s bound. A call into user code that does not return (an activity, a
// guard, an action) is reported once, naming the statechart, the state or transition and how
// long it has run; Stop() and the destructor return in bounded time whatever still runs, and
// what still runs comes back, when it returns, to memory that is still there.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_support.h"

namespace kse_test {
namespace {

using ::testing::HasSubstr;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;
using Kind = EngineReport::Kind;

constexpr milliseconds kLimit(3000);  // bound of every wait
constexpr milliseconds kSlack(500);   // a loaded machine, a sanitizer
constexpr milliseconds kPoll(10);     // how late WaitUntil may see that an activity began

/// Collects reports from any thread.
class Reports {
 public:
  Reporter Sink() {
    return [this](const EngineReport& report) {
      std::lock_guard<std::mutex> lock(mutex_);
      all_.push_back(report);
      arrived_.push_back(Clock::now());
    };
  }
  std::vector<EngineReport> Of(Kind kind) const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<EngineReport> out;
    for (const auto& report : all_) {
      if (report.kind == kind) out.push_back(report);
    }
    return out;
  }
  Clock::time_point FirstArrival(Kind kind) const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < all_.size(); ++i) {
      if (all_[i].kind == kind) return arrived_[i];
    }
    return Clock::time_point::max();
  }
  bool WaitFor(Kind kind, std::size_t count = 1) const {
    return WaitUntil([&] { return Of(kind).size() >= count; }, kLimit);
  }

 private:
  mutable std::mutex mutex_;
  std::vector<EngineReport> all_;
  std::vector<Clock::time_point> arrived_;
};

Options Watched(const std::shared_ptr<Reports>& reports, milliseconds limit, bool inline_activities = false) {
  Options options = inline_activities ? Inline() : Pooled();
  options.watchdog_limit = limit;
  options.stop_limit = milliseconds(200);
  options.reporter = reports->Sink();
  return options;
}

/// Waits at its gate, then uses its blackboard: it must still be there when the activity
/// returns, even if the statechart was destroyed meanwhile.
class StubbornActivity : public IActivity {
 public:
  StubbornActivity(std::shared_ptr<Gate> gate, std::shared_ptr<std::atomic<int>> started,
                   std::shared_ptr<std::atomic<int>> returned)
      : gate_(std::move(gate)), started_(std::move(started)), returned_(std::move(returned)) {}
  int Execute() override {
    ++*started_;
    gate_->Wait(milliseconds(10000));
    _blk->ProcessMessages();
    ++*returned_;
    return 0;
  }
  std::string GetName() override { return "Stubborn"; }

 private:
  std::shared_ptr<Gate> gate_;
  std::shared_ptr<std::atomic<int>> started_;
  std::shared_ptr<std::atomic<int>> returned_;
};

/// A guard that waits at its gate, then holds.
std::unique_ptr<ICondition> WaitsAt(std::shared_ptr<Gate> gate, std::shared_ptr<std::atomic<int>> entered,
                                    std::shared_ptr<std::atomic<int>> returned) {
  return If([gate, entered, returned](Blackboard&) {
    ++*entered;
    gate->Wait(milliseconds(10000));
    ++*returned;
    return true;
  });
}

class Watchdog : public ::testing::Test {
 protected:
  MessageHub hub;  // SteadyClock
  std::shared_ptr<Reports> reports = std::make_shared<Reports>();
  std::shared_ptr<Gate> gate = std::make_shared<Gate>();
  std::shared_ptr<std::atomic<int>> started = Counter();
  std::shared_ptr<std::atomic<int>> returned = Counter();

  /// START -> 'Work', whose activity waits at the gate: the chart most tests watch.
  BasicState* StubbornWork(Statechart& chart) {
    auto* start = chart.Add<StartState>("Robot_1", &chart);
    auto* work = chart.Add<BasicState>("Work", &chart, std::make_unique<StubbornActivity>(gate, started, returned));
    chart.AddTransition(start, work);
    return work;
  }
};

TEST_F(Watchdog, ReportsAnActivityRunningTooLongOnceNamingItsStateAndHowLong) {
  Statechart chart("Robot", hub, Watched(reports, milliseconds(100)));
  auto* work = StubbornWork(chart);
  work->SetLabel("0.2");
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }, kLimit));
  const auto began = Clock::now();
  ASSERT_TRUE(reports->WaitFor(Kind::Overrun));
  const auto latency = reports->FirstArrival(Kind::Overrun) - began;
  EXPECT_GE(latency, milliseconds(100) - kPoll);
  EXPECT_LT(latency, milliseconds(100) + kSlack);
  std::this_thread::sleep_for(milliseconds(300));
  const auto overruns = reports->Of(Kind::Overrun);
  ASSERT_EQ(overruns.size(), 1U) << "one report per overrun, not one per look";
  EXPECT_EQ(overruns[0].chart, "Robot");
  EXPECT_THAT(overruns[0].text, HasSubstr("activity 'Stubborn' of state 0.2 'Work' has been running for"));
  EXPECT_THAT(overruns[0].text, HasSubstr("(watchdog limit 100 ms)"));
  EXPECT_GE(overruns[0].running, milliseconds(100));
  EXPECT_EQ(chart.Overruns(), 1U);
  EXPECT_TRUE(reports->Of(Kind::OverrunEnded).empty());

  gate->Open();
  ASSERT_TRUE(reports->WaitFor(Kind::OverrunEnded));
  const auto ended = reports->Of(Kind::OverrunEnded);
  EXPECT_EQ(ended[0].overrun, overruns[0].overrun) << "the end names the overrun it ends";
  EXPECT_EQ(ended[0].call, "activity 'Stubborn' of state 0.2 'Work'");
  EXPECT_EQ(overruns[0].call, ended[0].call);
  EXPECT_THAT(ended[0].text, HasSubstr("activity 'Stubborn' of state 0.2 'Work' returned after about"));
  EXPECT_GE(ended[0].running, milliseconds(350));  // 100 + 300 ms, less a look
  chart.Stop();
  EXPECT_TRUE(reports->Of(Kind::Abandoned).empty());
}

TEST_F(Watchdog, ReportsAGuardThatNeverReturnsOnTheEngineThread) {
  Statechart chart("Robot", hub, Watched(reports, milliseconds(100)));
  auto* start = chart.Add<StartState>("Robot_1", &chart);
  auto* waiting = chart.Add<BasicState>("Waiting", &chart);
  auto* done = chart.Add<BasicState>("Done", &chart);
  waiting->SetLabel("0.2");
  done->SetLabel("0.3");
  chart.AddTransition(start, waiting);
  chart.AddTransition(waiting, done, WaitsAt(gate, started, returned));
  chart.Start();
  ASSERT_TRUE(reports->WaitFor(Kind::Overrun));
  EXPECT_THAT(reports->Of(Kind::Overrun)[0].text,
              HasSubstr("guard of transition 'Waiting_TO_Done' (0.2 -> 0.3) has been running for"));
  gate->Open();
  ASSERT_TRUE(WaitUntil([&] { return HasState(chart.ActiveStates(), "Done"); }, kLimit));
  EXPECT_TRUE(reports->WaitFor(Kind::OverrunEnded));
  chart.Stop();
  EXPECT_EQ(reports->Of(Kind::Overrun).size(), 1U);
}

TEST_F(Watchdog, ReportsAnInlineActivityWhileRunUntilStableWaitsForIt) {
  // The simulator's case: the activity runs on the caller's thread, inside RunUntilStable().
  Statechart chart("Robot", hub, Watched(reports, milliseconds(100), true));
  StubbornWork(chart);
  std::thread caller([&] { chart.RunUntilStable(); });
  const bool reported = reports->WaitFor(Kind::Overrun);
  gate->Open();
  caller.join();
  ASSERT_TRUE(reported);
  EXPECT_THAT(reports->Of(Kind::Overrun)[0].text, HasSubstr("activity 'Stubborn' of state 'Work'"));
}

TEST_F(Watchdog, ReportsActionsAndEntryHooksToo) {
  class SlowEntry : public BasicState {
   public:
    SlowEntry(std::string name, State* parent, std::shared_ptr<Gate> gate)
        : BasicState(std::move(name), parent), gate_(std::move(gate)) {}
    void OnEntry() override { gate_->Wait(milliseconds(10000)); }

   private:
    std::shared_ptr<Gate> gate_;
  };
  class SlowAction : public IAction {
   public:
    explicit SlowAction(std::shared_ptr<Gate> gate) : gate_(std::move(gate)) {}
    void Execute() override { gate_->Wait(milliseconds(10000)); }

   private:
    std::shared_ptr<Gate> gate_;
  };
  auto second_gate = std::make_shared<Gate>();
  Statechart chart("Robot", hub, Watched(reports, milliseconds(100), true));
  auto* start = chart.Add<StartState>("Robot_1", &chart);
  auto* slow = chart.Add<SlowEntry>("Slow", &chart, second_gate);
  chart.AddTransition(start, slow, nullptr, std::make_unique<SlowAction>(gate));
  std::thread caller([&] { chart.RunUntilStable(); });
  const bool action = reports->WaitFor(Kind::Overrun);
  gate->Open();
  const bool entry = reports->WaitFor(Kind::Overrun, 2);
  second_gate->Open();
  caller.join();
  ASSERT_TRUE(action && entry);
  EXPECT_THAT(reports->Of(Kind::Overrun)[0].text, HasSubstr("action of transition 'Robot_1_TO_Slow'"));
  EXPECT_THAT(reports->Of(Kind::Overrun)[1].text, HasSubstr("OnEntry of state 'Slow'"));
}

TEST_F(Watchdog, AnActivityCanHaveItsOwnLimit) {
  // "Stubborn" may take as long as it likes; the chart's other calls may not.
  Statechart chart("Robot", hub, Watched(reports, milliseconds(100)));
  chart.SetActivityWatchdogLimit("Stubborn", milliseconds(0));
  StubbornWork(chart);
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }, kLimit));
  std::this_thread::sleep_for(milliseconds(300));
  EXPECT_TRUE(reports->Of(Kind::Overrun).empty());

  chart.SetActivityWatchdogLimit("Stubborn", milliseconds(50));  // also after activation
  chart.SetWatchdogLimit(milliseconds(0));
  EXPECT_EQ(chart.WatchdogLimit(), milliseconds(0));
  ASSERT_TRUE(reports->WaitFor(Kind::Overrun));
  EXPECT_THAT(reports->Of(Kind::Overrun)[0].text, HasSubstr("(watchdog limit 50 ms)"));
  gate->Open();
  chart.Stop();
}

TEST_F(Watchdog, QuickCallsAreNeverReported) {
  // 20 ms of polling in many short steps: every call is short, whatever the total.
  Statechart chart("Robot", hub, Watched(reports, milliseconds(20)));
  auto* start = chart.Add<StartState>("Robot_1", &chart);
  auto runs = Counter();
  auto* scan = chart.Add<BasicState>("Scan", &chart, std::make_unique<CountingActivity>(runs));
  chart.AddTransition(start, scan);
  chart.AddTransition(scan, scan);
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return runs->load() > 1000; }, kLimit));
  std::this_thread::sleep_for(milliseconds(100));
  chart.Stop();
  EXPECT_TRUE(reports->Of(Kind::Overrun).empty());
  EXPECT_EQ(chart.Overruns(), 0U);
}

TEST_F(Watchdog, IsOnByDefaultWithALimitOfOneSecond) {
  EXPECT_EQ(Options{}.watchdog_limit, milliseconds(1000));
  EXPECT_EQ(Options{}.stop_limit, milliseconds(1000));
  Options options = Pooled();
  options.reporter = reports->Sink();
  Statechart chart("Robot", hub, options);
  EXPECT_EQ(chart.WatchdogLimit(), milliseconds(1000));
  StubbornWork(chart);
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }, kLimit));
  const auto began = Clock::now();
  ASSERT_TRUE(reports->WaitFor(Kind::Overrun));
  const auto latency = reports->FirstArrival(Kind::Overrun) - began;
  gate->Open();
  chart.Stop();
  EXPECT_GE(latency, milliseconds(1000) - kPoll);
  EXPECT_LT(latency, milliseconds(1000) + kSlack);
  std::cout << "[ watchdog ] reported after "
            << std::chrono::duration_cast<milliseconds>(latency).count() << " ms (limit 1000 ms)\n";
}

TEST_F(Watchdog, WithoutAReporterItWritesOnStandardError) {
  Options options = Pooled();
  options.watchdog_limit = milliseconds(50);
  ::testing::internal::CaptureStderr();
  bool reported = false;
  {
    Statechart chart("Robot", hub, options);
    StubbornWork(chart);
    chart.Start();
    reported = WaitUntil([&] { return chart.Overruns() == 1; }, kLimit);
    gate->Open();
    chart.Stop();
    // The overrun is counted when the watchdog notices it, and written after; destroying the
    // statechart waits for a delivery under way (Watchdog::Unwatch), so the line is written.
  }
  const std::string err = ::testing::internal::GetCapturedStderr();
  ASSERT_TRUE(reported);
  EXPECT_THAT(err, HasSubstr("[kse] statechart 'Robot': activity 'Stubborn' of state 'Work' has been running for"));
}

// ---------------------------------------------------------------------------------------------

class StopBound : public Watchdog {};

TEST_F(StopBound, StopReturnsWithinItsLimitWhenAnActivityNeverReturns) {
  Statechart chart("Robot", hub, Watched(reports, milliseconds(0)));
  auto* work = StubbornWork(chart);
  work->SetLabel("0.2");
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }, kLimit));
  const auto before = Clock::now();
  chart.Stop();
  const auto took = Clock::now() - before;
  EXPECT_GE(took, milliseconds(200));
  EXPECT_LT(took, milliseconds(200) + kSlack);
  std::cout << "[ stop ] returned after " << std::chrono::duration_cast<milliseconds>(took).count()
            << " ms (limit 200 ms)\n";
  const auto abandoned = reports->Of(Kind::Abandoned);
  ASSERT_EQ(abandoned.size(), 1U);
  EXPECT_THAT(abandoned[0].text, HasSubstr("Stop() stopped waiting after 200 ms"));
  EXPECT_THAT(abandoned[0].text, HasSubstr("activity 'Stubborn' of state 0.2 'Work'"));

  // The statechart lives on: the activity finishes as usual.
  gate->Open();
  ASSERT_TRUE(WaitUntil([&] { return chart.RunningActivities() == 0; }, kLimit));
  EXPECT_EQ(returned->load(), 1);
  chart.Stop();
  EXPECT_EQ(reports->Of(Kind::Abandoned).size(), 1U);
}

TEST_F(StopBound, StopReturnsWhenTheEngineThreadIsStuckInAGuardAndStartResumes) {
  Statechart chart("Robot", hub, Watched(reports, milliseconds(0)));
  auto* start = chart.Add<StartState>("Robot_1", &chart);
  auto* waiting = chart.Add<BasicState>("Waiting", &chart);
  auto* done = chart.Add<BasicState>("Done", &chart);
  chart.AddTransition(start, waiting);
  chart.AddTransition(waiting, done, WaitsAt(gate, started, returned));
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }, kLimit));
  const auto before = Clock::now();
  chart.Stop();
  EXPECT_LT(Clock::now() - before, milliseconds(200) + kSlack);
  EXPECT_FALSE(chart.IsStarted());
  const auto abandoned = reports->Of(Kind::Abandoned);
  ASSERT_EQ(abandoned.size(), 1U);
  EXPECT_THAT(abandoned[0].text,
              HasSubstr("the engine thread, in the guard of transition 'Waiting_TO_Done'"));

  // The guard returns to a thread that was given up: it takes nothing. A new start evaluates
  // again and takes the transition.
  gate->Open();
  ASSERT_TRUE(WaitUntil([&] { return returned->load() == 1; }, kLimit));
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return HasState(chart.ActiveStates(), "Done"); }, kLimit));
  chart.Stop();
  EXPECT_EQ(started->load(), 2);
}

TEST_F(StopBound, DestroyingAStatechartWhoseActivityNeverReturnedIsSafe) {
  const auto before = Clock::now();
  {
    Statechart chart("Robot", hub, Watched(reports, milliseconds(0)));
    StubbornWork(chart);
    chart.Start();
    ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }, kLimit));
  }
  EXPECT_LT(Clock::now() - before, milliseconds(200) + kSlack);
  const auto abandoned = reports->Of(Kind::Abandoned);
  ASSERT_EQ(abandoned.size(), 2U);
  EXPECT_THAT(abandoned[1].text, HasSubstr("destroyed while 1 activity and 0 engine threads still ran"));
  // The activity returns (and uses its blackboard) after its statechart is gone.
  gate->Open();
  ASSERT_TRUE(WaitUntil([&] { return returned->load() == 1; }, kLimit));
  std::this_thread::sleep_for(milliseconds(50));  // its worker finishes the bookkeeping
}

TEST_F(StopBound, DestroyingAStatechartWhoseEngineThreadIsStuckInAGuardIsSafe) {
  {
    Statechart chart("Robot", hub, Watched(reports, milliseconds(0)));
    auto* start = chart.Add<StartState>("Robot_1", &chart);
    auto* waiting = chart.Add<OrState>("Waiting", &chart);
    auto* inner = chart.Add<StartState>("Waiting_1", waiting);
    auto* deep = chart.Add<BasicState>("Deep", waiting);
    auto* done = chart.Add<BasicState>("Done", &chart);
    chart.AddTransition(start, waiting);
    chart.AddTransition(inner, deep, WaitsAt(gate, started, returned));
    chart.AddTransition(deep, done);
    chart.Start();
    ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }, kLimit));
  }
  ASSERT_EQ(reports->Of(Kind::Abandoned).size(), 2U);
  EXPECT_THAT(reports->Of(Kind::Abandoned)[1].text, HasSubstr("0 activities and 1 engine thread still ran"));
  // The guard returns inside a step of the destroyed statechart: the step must stop there.
  gate->Open();
  ASSERT_TRUE(WaitUntil([&] { return returned->load() == 1; }, kLimit));
  std::this_thread::sleep_for(milliseconds(50));
}

TEST_F(StopBound, DestroyingAStatechartStuckInAnInlineActivityIsSafe) {
  {
    Statechart chart("Robot", hub, Watched(reports, milliseconds(0), true));
    auto* work = StubbornWork(chart);
    auto* after = chart.Add<BasicState>("After", &chart);
    chart.AddTransition(work, after);
    chart.Start();
    ASSERT_TRUE(WaitUntil([&] { return started->load() == 1; }, kLimit));
  }
  ASSERT_EQ(reports->Of(Kind::Abandoned).size(), 2U);
  EXPECT_THAT(reports->Of(Kind::Abandoned)[0].text,
              HasSubstr("the engine thread, in the activity 'Stubborn' of state 'Work'"));
  gate->Open();
  ASSERT_TRUE(WaitUntil([&] { return returned->load() == 1; }, kLimit));
  std::this_thread::sleep_for(milliseconds(50));
}

}  // namespace
}  // namespace kse_test
