// Start()/Stop(): the engine on its own thread with real time. It re-evaluates when an activity
// ends or a wake-up time passes, at once (every reaction below is required well under a
// second), and not when a message is published or Wake() is called.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <thread>
#include <vector>

#include "test_support.h"

namespace kse_test {
namespace {

using ::testing::ElementsAre;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

constexpr milliseconds kReaction(600);  // < the engine thread's 1 s look at its clock
constexpr milliseconds kLimit(3000);    // bound of every wait

class Threaded : public ::testing::Test {
 protected:
  MessageHub hub;  // SteadyClock
};

TEST_F(Threaded, ActivityEndWakesTheEngine) {
  Statechart chart("Root", hub, Pooled());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto finished = Counter();
  auto* work = chart.Add<BasicState>(
      "Work", &chart, std::make_unique<SleepingActivity>(milliseconds(40), finished));
  auto* after = chart.Add<BasicState>("After", &chart);
  chart.AddTransition(start, work);
  chart.AddTransition(work, after);

  chart.Start();
  EXPECT_TRUE(chart.IsStarted());
  ASSERT_TRUE(WaitUntil([&] { return finished->load() == 1; }, kLimit));
  const auto ended = Clock::now();
  ASSERT_TRUE(WaitUntil([&] { return HasState(chart.ActiveStates(), "After"); }, kLimit));
  EXPECT_LT(Clock::now() - ended, kReaction);
  chart.Stop();
  EXPECT_FALSE(chart.IsStarted());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "After"));
}

TEST_F(Threaded, TimerExpiryWakesTheEngine) {
  Statechart chart("Root", hub, Pooled());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* waiting = chart.Add<BasicState>("Waiting", &chart);
  auto* done = chart.Add<BasicState>("Done", &chart);
  chart.AddTransition(start, waiting, nullptr, std::make_unique<TimeoutAction>("behavior", 60));
  chart.AddTransition(waiting, done, TimeoutCheck("behavior"));

  const auto begin = Clock::now();
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return HasState(chart.ActiveStates(), "Done"); }, kLimit));
  const auto elapsed = Clock::now() - begin;
  chart.Stop();
  EXPECT_GE(elapsed, milliseconds(60));
  EXPECT_LT(elapsed, milliseconds(60) + kReaction);
}

TEST_F(Threaded, PublishDoesNotWakeTheEngine) {
  Statechart chart("Root", hub, Pooled());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* waiting = chart.Add<BasicState>("Waiting", &chart);
  auto* playing = chart.Add<BasicState>("Playing", &chart);
  auto evals = Counter();
  chart.AddTransition(start, waiting);
  chart.AddTransition(waiting, playing, If([evals](Blackboard& blk) {
                        ++*evals;
                        blk.ProcessMessages();
                        auto gsm = blk.ReadState<GameStateMessage>("worldstate");
                        return gsm != nullptr && gsm->player_state() == PLAYER_PLAYING;
                      }, {"worldstate"}));
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return evals->load() == 1; }, kLimit));
  auto message = std::make_shared<GameStateMessage>();
  message->set_player_state(PLAYER_PLAYING);
  std::thread publisher([&] { hub.Publish("worldstate", Kind::State, message); });
  publisher.join();
  chart.Wake();
  std::this_thread::sleep_for(milliseconds(100));
  chart.Stop();
  EXPECT_EQ(evals->load(), 1) << "neither the publish nor Wake() made the engine evaluate";
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Waiting"));
}

TEST_F(Threaded, PollingLoopRunsTheActivityRepeatedly) {
  // Scan -> Scan [TimeoutCheck(behavior)] / TimeoutAction.behavior.20 until 5 runs.
  Statechart chart("Root", hub, Pooled());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto runs = Counter();
  auto* scan = chart.Add<BasicState>("Scan", &chart, std::make_unique<CountingActivity>(runs));
  auto* end = chart.Add<EndState>("Root_3", &chart);
  chart.AddTransition(start, scan, nullptr, std::make_unique<TimeoutAction>("behavior", 20));
  chart.AddTransition(scan, scan, If([runs](Blackboard& blk) {
                        const auto timeout = blk.ReadState<TimeoutMsg>("behavior");
                        blk.ProcessMessages();
                        return statechart_engine::TimeoutCheck(blk, timeout) && runs->load() < 5;
                      }, {"behavior"}),
                      std::make_unique<TimeoutAction>("behavior", 20));
  chart.AddTransition(scan, end, If([runs](Blackboard&) { return runs->load() >= 5; }));
  const auto begin = Clock::now();
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return HasState(chart.ActiveStates(), "Root_3"); }, kLimit));
  const auto elapsed = Clock::now() - begin;
  chart.Stop();
  EXPECT_EQ(runs->load(), 5);
  EXPECT_GE(elapsed, milliseconds(80));  // four waits of 20 ms
  EXPECT_LT(elapsed, milliseconds(80) + kReaction);
}

