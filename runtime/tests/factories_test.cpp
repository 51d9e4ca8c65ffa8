// Factories and registrars, and a statechart written the way the Monas generator writes one
// (docs/generated-code.md): activity and statechart classes registered by name from static
// objects, ICondition/IAction classes reading the blackboard, TimeoutAction subclasses.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "kse/behavior/BehaviorConst.h"
#include "kse/behavior/Guards.h"
#include "kse/messages/all.h"
#include "statechart_engine/statechart_engine.h"
#include "test_support.h"

// ---- activities/TestScan/TestScan.cpp (as generated, with a user body) ------------------------

class TestScan : public statechart_engine::IActivity {
 public:
  void UserInit() override { _blk->Subscribe("worldstate"); }
  int Execute() override {
    _blk->ProcessMessages();
    MotionHeadMessage head;
    head.set_command("setHead");
    head.add_parameter(0.5F);
    head.add_parameter(-0.2F);
    _blk->Publish("motion", kse::messaging::Kind::Signal, head);
    return 0;
  }
  std::string GetName() override { return "TestScan"; }
};
static statechart_engine::ActivityRegistrar<TestScan>::Type temp("TestScan");

class TestKick : public statechart_engine::IActivity {
 public:
  int Execute() override {
    MotionActionMessage action;
    action.set_command("KickForwardLeft");
    _blk->Publish("motion", kse::messaging::Kind::Signal, action);
    return 0;
  }
  std::string GetName() override { return "TestKick"; }
};
static statechart_engine::ActivityRegistrar<TestKick> kickRegistrar("TestKick");

// ---- statecharts/MiniGoalie/transitions (as generated) ----------------------------------------

class TrCond_0_2TOKick : public statechart_engine::ICondition {
 public:
  void UserInit() override { _blk->Subscribe("worldstate"); }
  bool Eval() override {
    // [worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING && readyToKick(worldstate.Data.WorldInfo)]
    std::shared_ptr<const GameStateMessage> var_0 = _blk->ReadState<GameStateMessage>("worldstate");
    std::shared_ptr<const WorldInfo> var_1 = _blk->ReadData<WorldInfo>("worldstate");
    if (var_0 == nullptr || var_1 == nullptr) return false;
    return var_0->player_state() == PLAYER_PLAYING && readyToKick(*var_1);
  }
};

class TrCond_0_2TOScan : public statechart_engine::ICondition {
 public:
  void UserInit() override { _blk->Subscribe("worldstate"); }
  bool Eval() override {
    std::shared_ptr<const WorldInfo> var_1 = _blk->ReadData<WorldInfo>("worldstate");
    return var_1 == nullptr || !readyToKick(*var_1);
  }
};

class TrCond_ScanTOScan : public statechart_engine::ICondition {
 public:
  void UserInit() override {
    _blk->Subscribe("worldstate");
    _blk->Subscribe("behavior");
  }
  bool Eval() override {
    // [TimeoutCheck(behavior) && !readyToKick(worldstate.Data.WorldInfo)]
    std::shared_ptr<const WorldInfo> var_1 = _blk->ReadData<WorldInfo>("worldstate");
    std::shared_ptr<const TimeoutMsg> timeout = _blk->ReadState<TimeoutMsg>("behavior");
    _blk->ProcessMessages();
    return statechart_engine::TimeoutCheck(*_blk, timeout) && (var_1 == nullptr || !readyToKick(*var_1));
  }
};

class TrCond_ScanTO0_4 : public statechart_engine::ICondition {
 public:
  void UserInit() override { _blk->Subscribe("worldstate"); }
  bool Eval() override {
    std::shared_ptr<const WorldInfo> var_1 = _blk->ReadData<WorldInfo>("worldstate");
    return var_1 != nullptr && readyToKick(*var_1);
  }
};

class TrAction_0_2TOScan : public statechart_engine::TimeoutAction {
 public:
  TrAction_0_2TOScan() : statechart_engine::TimeoutAction("behavior", 250) {}
};

