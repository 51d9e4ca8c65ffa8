// The simulation a user drives (and the conformance suite through it): a small statechart written
// against the engine, run by commands as the Simulation view and the case files give them.

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <kse/messages/all.h>
#include <statechart_engine/Factories.h>
#include <statechart_engine/Statechart.h>
#include <statechart_engine/TimeoutAction.h>

#include "kse/simulation/Script.h"
#include "kse/simulation/Simulation.h"
#include "kse/simulation/Simulator.h"

namespace {

using kse::simulation::ParseCommand;
using kse::simulation::ScriptError;
using kse::simulation::Simulation;

// 0.1 START -> 0.2 Work (activity) -> 0.3 Wait (a 100 ms timer set on the way) -> 0.4 Work again
// (launched by the timer, in the middle of an advance) -> 0.5 END
class ErrandChart : public statechart_engine::IStatechart {
 public:
  ErrandChart(kse::messaging::MessageHub& hub, const statechart_engine::Options& options) : chart_("Node_errand", hub, options) {
    using namespace statechart_engine;
    auto* start = chart_.Add<StartState>("Node_start", &chart_);
    auto* work = chart_.Add<BasicState>("Node_work", &chart_, ActivityFactory::Instance().PartNamed("Work"));
    auto* wait = chart_.Add<BasicState>("Node_wait", &chart_);
    auto* again = chart_.Add<BasicState>("Node_again", &chart_, ActivityFactory::Instance().PartNamed("Work"));
    auto* end = chart_.Add<EndState>("Node_end", &chart_);
    start->SetLabel("0.1");
    work->SetLabel("0.2");
    wait->SetLabel("0.3");
    again->SetLabel("0.4");
    end->SetLabel("0.5");
    chart_.AddTransition(start, work);
    chart_.AddTransition(work, wait, nullptr, std::make_unique<TimeoutAction>("tick", 100));
    chart_.AddTransition(wait, again, std::make_unique<TimeoutCondition>("tick"));
    chart_.AddTransition(again, end);
  }
  void Start() override { chart_.Start(); }
  void Stop() override { chart_.Stop(); }
  statechart_engine::Statechart& Chart() override { return chart_; }

 private:
  statechart_engine::Statechart chart_;
};

statechart_engine::StatechartRegistrar<ErrandChart> registrar("Errand");

class SimulationTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { kse::simulation::RegisterScriptedActivities({"Work"}); }
  std::vector<std::string> Run(Simulation& simulation, const std::string& command) {
    return simulation.Execute(ParseCommand(command));
  }
};

using Lines = std::vector<std::string>;

TEST_F(SimulationTest, ARunGoesAsTheCommandsSay) {
  Simulation simulation("Errand");
  EXPECT_EQ(Run(simulation, "start"), Lines({"0.1 -> 0.2"}));
  EXPECT_EQ(simulation.Running(), Lines({"Work"}));
  EXPECT_EQ(Run(simulation, "finish Work"), Lines({"0.2 -> 0.3"}));
  ASSERT_EQ(simulation.LastTaken().size(), 1u);
  EXPECT_EQ(simulation.LastTaken()[0].index, 1);
  EXPECT_EQ(Run(simulation, "advance 50"), Lines{});
  EXPECT_EQ(Run(simulation, "active"), Lines({"active: 0.3"}));
  EXPECT_EQ(Run(simulation, "advance 60"), Lines({"0.3 -> 0.4"}));
  EXPECT_EQ(simulation.Elapsed().count(), 110);
  // the timer launched Work again at 100 ms, within the advance: that is when it began
  ASSERT_EQ(simulation.RunningSince().size(), 1u);
  EXPECT_EQ(simulation.RunningSince()[0].first, "Work");
  EXPECT_EQ(simulation.RunningSince()[0].second.count(), 100);
  EXPECT_EQ(Run(simulation, "finish Work"), Lines({"0.4 -> 0.5"}));
  EXPECT_EQ(Run(simulation, "running"), Lines({"running: none"}));
}

TEST_F(SimulationTest, AnAdvanceStopsAtTheWakeUpThatHitABreakpoint) {
  {
    // a program runs one simulation at a time: its activities are the stand-ins' only runs
    Simulation simulation("Errand");
    simulation.SetBreakpoints({"0.4"}, {});
    Run(simulation, "start");
    Run(simulation, "finish Work");
    EXPECT_EQ(Run(simulation, "advance 5000"), Lines({"0.3 -> 0.4"}));  // and it stops there, with Work running
    EXPECT_EQ(simulation.StoppedAt(), "state 0.4");
    EXPECT_EQ(simulation.Executed(), "advance 100");  // what the trace records: it replays the same
    EXPECT_EQ(simulation.Elapsed().count(), 100);
  }

  Simulation again("Errand");
  again.SetBreakpoints({}, {1});
  EXPECT_EQ(Run(again, "start"), Lines({"0.1 -> 0.2"}));
  EXPECT_EQ(again.StoppedAt(), "");
  Run(again, "finish Work");
  EXPECT_EQ(again.StoppedAt(), "transition 1");
}