TEST_F(Threaded, ThrowingActivityDoesNotStopTheEngine) {
  Statechart chart("Root", hub, Pooled());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* bad = chart.Add<BasicState>("Bad", &chart, std::make_unique<ThrowingActivity>());
  auto runs = Counter();
  auto* good = chart.Add<BasicState>("Good", &chart, std::make_unique<CountingActivity>(runs));
  chart.AddTransition(start, bad);
  chart.AddTransition(bad, good);
  ::testing::internal::CaptureStderr();
  chart.Start();
  const bool reached = WaitUntil([&] { return runs->load() == 1; }, kLimit);
  chart.Stop();
  ::testing::internal::GetCapturedStderr();
  ASSERT_TRUE(reached);
  EXPECT_EQ(chart.ActivityFailures(), 1U);
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Good"));
}

TEST_F(Threaded, InlineActivitiesWorkInThreadedMode) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto runs = Counter();
  auto* x = chart.Add<BasicState>("X", &chart, std::make_unique<CountingActivity>(runs));
  auto* end = chart.Add<EndState>("Root_3", &chart);
  chart.AddTransition(start, x);
  chart.AddTransition(x, end);
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return HasState(chart.ActiveStates(), "Root_3"); }, kLimit));
  chart.Stop();
  EXPECT_EQ(runs->load(), 1);
}

TEST_F(Threaded, StopKeepsTheConfigurationAndStartResumes) {
  Statechart chart("Root", hub, Pooled());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* waiting = chart.Add<BasicState>("Waiting", &chart);
  auto* done = chart.Add<BasicState>("Done", &chart);
  auto go = Flag(false);
  chart.AddTransition(start, waiting);
  chart.AddTransition(waiting, done, When(go));
  chart.Stop();  // not started: nothing happens
  chart.Start();
  chart.Start();  // already started: nothing happens
  ASSERT_TRUE(WaitUntil([&] { return HasState(chart.ActiveStates(), "Waiting"); }, kLimit));
  chart.Stop();
  go->store(true);
  chart.Wake();
  std::this_thread::sleep_for(milliseconds(20));
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Waiting")) << "stopped: no steps";
  chart.Start();  // a start is a reason to evaluate
  ASSERT_TRUE(WaitUntil([&] { return HasState(chart.ActiveStates(), "Done"); }, kLimit));
  chart.Stop();
  chart.Stop();
}

TEST_F(Threaded, DestroyingAStartedChartStopsIt) {
  auto runs = Counter();
  {
    Statechart chart("Root", hub, Pooled());
    auto* start = chart.Add<StartState>("Root_1", &chart);
    auto* x = chart.Add<BasicState>("X", &chart, std::make_unique<CountingActivity>(runs));
    chart.AddTransition(start, x);
    chart.AddTransition(x, x);  // loops forever
    chart.Start();
    ASSERT_TRUE(WaitUntil([&] { return runs->load() > 10; }, kLimit));
  }
  const int after = runs->load();
  std::this_thread::sleep_for(milliseconds(10));
  EXPECT_EQ(runs->load(), after);
}

TEST_F(Threaded, ConcurrentPublishersWhileTheEngineRuns) {
  // Two regions count signals published from four threads; every signal reaches both. Each
  // region polls with an activity whose end wakes the engine (a publish does not).
  Statechart chart("Root", hub, Pooled());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* both = chart.Add<AndState>("Both", &chart);
  auto counts = std::make_shared<std::array<std::atomic<int>, 2>>();
  for (int region = 0; region < 2; ++region) {
    auto* r = chart.Add<OrState>("R" + std::to_string(region), both);
    auto* rStart = chart.Add<StartState>("R" + std::to_string(region) + "_1", r);
    auto* counting = chart.Add<BasicState>("Counting" + std::to_string(region), r,
                                           std::make_unique<CountingActivity>(Counter()));
    chart.AddTransition(rStart, counting);
    chart.AddTransition(counting, counting, If([counts, region](Blackboard& blk) {
                          blk.ProcessMessages();
                          while (blk.ReadSignal<FallMessage>("events") != nullptr) {
                            ++(*counts)[static_cast<std::size_t>(region)];
                          }
                          return true;
                        }, {"events"}));
  }
  chart.AddTransition(start, both);
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return hub.SubscriberCount("events") == 2; }, kLimit));

  constexpr int kThreads = 4;
  constexpr int kEach = 200;
  std::vector<std::thread> publishers;
  for (int t = 0; t < kThreads; ++t) {
    publishers.emplace_back([&] {
      for (int i = 0; i < kEach; ++i) {
        auto message = std::make_shared<FallMessage>();
        message->set_fall(i % 3 - 1);
        hub.Publish("events", Kind::Signal, message);
      }
    });
  }
  for (auto& publisher : publishers) publisher.join();
  ASSERT_TRUE(WaitUntil([&] {
    return (*counts)[0].load() == kThreads * kEach && (*counts)[1].load() == kThreads * kEach;
  }, kLimit));
  chart.Stop();
}