class TrAction_ScanTOScan : public statechart_engine::TimeoutAction {
 public:
  TrAction_ScanTOScan() : statechart_engine::TimeoutAction("behavior", 250) {}
  void Execute() override {
    statechart_engine::TimeoutAction::Execute();
    BToHeadMessage message;  // publish.behavior.Signal.BToHeadMessage.set_headaction(1)
    message.set_headaction(1);
    _blk->Publish("behavior", kse::messaging::Kind::Signal, message);
  }
};

// ---- statecharts/MiniGoalie/MiniGoalie.h/.cpp (as generated) --------------------------------

class MiniGoalie : public statechart_engine::IStatechart {
 public:
  MiniGoalie(kse::messaging::MessageHub& hub, const statechart_engine::Options& options)
      : _statechart(std::make_unique<statechart_engine::Statechart>("Node_MiniGoalie", hub, options)) {
    using namespace statechart_engine;
    Statechart* Node_0 = _statechart.get();
    StartState* Node_0_1 = _statechart->Add<StartState>("Node_0_1", Node_0);
    ConditionConnector* Node_0_2 = _statechart->Add<ConditionConnector>("Node_0_2", Node_0);
    BasicState* Node_Kick = _statechart->Add<BasicState>("Node_Kick", Node_0,
                                                         ActivityFactory::Instance().Create("TestKick"));
    BasicState* Node_Scan = _statechart->Add<BasicState>("Node_Scan", Node_0,
                                                         ActivityFactory::Instance().Create("TestScan"));
    EndState* Node_0_4 = _statechart->Add<EndState>("Node_0_4", Node_0);
    _statechart->AddTransition(Node_0_1, Node_0_2);
    _statechart->AddTransition(Node_0_2, Node_Kick, std::make_unique<TrCond_0_2TOKick>());
    _statechart->AddTransition(Node_0_2, Node_Scan, std::make_unique<TrCond_0_2TOScan>(),
                               std::make_unique<TrAction_0_2TOScan>());
    _statechart->AddTransition(Node_Scan, Node_Scan, std::make_unique<TrCond_ScanTOScan>(),
                               std::make_unique<TrAction_ScanTOScan>());
    _statechart->AddTransition(Node_Scan, Node_0_4, std::make_unique<TrCond_ScanTO0_4>());
    _statechart->AddTransition(Node_Kick, Node_0_4);
  }
  void Start() override { _statechart->Start(); }
  void Stop() override { _statechart->Stop(); }
  statechart_engine::Statechart& Chart() override { return *_statechart; }

 private:
  std::unique_ptr<statechart_engine::Statechart> _statechart;
};
static statechart_engine::StatechartRegistrar<MiniGoalie>::Type miniGoalieRegistrar("MiniGoalie");

// ---------------------------------------------------------------------------------------------