TEST_F(SimulationTest, AWrongCommandIsRefusedAndChangesNothing) {
  Simulation simulation("Errand");
  Run(simulation, "start");
  EXPECT_THROW(Run(simulation, "finish Work Rest"), ScriptError);
  EXPECT_EQ(simulation.Running(), Lines({"Work"}));  // Work was not finished either
  for (const char* wrong : {"advance -1", "advance 1x", "advance 3600001", "publish t State NoSuchMessage",
                            "publish t Loud GameStateMessage", "publish t State GameStateMessage { nonsense: 1 }",
                            "jump", "start"}) {
    EXPECT_THROW(Run(simulation, wrong), ScriptError) << wrong;
  }
  EXPECT_EQ(simulation.Elapsed().count(), 0);
  EXPECT_EQ(Run(simulation, "active"), Lines({"active: 0.2"}));
}

TEST_F(SimulationTest, APublishedMessageIsReadBack) {
  Simulation simulation("Errand");
  Run(simulation, "publish worldstate State GameStateMessage { player_state: 3 }");
  EXPECT_EQ(Run(simulation, "read worldstate State GameStateMessage"), Lines({"GameStateMessage: { player_state: 3 }"}));
  EXPECT_EQ(Run(simulation, "read other State GameStateMessage"), Lines({"GameStateMessage: none"}));
}

TEST_F(SimulationTest, AScriptReadsBackWhatItsTranscriptWrites) {
  std::istringstream in("# a comment\nmodel Errand\nstart\n  0.1 -> 0.2\nadvance 10\n");
  const auto script = kse::simulation::ParseScript(in, "x.case");
  EXPECT_EQ(script.model, "Errand");
  ASSERT_EQ(script.commands.size(), 2u);
  EXPECT_EQ(script.commands[0].output, Lines({"0.1 -> 0.2"}));
  EXPECT_EQ(kse::simulation::Transcript(script.commands), "start\n  0.1 -> 0.2\nadvance 10\n");
  std::istringstream stray("model Errand\n  0.1 -> 0.2\nstart\n");
  try {
    kse::simulation::ParseScript(stray, "y.case");
    FAIL() << "a stray line was read";
  } catch (const ScriptError& e) {
    EXPECT_STREQ(e.what(), "y.case:2: an expected line before any command");
  }
}

// The session the tool talks to: commands in, one JSON line each out.
TEST_F(SimulationTest, ASessionAnswersEachCommandWithOneLine) {
  std::istringstream in("breakpoints state:0.4\nstart\nfinish Nobody\nfinish Work\nadvance 500\n" +
                        std::string(70000, 'x') + "\nquit\nstart\n");
  std::ostringstream out;
  auto* old_in = std::cin.rdbuf(in.rdbuf());
  auto* old_out = std::cout.rdbuf(out.rdbuf());
  const char* argv[] = {"kse-simulator", "--serve", "Errand"};
  const int status = kse::simulation::RunSimulator(3, const_cast<char**>(argv));
  std::cin.rdbuf(old_in);
  std::cout.rdbuf(old_out);
  EXPECT_EQ(status, 0);
  std::vector<std::string> lines;
  std::istringstream reply(out.str());
  for (std::string line; std::getline(reply, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 7u) << out.str();
  EXPECT_EQ(lines[0], R"({"type":"ready","model":"Errand","states":["Node_errand","0.1","0.2","0.3","0.4","0.5"],"transitions":4,"activities":[]})");
  EXPECT_EQ(lines[2], R"({"type":"result","ok":true,"command":"start","lines":["0.1 -> 0.2"],"taken":[{"tr":0,"from":"0.1","to":"0.2"}],"active":["Node_errand","0.2"],"running":["Work"],"since":[0],"time":0,"started":true})");
  EXPECT_EQ(lines[3], R"({"type":"result","ok":false,"command":"finish Nobody","error":"'Nobody' is not running","active":["Node_errand","0.2"],"running":["Work"],"since":[0],"time":0,"started":true})");
  EXPECT_EQ(lines[5], R"({"type":"result","ok":true,"command":"advance 100","lines":["0.3 -> 0.4"],"taken":[{"tr":2,"from":"0.3","to":"0.4"}],"stopped":"state 0.4","active":["Node_errand","0.4"],"running":["Work"],"since":[100],"time":100,"started":true})");
  EXPECT_NE(lines[6].find("longer than 64 KiB"), std::string::npos);
}

}  // namespace