// The engine's lock (ADR 0022) against threads that step at once: every step is taken whole
// (the counters are written without locked instructions, so a step that overlapped another
// would lose counts), and a statechart that never settles, stepped by the engine thread without
// end, still answers ActiveStates() promptly on another thread.
TEST_F(Threaded, StepsOfSeveralThreadsAreTakenOneAtATime) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<BasicState>("A", &chart);
  auto* b = chart.Add<BasicState>("B", &chart);
  // The guard gives the processor away in the middle of the step: another thread's step would
  // begin inside this one if the lock let it.
  std::atomic<int> inside{0};
  std::atomic<int> most_inside{0};
  auto guard = [&](Blackboard&) {
    const int now = ++inside;
    int most = most_inside.load();
    while (now > most && !most_inside.compare_exchange_weak(most, now)) {
    }
    std::this_thread::yield();
    --inside;
    return true;
  };
  chart.AddTransition(start, a);
  chart.AddTransition(a, b, If(guard));
  chart.AddTransition(b, a, If(guard));
  chart.Activate();

  constexpr int kThreads = 3;
  constexpr int kSteps = 1000;
  std::atomic<int> refused{0};
  std::vector<std::thread> steppers;
  for (int t = 0; t < kThreads; ++t) {
    steppers.emplace_back([&] {
      for (int i = 0; i < kSteps; ++i) {
        if (!chart.Step()) ++refused;
      }
    });
  }
  for (auto& stepper : steppers) stepper.join();
  EXPECT_EQ(most_inside.load(), 1) << "two steps overlapped";
  EXPECT_EQ(refused.load(), 0);
  EXPECT_EQ(chart.StepNumber(), static_cast<std::size_t>(kThreads * kSteps));
  EXPECT_EQ(chart.TransitionsTaken(), static_cast<std::size_t>(kThreads * kSteps));
}

TEST_F(Threaded, ActiveStatesAnswersWhileTheEngineThreadNeverSettles) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<BasicState>("A", &chart);
  auto* b = chart.Add<BasicState>("B", &chart);
  chart.AddTransition(start, a);
  chart.AddTransition(a, b, Always());
  chart.AddTransition(b, a, Always());
  chart.Start();
  ASSERT_TRUE(WaitUntil([&] { return chart.TransitionsTaken() > 10000; }, kLimit));

  auto slowest = Clock::duration::zero();
  for (int i = 0; i < 50; ++i) {
    const auto begin = Clock::now();
    const auto names = chart.ActiveStates();
    slowest = std::max(slowest, Clock::now() - begin);
    // Taken between two steps: the root and exactly one of A and B.
    ASSERT_EQ(names.size(), 2U);
    EXPECT_TRUE(names[1] == "A" || names[1] == "B") << names[1];
  }
  const std::size_t taken = chart.TransitionsTaken();
  ASSERT_TRUE(WaitUntil([&] { return chart.TransitionsTaken() > taken; }, kLimit))
      << "the engine thread goes on after the readers";
  chart.Stop();
  EXPECT_LT(slowest, milliseconds(100));
}

TEST_F(Threaded, UserCodeInsideAStepMayCallBackIntoTheStatechart) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<BasicState>("A", &chart);
  std::vector<std::string> seen;
  chart.AddTransition(start, a, If([&](Blackboard&) {
                        seen = chart.ActiveStates();  // on the stepping thread, under its lock
                        return true;
                      }));
  chart.RunUntilStable();
  EXPECT_THAT(seen, ElementsAre("Root", "Root_1"));
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "A"));
}

}  // namespace
}  // namespace kse_test