namespace kse_test {
namespace {

using ::testing::Contains;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::shared_ptr<WorldInfo> BallAt(float x, float y) {
  auto world = std::make_shared<WorldInfo>();
  Ball* ball = world->add_balls();
  ball->set_relativex(x);
  ball->set_relativey(y);
  return world;
}

std::shared_ptr<GameStateMessage> Playing() {
  auto gsm = std::make_shared<GameStateMessage>();
  gsm->set_player_state(PLAYER_PLAYING);
  return gsm;
}

TEST(Factories, RegisteredActivitiesAreCreatedByName) {
  auto& factory = ActivityFactory::Instance();
  EXPECT_TRUE(factory.Contains("TestScan"));
  EXPECT_THAT(factory.Names(), Contains("TestKick"));
  auto activity = factory.Create("TestScan");
  ASSERT_NE(activity, nullptr);
  EXPECT_EQ(activity->GetName(), "TestScan");
  EXPECT_NE(factory.Create("TestScan").get(), activity.get()) << "a new object per call";
}

TEST(Factories, UnknownActivityGivesNullAndAMessage) {
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(ActivityFactory::Instance().Create("NoSuchActivity"), nullptr);
  EXPECT_THAT(::testing::internal::GetCapturedStderr(), HasSubstr("unknown activity 'NoSuchActivity'"));
}

TEST(Factories, DuplicateRegistrationKeepsTheFirst) {
  auto& factory = ActivityFactory::Instance();
  ::testing::internal::CaptureStderr();
  const bool registered = factory.Register("TestScan", [] { return std::unique_ptr<IActivity>(new TestKick()); });
  ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(registered);
  EXPECT_EQ(factory.Create("TestScan")->GetName(), "TestScan");
  EXPECT_TRUE(factory.Register("TemporaryActivity", [] { return std::unique_ptr<IActivity>(new TestKick()); }));
  EXPECT_TRUE(factory.Unregister("TemporaryActivity"));
  EXPECT_FALSE(factory.Contains("TemporaryActivity"));
}

TEST(Factories, ADuplicateRegistrationIsAClashNamingBothOrigins) {
  auto& factory = ActivityFactory::Instance();
  const auto before = factory.Clashes().size();
  ASSERT_TRUE(factory.Register("ClashingActivity", [] { return std::unique_ptr<IActivity>(new TestKick()); },
                               "/team/src/activities/ClashingActivity/ClashingActivity.cpp"));
  ::testing::internal::CaptureStderr();
  EXPECT_FALSE(factory.Register("ClashingActivity", [] { return std::unique_ptr<IActivity>(new TestKick()); },
                                "/examples/src/activities/ClashingActivity/ClashingActivity.cpp"));
  EXPECT_THAT(::testing::internal::GetCapturedStderr(),
              HasSubstr("activity 'ClashingActivity' is registered twice: by /team/src/activities/ClashingActivity/"
                        "ClashingActivity.cpp and by /examples/src/activities/ClashingActivity/ClashingActivity.cpp"));
  const auto clashes = factory.Clashes();
  ASSERT_EQ(clashes.size(), before + 1);
  EXPECT_THAT(clashes.back(), HasSubstr("/team/src/activities/ClashingActivity/ClashingActivity.cpp"));
  EXPECT_THAT(clashes.back(), HasSubstr("/examples/src/activities/ClashingActivity/ClashingActivity.cpp"));
  EXPECT_TRUE(factory.Unregister("ClashingActivity"));
}

TEST(Factories, RegistrarsNameTheirSourceFile) {
  // TestScan is registered at the top of this file, and again here: both registrars are in
  // this file, and the clash names it twice (the caller's file, not Factories.h)
  struct Local : IActivity {
    int Execute() override { return 0; }
    std::string GetName() override { return "TestScan"; }
  };
  auto& factory = ActivityFactory::Instance();
  ::testing::internal::CaptureStderr();
  const ActivityRegistrar<Local> again("TestScan");
  const std::string message = ::testing::internal::GetCapturedStderr();
  EXPECT_THAT(message, ::testing::ContainsRegex("activity 'TestScan' is registered twice: by [^ ]*factories_test\\.cpp "
                                                "and by [^ ]*factories_test\\.cpp"));
  EXPECT_THAT(factory.Clashes().back(), ::testing::Not(HasSubstr("Factories.h")));
}

TEST(Factories, RegisteredStatechartsAreCreatedByName) {
  ManualClock clock;
  MessageHub hub(clock);
  auto& factory = StatechartFactory::Instance();
  EXPECT_TRUE(factory.Contains("MiniGoalie"));
  EXPECT_THAT(factory.Names(), Contains("MiniGoalie"));
  auto chart = factory.Create("MiniGoalie", hub, Inline());
  ASSERT_NE(chart, nullptr);
  EXPECT_EQ(chart->Chart().Name(), "Node_MiniGoalie");
  EXPECT_TRUE(chart->Chart().GetOptions().inline_activities);
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(factory.Create("NoSuchChart", hub), nullptr);
  EXPECT_THAT(::testing::internal::GetCapturedStderr(), HasSubstr("unknown statechart 'NoSuchChart'"));
}

class GeneratedStyle : public ::testing::TestWithParam<bool> {
 protected:
  Options Mode() const { return GetParam() ? Inline() : Pooled(); }
  ManualClock clock;
  MessageHub hub{clock};
};

INSTANTIATE_TEST_SUITE_P(Modes, GeneratedStyle, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& mode) {
                           return mode.param ? "Inline" : "Pooled";
                         });

TEST_P(GeneratedStyle, ScansUntilTheBallIsReadyThenEnds) {
  Blackboard motion(hub, "motion observer");
  motion.Subscribe("motion");
  Blackboard head(hub, "head observer");
  head.Subscribe("behavior");
  hub.Publish("worldstate", Kind::State, Playing());

  auto goalie = StatechartFactory::Instance().Create("MiniGoalie", hub, Mode());
  ASSERT_NE(goalie, nullptr);
  Statechart& chart = goalie->Chart();
  chart.Activate();
  hub.Publish("worldstate", Kind::Data, BallAt(1.0F, 0.5F));
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Node_MiniGoalie", "Node_Scan"));
  motion.ProcessMessages();
  EXPECT_NE(motion.ReadSignal<MotionHeadMessage>("motion"), nullptr);

  clock.Advance(std::chrono::milliseconds(250));  // the polling self-loop re-runs Scan
  chart.RunUntilStable();
  auto* scan = static_cast<BasicState*>(chart.States()[4]);
  ASSERT_EQ(scan->Name(), "Node_Scan");
  EXPECT_EQ(chart.Launches(scan), 2U);
  head.ProcessMessages();
  auto headAction = head.ReadSignal<BToHeadMessage>("behavior");
  ASSERT_NE(headAction, nullptr);
  EXPECT_EQ(headAction->headaction(), 1);

  // The ball at the kicking spot is published, but the engine is not woken by that: at the next
  // wake-up the exit guard still reads the snapshot Scan took, the self-loop runs Scan once
  // more, and then the exit sees the ball.
  hub.Publish("worldstate", Kind::Data, BallAt(0.12F, -0.02F));
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Node_MiniGoalie", "Node_Scan"));
  clock.Advance(std::chrono::milliseconds(250));
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Node_MiniGoalie", "Node_0_4"));
  EXPECT_EQ(chart.Launches(scan), 3U);
  EXPECT_EQ(chart.ActivityFailures(), 0U);
}

TEST_P(GeneratedStyle, TheFirstDecisionSeesTheSnapshotNotTheLatestPublish) {
  Blackboard motion(hub, "motion observer");
  motion.Subscribe("motion");
  hub.Publish("worldstate", Kind::State, Playing());
  auto goalie = StatechartFactory::Instance().Create("MiniGoalie", hub, Mode());
  ASSERT_NE(goalie, nullptr);
  goalie->Chart().Activate();  // subscribes; Data is a stream, only State is kept for late subscribers
  hub.Publish("worldstate", Kind::Data, BallAt(0.125F, 0.04F));
  goalie->Chart().RunUntilStable();
  // The connector's guards read a blackboard nobody refreshed yet: no ball, so Scan; Scan
  // refreshes it, and its exit sees the ball.
  EXPECT_THAT(goalie->Chart().ActiveStates(), ElementsAre("Node_MiniGoalie", "Node_0_4"));
  motion.ProcessMessages();
  EXPECT_EQ(motion.ReadSignal<MotionActionMessage>("motion"), nullptr) << "no kick";
  EXPECT_NE(motion.ReadSignal<MotionHeadMessage>("motion"), nullptr) << "Scan ran";
}

TEST(GeneratedStyleThreaded, StartAndStopThroughTheWrapper) {
  MessageHub hub;
  auto goalie = StatechartFactory::Instance().Create("MiniGoalie", hub);
  ASSERT_NE(goalie, nullptr);
  goalie->Start();
  ASSERT_TRUE(WaitUntil([&] { return HasState(goalie->Chart().ActiveStates(), "Node_Scan"); }));
  auto world = BallAt(0.12F, 0.0F);
  hub.Publish("worldstate", Kind::Data, world);
  ASSERT_TRUE(WaitUntil([&] { return HasState(goalie->Chart().ActiveStates(), "Node_0_4"); }));
  goalie->Stop();
}

}  // namespace
}  // namespace kse_test
