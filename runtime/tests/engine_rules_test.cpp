// The engine rules of docs/semantics.md through the engine's own API, one scripted scenario each,
// checked through ActiveStates(), hook logs and observers. Synchronous: Activate()/Step(). The
// same rules on generated code: tests/conformance.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_support.h"

namespace kse_test {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

class EngineRules : public ::testing::Test {
 protected:
  ManualClock clock;
  MessageHub hub{clock};
  Log log;
};

// ---------------------------------------------------------------------------------------------
// START activation
// ---------------------------------------------------------------------------------------------

TEST_F(EngineRules, ActivationEntersTheRootAndItsStart) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<OrState>("A", &chart);
  auto* aStart = chart.Add<StartState>("A_1", a);
  auto* x = chart.Add<BasicState>("X", a);
  chart.AddTransition(start, a);
  chart.AddTransition(aStart, x);

  EXPECT_THAT(chart.ActiveStates(), IsEmpty());
  chart.Activate();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Root_1"));
  // Entering an OR state activates its START.
  EXPECT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "A", "A_1"));
  EXPECT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "A", "X"));
  EXPECT_FALSE(chart.Step());
  EXPECT_EQ(chart.TransitionsTaken(), 2U);
}

TEST_F(EngineRules, StepActivatesOnFirstUseAndActivateIsIdempotent) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* x = chart.Add<BasicState>("X", &chart);
  chart.AddTransition(start, x);
  EXPECT_FALSE(chart.IsActivated());
  EXPECT_TRUE(chart.Step());
  EXPECT_TRUE(chart.IsActivated());
  chart.Activate();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "X"));
}

TEST_F(EngineRules, OrStateWithoutStartIsRejected) {
  Statechart chart("Root", hub, Inline());
  chart.Add<StartState>("Root_1", &chart);
  chart.Add<OrState>("Empty", &chart);
  EXPECT_THROW(chart.Activate(), std::logic_error);
}

TEST_F(EngineRules, AndStateWithNonOrChildIsRejected) {
  Statechart chart("Root", hub, Inline());
  chart.Add<StartState>("Root_1", &chart);
  auto* both = chart.Add<AndState>("Both", &chart);
  chart.Add<BasicState>("NotARegion", both);
  EXPECT_THROW(chart.Activate(), std::logic_error);
}

TEST_F(EngineRules, NoStructuralChangesAfterActivation) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  chart.Activate();
  EXPECT_THROW(chart.Add<BasicState>("Late", &chart), std::logic_error);
  EXPECT_THROW(chart.AddTransition(start, start), std::logic_error);
}

// ---------------------------------------------------------------------------------------------
// Inner transitions first; a composite moves when its inside cannot
// ---------------------------------------------------------------------------------------------

TEST_F(EngineRules, InnerTransitionsWinAndTheCompositeMovesWhenItsInsideCannot) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<OrState>("A", &chart);
  auto* aStart = chart.Add<StartState>("A_1", a);
  auto* x = chart.Add<BasicState>("X", a);
  auto* aEnd = chart.Add<EndState>("A_3", a);
  auto* b = chart.Add<BasicState>("B", &chart);
  auto outerEvals = Counter();
  chart.AddTransition(start, a);
  chart.AddTransition(aStart, x);
  chart.AddTransition(x, aEnd, Never());
  chart.AddTransition(a, b, When(Flag(true), outerEvals));

  chart.Activate();
  EXPECT_TRUE(chart.Step());  // Root_1 -> A
  EXPECT_TRUE(chart.Step());  // inner A_1 -> X: the inside moved, A's own transition is not tried
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "A", "X"));
  EXPECT_EQ(outerEvals->load(), 0);
  // X cannot move (its guard is false) and nothing runs: A tries its own transition, although
  // its END was never reached.
  EXPECT_TRUE(chart.Step());
  EXPECT_EQ(outerEvals->load(), 1);
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "B"));
}

TEST_F(EngineRules, DeepestTransitionFiresFirstAcrossSeveralLevels) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* outer = chart.Add<OrState>("Outer", &chart);
  auto* outerStart = chart.Add<StartState>("Outer_1", outer);
  auto* inner = chart.Add<OrState>("Inner", outer);
  auto* innerStart = chart.Add<StartState>("Inner_1", inner);
  auto* innerEnd = chart.Add<EndState>("Inner_2", inner);
  auto* outerEnd = chart.Add<EndState>("Outer_3", outer);
  auto* done = chart.Add<BasicState>("Done", &chart);
  auto* end = chart.Add<EndState>("Root_end", &chart);
  chart.AddTransition(start, outer);
  chart.AddTransition(outerStart, inner);
  chart.AddTransition(innerStart, innerEnd);
  chart.AddTransition(inner, outerEnd);
  chart.AddTransition(outer, done);
  chart.AddTransition(done, end);

  std::vector<std::string> taken;
  chart.SetObserver([&](const TransitionSegmentBase& t) { taken.push_back(t.Name()); });
  chart.RunUntilStable();
  EXPECT_THAT(taken, ElementsAre("Root_1_TO_Outer", "Outer_1_TO_Inner", "Inner_1_TO_Inner_2",
                                 "Inner_TO_Outer_3", "Outer_TO_Done", "Done_TO_Root_end"));
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Root_end"));
}

TEST_F(EngineRules, OrStateWithoutEndLeavesWhenItsInsideIsIdle) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* forever = chart.Add<OrState>("Forever", &chart);
  auto* fStart = chart.Add<StartState>("Forever_1", forever);
  auto* x = chart.Add<BasicState>("X", forever);
  auto* other = chart.Add<BasicState>("Other", &chart);
  auto evals = Counter();
  chart.AddTransition(start, forever);
  chart.AddTransition(fStart, x);
  chart.AddTransition(forever, other, When(Flag(true), evals));
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Other"));
  EXPECT_EQ(evals->load(), 1);
}

TEST_F(EngineRules, EndNeverStepsAndAFalseExitKeepsTheComposite) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<OrState>("A", &chart);
  auto* aStart = chart.Add<StartState>("A_1", a);
  auto* aEnd = chart.Add<EndState>("A_2", a);
  auto* b = chart.Add<BasicState>("B", &chart);
  auto evals = Counter();
  chart.AddTransition(start, a);
  chart.AddTransition(aStart, aEnd);
  chart.AddTransition(a, b, When(Flag(false), evals));
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "A", "A_2"));
  EXPECT_EQ(evals->load(), 1);
  EXPECT_FALSE(chart.Step());
  EXPECT_EQ(evals->load(), 2);
}

// ---------------------------------------------------------------------------------------------
// Guarded before unguarded; model order
// ---------------------------------------------------------------------------------------------

TEST_F(EngineRules, GuardedTransitionsAreTriedBeforeUnguardedOnes) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* s = chart.Add<BasicState>("S", &chart);
  auto* unguarded = chart.Add<BasicState>("Unguarded", &chart);
  auto* guarded = chart.Add<BasicState>("Guarded", &chart);
  chart.AddTransition(start, s);
  chart.AddTransition(s, unguarded);           // first in model order, but unguarded
  chart.AddTransition(s, guarded, Always());  // guarded: tried first
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Guarded"));
  ASSERT_EQ(s->Outgoing().size(), 2U);
  EXPECT_EQ(s->Outgoing()[0]->Target(), guarded);
}

TEST_F(EngineRules, UnguardedTransitionFiresWhenNoGuardHolds) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* s = chart.Add<BasicState>("S", &chart);
  auto* unguarded = chart.Add<BasicState>("Unguarded", &chart);
  auto* guarded = chart.Add<BasicState>("Guarded", &chart);
  auto evals = Counter();
  chart.AddTransition(start, s);
  chart.AddTransition(s, unguarded);
  chart.AddTransition(s, guarded, When(Flag(false), evals));
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Unguarded"));
  EXPECT_EQ(evals->load(), 1);
}

TEST_F(EngineRules, AmongGuardedTransitionsTheLastCreatedIsTriedFirst) {
  for (bool b1First : {true, false}) {
    Statechart chart("Root", hub, Inline());
    auto* start = chart.Add<StartState>("Root_1", &chart);
    auto* s = chart.Add<BasicState>("S", &chart);
    auto* b1 = chart.Add<BasicState>("B1", &chart);
    auto* b2 = chart.Add<BasicState>("B2", &chart);
    chart.AddTransition(start, s);
    auto firstEvals = Counter();
    if (b1First) {
      chart.AddTransition(s, b1, When(Flag(true), firstEvals));
      chart.AddTransition(s, b2, Always());
    } else {
      chart.AddTransition(s, b2, When(Flag(true), firstEvals));
      chart.AddTransition(s, b1, Always());
    }
    chart.RunUntilStable();
    EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", b1First ? "B2" : "B1"));
    EXPECT_EQ(firstEvals->load(), 0) << "the first true guard wins; later ones are not evaluated";
  }
}

TEST_F(EngineRules, AmongUnguardedTransitionsModelOrderDecides) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* s = chart.Add<BasicState>("S", &chart);
  auto* b1 = chart.Add<BasicState>("B1", &chart);
  auto* b2 = chart.Add<BasicState>("B2", &chart);
  chart.AddTransition(start, s);
  chart.AddTransition(s, b2);
  chart.AddTransition(s, b1);
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "B2"));
}

// ---------------------------------------------------------------------------------------------
// Exit/entry order around the lowest common ancestor
// ---------------------------------------------------------------------------------------------

TEST_F(EngineRules, TransitionExitsUpToTheLcaRunsTheActionThenEntersDownToTheTarget) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* p = chart.Add<Probe<OrState>>(&log, "P", &chart);
  auto* pStart = chart.Add<Probe<StartState>>(&log, "P_1", p);
  auto* q = chart.Add<Probe<OrState>>(&log, "Q", p);
  auto* qStart = chart.Add<Probe<StartState>>(&log, "Q_1", q);
  auto* s = chart.Add<Probe<BasicState>>(&log, "S", q,
                                         std::make_unique<CountingActivity>(Counter(), &log, "S"));
  auto* t = chart.Add<Probe<OrState>>(&log, "T", &chart);
  chart.Add<Probe<StartState>>(&log, "T_1", t);
  auto* u = chart.Add<Probe<OrState>>(&log, "U", t);
  chart.Add<Probe<StartState>>(&log, "U_1", u);
  auto* v = chart.Add<Probe<OrState>>(&log, "V", u);
  chart.Add<Probe<StartState>>(&log, "V_1", v);
  chart.AddTransition(start, p);
  chart.AddTransition(pStart, q);
  chart.AddTransition(qStart, s);
  auto* cross = chart.AddTransition(s, v, nullptr, Logs(&log, "action S->V"));

  chart.Activate();
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "P", "Q", "S"));
  log.Clear();
  ASSERT_TRUE(chart.Step());
  EXPECT_EQ(cross->LowestCommonAncestor(), chart.Root());
  EXPECT_THAT(log.Events(), ElementsAre("exit S", "exit Q", "exit P", "action S->V", "enter T",
                                        "enter U", "enter V", "enter V_1"));
  // Entered along the path: the STARTs of T and U stay inactive.
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "T", "U", "V", "V_1"));
}

TEST_F(EngineRules, StatesAboveTheLcaStayActive) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* p = chart.Add<Probe<OrState>>(&log, "P", &chart);
  auto* pStart = chart.Add<Probe<StartState>>(&log, "P_1", p);
  auto* x = chart.Add<Probe<BasicState>>(&log, "X", p);
  auto* y = chart.Add<Probe<BasicState>>(&log, "Y", p);
  chart.AddTransition(start, p);
  chart.AddTransition(pStart, x);
  auto* xy = chart.AddTransition(x, y, nullptr, Logs(&log, "action"));
  chart.RunUntilStable();
  EXPECT_EQ(xy->LowestCommonAncestor(), p);
  EXPECT_THAT(log.Events(), ElementsAre("enter P", "enter P_1", "exit P_1", "enter X", "exit X",
                                        "action", "enter Y"));
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "P", "Y"));
}

TEST_F(EngineRules, SelfLoopExitsAndReentersTheState) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto runs = Counter();
  auto* x = chart.Add<Probe<BasicState>>(&log, "X", &chart,
                                         std::make_unique<CountingActivity>(runs, &log, "X"));
  auto again = Flag(true);
  chart.AddTransition(start, x);
  auto* loop = chart.AddTransition(x, x, When(again), Logs(&log, "loop action"));
  chart.Activate();
  ASSERT_TRUE(chart.Step());
  log.Clear();
  ASSERT_TRUE(chart.Step());
  EXPECT_EQ(loop->LowestCommonAncestor(), chart.Root());
  EXPECT_THAT(log.Events(), ElementsAre("exit X", "loop action", "enter X", "run X"));
  again->store(false);
  EXPECT_FALSE(chart.Step());
  EXPECT_EQ(runs->load(), 2);
}

TEST_F(EngineRules, LeavingACompositeStateExitsItsActiveDescendantsInnermostFirst) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<Probe<OrState>>(&log, "A", &chart);
  auto* aStart = chart.Add<Probe<StartState>>(&log, "A_1", a);
  auto* aEnd = chart.Add<Probe<EndState>>(&log, "A_2", a);
  auto* b = chart.Add<Probe<BasicState>>(&log, "B", &chart);
  chart.AddTransition(start, a);
  chart.AddTransition(aStart, aEnd);
  chart.AddTransition(a, b, nullptr, Logs(&log, "action"));
  chart.RunUntilStable();
  EXPECT_THAT(log.Events(), ElementsAre("enter A", "enter A_1", "exit A_1", "enter A_2",
                                        "exit A_2", "exit A", "action", "enter B"));
}

TEST_F(EngineRules, TransitionIntoANestedStateOfAnAndEntersTheOtherRegionsByDefault) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* both = chart.Add<Probe<AndState>>(&log, "Both", &chart);
  auto* r1 = chart.Add<Probe<OrState>>(&log, "R1", both);
  chart.Add<Probe<StartState>>(&log, "R1_1", r1);
  auto* deep = chart.Add<Probe<BasicState>>(&log, "Deep", r1);
  auto* r2 = chart.Add<Probe<OrState>>(&log, "R2", both);
  chart.Add<Probe<StartState>>(&log, "R2_1", r2);
  chart.AddTransition(start, deep);
  chart.Activate();
  log.Clear();
  ASSERT_TRUE(chart.Step());
  EXPECT_THAT(log.Events(),
              ElementsAre("enter Both", "enter R1", "enter Deep", "enter R2", "enter R2_1"));
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "Deep", "R2", "R2_1"));
}

// ---------------------------------------------------------------------------------------------
// Condition connectors
// ---------------------------------------------------------------------------------------------

TEST_F(EngineRules, ConnectorChainIsTakenAtomically) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<Probe<StartState>>(&log, "Root_1", &chart);
  auto* c1 = chart.Add<Probe<ConditionConnector>>(&log, "C1", &chart);
  auto* c2 = chart.Add<Probe<ConditionConnector>>(&log, "C2", &chart);
  auto* x = chart.Add<Probe<BasicState>>(&log, "X", &chart);
  chart.AddTransition(start, c1, nullptr, Logs(&log, "a1"));
  chart.AddTransition(c1, c2, Always(), Logs(&log, "a2"));
  chart.AddTransition(c2, x, Always(), Logs(&log, "a3"));
  std::vector<std::string> taken;
  chart.SetObserver([&](const TransitionSegmentBase& t) { taken.push_back(t.Name()); });

  chart.Activate();
  log.Clear();
  EXPECT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "X"));
  EXPECT_THAT(taken, ElementsAre("Root_1_TO_C1", "C1_TO_C2", "C2_TO_X"));
  EXPECT_THAT(log.Events(), ElementsAre("exit Root_1", "a1", "enter C1", "exit C1", "a2",
                                        "enter C2", "exit C2", "a3", "enter X"));
  EXPECT_FALSE(chart.Step());
}

TEST_F(EngineRules, ConnectorIsNotEnteredWhenNoOutgoingGuardHolds) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* c = chart.Add<ConditionConnector>("C", &chart);
  auto* x = chart.Add<BasicState>("X", &chart);
  auto* y = chart.Add<BasicState>("Y", &chart);
  auto toY = Flag(false);
  chart.AddTransition(start, c, nullptr, Logs(&log, "into C"));
  chart.AddTransition(c, x, Never());
  chart.AddTransition(c, y, When(toY));

  chart.Activate();
  EXPECT_FALSE(chart.Step());
  EXPECT_FALSE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Root_1"));
  EXPECT_THAT(log.Events(), IsEmpty()) << "no action of a chain that is not taken may run";
  EXPECT_EQ(chart.TransitionsTaken(), 0U);

  toY->store(true);
  EXPECT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Y"));
  EXPECT_THAT(log.Events(), ElementsAre("into C"));
}

TEST_F(EngineRules, ConnectorChainBacktracksWhenALaterConnectorIsBlocked) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* c1 = chart.Add<ConditionConnector>("C1", &chart);
  auto* c2 = chart.Add<ConditionConnector>("C2", &chart);
  auto* x = chart.Add<BasicState>("X", &chart);
  auto* y = chart.Add<BasicState>("Y", &chart);
  chart.AddTransition(start, c1);
  chart.AddTransition(c1, y, Always(), Logs(&log, "C1->Y"));
  chart.AddTransition(c1, c2, Always(), Logs(&log, "C1->C2"));  // created last: tried first
  chart.AddTransition(c2, x, Never());
  chart.RunUntilStable();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Y"));
  EXPECT_THAT(log.Events(), ElementsAre("C1->Y"));
}

TEST_F(EngineRules, UnguardedConnectorBranchIsTheElseBranch) {
  for (bool guardHolds : {false, true}) {
    Statechart chart("Root", hub, Inline());
    auto* start = chart.Add<StartState>("Root_1", &chart);
    auto* c = chart.Add<ConditionConnector>("C", &chart);
    auto* otherwise = chart.Add<BasicState>("Otherwise", &chart);
    auto* guarded = chart.Add<BasicState>("Guarded", &chart);
    chart.AddTransition(start, c);
    chart.AddTransition(c, otherwise);
    chart.AddTransition(c, guarded, When(Flag(guardHolds)));
    chart.RunUntilStable();
    EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", guardHolds ? "Guarded" : "Otherwise"));
  }
}

TEST_F(EngineRules, OrPatternOfTheTransformationChoosesByGuard) {
  // t1 | t2 : START -> CONDITION -> t_i -> END, as the formula transformation builds it.
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("0_1", &chart);
  auto* choice = chart.Add<ConditionConnector>("0_2", &chart);
  auto* playing = chart.Add<BasicState>("Playing", &chart);
  auto* other = chart.Add<BasicState>("NonPlaying", &chart);
  auto* end = chart.Add<EndState>("0_5", &chart);
  auto play = Flag(false);
  auto notPlay = Flag(false);
  chart.AddTransition(start, choice);
  chart.AddTransition(choice, playing, When(play));
  chart.AddTransition(choice, other, When(notPlay));
  chart.AddTransition(playing, end);
  chart.AddTransition(other, end);
  chart.Activate();
  EXPECT_FALSE(chart.Step());
  notPlay->store(true);
  EXPECT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "NonPlaying"));
  EXPECT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "0_5"));
}

// ---------------------------------------------------------------------------------------------
// AND states
// ---------------------------------------------------------------------------------------------

struct TwoRegions {
  Statechart* chart;
  AndState* both;
  OrState* r1;
  OrState* r2;
  StartState* r1Start;
  StartState* r2Start;
};

TwoRegions BuildTwoRegions(Statechart& chart) {
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* both = chart.Add<AndState>("Both", &chart);
  auto* r1 = chart.Add<OrState>("R1", both);
  auto* r1Start = chart.Add<StartState>("R1_1", r1);
  auto* r2 = chart.Add<OrState>("R2", both);
  auto* r2Start = chart.Add<StartState>("R2_1", r2);
  chart.AddTransition(start, both);
  return {&chart, both, r1, r2, r1Start, r2Start};
}

TEST_F(EngineRules, AllAndRegionsAreActiveTogether) {
  Statechart chart("Root", hub, Inline());
  auto regions = BuildTwoRegions(chart);
  auto* a1 = chart.Add<BasicState>("A1", regions.r1);
  auto* a2 = chart.Add<BasicState>("A2", regions.r2);
  chart.AddTransition(regions.r1Start, a1);
  chart.AddTransition(regions.r2Start, a2);
  chart.Activate();
  ASSERT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "R1_1", "R2", "R2_1"));
  // One step moves every region.
  ASSERT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "A1", "R2", "A2"));
}

TEST_F(EngineRules, EachAndRegionHasItsOwnBlackboard) {
  Statechart chart("Root", hub, Inline());
  auto regions = BuildTwoRegions(chart);
  auto* a1 = chart.Add<BasicState>("A1", regions.r1,
                                   std::make_unique<CountingActivity>(Counter()));
  auto* inner = chart.Add<OrState>("Inner", regions.r2);
  auto* innerStart = chart.Add<StartState>("Inner_1", inner);
  auto* a2 = chart.Add<BasicState>("A2", inner, std::make_unique<CountingActivity>(Counter()));
  auto* t1 = chart.AddTransition(regions.r1Start, a1, Always(), Logs(&log, "x"));
  auto* t2 = chart.AddTransition(regions.r2Start, inner, Always());
  auto* t3 = chart.AddTransition(innerStart, a2, Always());
  chart.Activate();

  Blackboard* root = &chart.RootBlackboard();
  Blackboard* b1 = chart.ScopeOf(regions.r1);
  Blackboard* b2 = chart.ScopeOf(regions.r2);
  ASSERT_NE(b1, nullptr);
  ASSERT_NE(b2, nullptr);
  EXPECT_NE(b1, b2);
  EXPECT_NE(b1, root);
  EXPECT_EQ(chart.ScopeOf(chart.Root()), root);
  EXPECT_EQ(chart.ScopeOf(regions.both), root);
  EXPECT_EQ(chart.ScopeOf(a1), b1);
  EXPECT_EQ(chart.ScopeOf(a2), b2);
  EXPECT_EQ(chart.ActivityOf(a1)->GetBlackboard(), b1);
  EXPECT_EQ(chart.ActivityOf(a2)->GetBlackboard(), b2);
  // Guards and actions get the scope of the transition's LCA.
  EXPECT_EQ(chart.ConditionOf(t1)->GetBlackboard(), b1);
  EXPECT_EQ(chart.ActionOf(t1)->GetBlackboard(), b1);
  EXPECT_EQ(chart.ConditionOf(t2)->GetBlackboard(), b2);
  EXPECT_EQ(chart.ConditionOf(t3)->GetBlackboard(), b2);
  EXPECT_EQ(chart.ScopeOf(chart.Transitions()[0]), root);  // Root_1 -> Both
}

TEST_F(EngineRules, ASignalIsSeenOnceByEachRegion) {
  Statechart chart("Root", hub, Inline());
  auto regions = BuildTwoRegions(chart);
  auto* a1 = chart.Add<BasicState>("A1", regions.r1);
  auto* b1 = chart.Add<BasicState>("B1", regions.r1);
  auto* a2 = chart.Add<BasicState>("A2", regions.r2);
  auto* b2 = chart.Add<BasicState>("B2", regions.r2);
  auto signalled = [] {
    return If(
        [](Blackboard& blk) {
          blk.ProcessMessages();
          return blk.ReadSignal<HeadToBMessage>("events") != nullptr;
        },
        {"events"});
  };
  chart.AddTransition(regions.r1Start, a1, signalled());
  chart.AddTransition(a1, b1, signalled());
  chart.AddTransition(regions.r2Start, a2, signalled());
  chart.AddTransition(a2, b2, signalled());
  while (chart.Step()) {
  }
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "R1_1", "R2", "R2_1"));
  EXPECT_EQ(hub.SubscriberCount("events"), 2U);

  HeadToBMessage message;
  message.set_ballfound(1);
  chart.RootBlackboard().Publish("events", Kind::Signal, message);
  while (chart.Step()) {
  }
  // Each region consumed its own copy of the one signal, and only once.
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "A1", "R2", "A2"));

  chart.RootBlackboard().Publish("events", Kind::Signal, message);
  while (chart.Step()) {
  }
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "B1", "R2", "B2"));
}

TEST_F(EngineRules, AndStateIsLeftWhenNoRegionMovesAndNoneRuns) {
  Statechart chart("Root", hub, Pooled());
  auto regions = BuildTwoRegions(chart);
  auto* end1 = chart.Add<EndState>("R1_2", regions.r1);
  auto gate = std::make_shared<Gate>();
  auto started = Counter();
  auto* x2 = chart.Add<BasicState>("X2", regions.r2, std::make_unique<BlockingActivity>(gate, started));
  auto* end2 = chart.Add<EndState>("R2_3", regions.r2);
  auto* after = chart.Add<BasicState>("After", &chart);
  auto leaveEvals = Counter();
  chart.AddTransition(regions.r1Start, end1);
  chart.AddTransition(regions.r2Start, x2);
  chart.AddTransition(x2, end2, Never());
  chart.AddTransition(regions.both, after, When(Flag(true), leaveEvals));
  chart.RunIfWoken();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "R1_2", "R2", "X2"));
  EXPECT_TRUE(chart.IsRunning(regions.r2));
  EXPECT_FALSE(chart.IsRunning(regions.r1));
  EXPECT_EQ(leaveEvals->load(), 0) << "X2 runs in a region: the AND state waits";
  gate->Open();
  ASSERT_TRUE(WaitUntil([&] { return chart.RunningActivities() == 0U; }));
  EXPECT_TRUE(chart.RunIfWoken()) << "the activity's end woke the engine";
  // X2's own transition is false and nothing runs: the AND state leaves, its regions unfinished.
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "After"));
  EXPECT_EQ(leaveEvals->load(), 1);
}

TEST_F(EngineRules, RegionsExitInReverseOrderWhenTheAndStateIsLeft) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* both = chart.Add<Probe<AndState>>(&log, "Both", &chart);
  auto* r1 = chart.Add<Probe<OrState>>(&log, "R1", both);
  auto* r1Start = chart.Add<StartState>("R1_1", r1);
  auto* r1End = chart.Add<Probe<EndState>>(&log, "R1_2", r1);
  auto* r2 = chart.Add<Probe<OrState>>(&log, "R2", both);
  auto* r2Start = chart.Add<StartState>("R2_1", r2);
  auto* r2End = chart.Add<Probe<EndState>>(&log, "R2_2", r2);
  auto* after = chart.Add<Probe<BasicState>>(&log, "After", &chart);
  chart.AddTransition(start, both);
  chart.AddTransition(r1Start, r1End);
  chart.AddTransition(r2Start, r2End);
  chart.AddTransition(both, after, nullptr, Logs(&log, "action"));
  ASSERT_TRUE(chart.Step());  // Root_1 -> Both
  ASSERT_TRUE(chart.Step());  // both regions reach their END in the same step
  log.Clear();
  ASSERT_TRUE(chart.Step());
  EXPECT_THAT(log.Events(), ElementsAre("exit R2_2", "exit R2", "exit R1_2", "exit R1",
                                        "exit Both", "action", "enter After"));
}

// A step starts where the last transition left the configuration: from the deepest state when
// it is one path from the root, from the root when an AND state is active. Round and round
// between an AND state and an OR state, then out of a region, every step's states are checked.
TEST_F(EngineRules, EachStepStartsFromTheConfigurationTheLastTransitionLeft) {
  Statechart chart("Root", hub, Inline());
  auto regions = BuildTwoRegions(chart);
  auto* x1 = chart.Add<BasicState>("X1", regions.r1);
  auto* y = chart.Add<BasicState>("Y", regions.r2);
  auto* q = chart.Add<OrState>("Q", &chart);
  auto* qStart = chart.Add<StartState>("Q_1", q);
  auto* z = chart.Add<BasicState>("Z", q);
  auto* out = chart.Add<BasicState>("Out", &chart);
  auto leave = Flag(false);
  chart.AddTransition(regions.r1Start, x1);
  chart.AddTransition(regions.r2Start, y);
  chart.AddTransition(x1, out, When(leave));
  chart.AddTransition(regions.both, q);
  chart.AddTransition(qStart, z);
  chart.AddTransition(q, regions.both);
  chart.Activate();
  for (int round = 0; round < 2; ++round) {
    ASSERT_TRUE(chart.Step());
    EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "R1_1", "R2", "R2_1"));
    ASSERT_TRUE(chart.Step());  // both regions move in one step
    EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Both", "R1", "X1", "R2", "Y"));
    ASSERT_TRUE(chart.Step());
    EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Q", "Q_1"));
    ASSERT_TRUE(chart.Step());
    EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Q", "Z"));
  }
  ASSERT_TRUE(chart.Step());  // Q -> Both
  ASSERT_TRUE(chart.Step());
  leave->store(true);
  ASSERT_TRUE(chart.Step());  // out of region R1: the whole AND state is left
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Out"));
  EXPECT_FALSE(chart.Step());
  EXPECT_EQ(chart.TransitionsTaken(), 14U);  // a step of both regions takes two
}

// User code that steps the statechart while a transition fires (its lock is recursive): the
// next step starts from what that inner step left, not from the outer transition's target.
TEST_F(EngineRules, AStepTakenByUserCodeDuringATransitionIsNotUndone) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<BasicState>("A", &chart);
  auto* b = chart.Add<BasicState>("B", &chart);
  auto* c = chart.Add<BasicState>("C", &chart);
  auto* d = chart.Add<BasicState>("D", &chart);
  chart.AddTransition(start, a);
  chart.AddTransition(a, b);
  chart.AddTransition(c, d);
  chart.AddTransition(b, c);
  std::vector<std::string> fired;
  chart.SetObserver([&](const TransitionSegmentBase& t) {
    fired.push_back(t.Source()->Name() + ">" + t.Target()->Name());
    if (t.Target() == b) chart.Step();  // B -> C, inside A -> B
  });
  chart.Activate();
  ASSERT_TRUE(chart.Step());
  ASSERT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "C"));
  ASSERT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "D"));
  EXPECT_THAT(fired, ElementsAre("Root_1>A", "A>B", "B>C", "C>D"));
}

// ---------------------------------------------------------------------------------------------
// Timeouts (ManualClock)
// ---------------------------------------------------------------------------------------------

TEST_F(EngineRules, TimeoutCheckHoldsOnlyOnceTheClockPassesTheWakeupTime) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* waiting = chart.Add<BasicState>("Waiting", &chart);
  auto* done = chart.Add<BasicState>("Done", &chart);
  chart.AddTransition(start, waiting, nullptr, std::make_unique<TimeoutAction>("behavior", 250));
  chart.AddTransition(waiting, done, TimeoutCheck("behavior"));
  chart.Activate();
  auto timeout = chart.RootBlackboard().ReadState<TimeoutMsg>("behavior");
  ASSERT_NE(timeout, nullptr) << "every TimeoutAction publishes an empty TimeoutMsg at start";
  EXPECT_TRUE(timeout->wakeup().empty());
  EXPECT_FALSE(statechart_engine::TimeoutCheck(chart.RootBlackboard(), timeout))
      << "no wake-up time: false";
  ASSERT_TRUE(chart.Step());
  timeout = chart.RootBlackboard().ReadState<TimeoutMsg>("behavior");
  EXPECT_FALSE(timeout->wakeup().empty());
  EXPECT_EQ(chart.RootBlackboard().NextWakeup(), clock.Now() + std::chrono::milliseconds(250));
  EXPECT_FALSE(chart.Step());
  clock.Advance(std::chrono::milliseconds(249));
  EXPECT_FALSE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Waiting"));
  clock.Advance(std::chrono::milliseconds(1));
  EXPECT_TRUE(chart.Step());
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "Done"));
}

TEST_F(EngineRules, TheEngineRunsOnlyWhenWokenByATimerOrAnActivity) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* waiting = chart.Add<BasicState>("Waiting", &chart);
  auto* done = chart.Add<BasicState>("Done", &chart);
  auto evals = Counter();
  chart.AddTransition(start, waiting, nullptr, std::make_unique<TimeoutAction>("behavior", 100));
  chart.AddTransition(waiting, done, When(Flag(false), evals));
  EXPECT_TRUE(chart.RunIfWoken()) << "activation wakes it";
  EXPECT_EQ(evals->load(), 1);
  chart.Wake();
  hub.Publish("behavior", Kind::State, std::make_shared<HeadToBMessage>());
  EXPECT_FALSE(chart.RunIfWoken()) << "a publish or a look at the clock is no reason";
  clock.Advance(std::chrono::milliseconds(99));
  EXPECT_FALSE(chart.RunIfWoken());
  EXPECT_EQ(evals->load(), 1);
  clock.Advance(std::chrono::milliseconds(1));
  EXPECT_TRUE(chart.RunIfWoken()) << "the wake-up time passed";
  EXPECT_EQ(evals->load(), 2);
  EXPECT_FALSE(chart.RunIfWoken());
}

TEST_F(EngineRules, PollingSelfLoopRearmsItsTimer) {
  // The Goalie's pattern: X -> X [TimeoutCheck(behavior) && ...] / TimeoutAction.behavior.250
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto runs = Counter();
  auto* scan = chart.Add<BasicState>("Scan", &chart, std::make_unique<CountingActivity>(runs));
  chart.AddTransition(start, scan, nullptr, std::make_unique<TimeoutAction>("behavior", 250));
  chart.AddTransition(scan, scan, TimeoutCheck("behavior"),
                      std::make_unique<TimeoutAction>("behavior", 250));
  chart.RunUntilStable();
  EXPECT_EQ(runs->load(), 1);
  for (int i = 0; i < 4; ++i) {
    clock.Advance(std::chrono::milliseconds(100));
    chart.RunUntilStable();
  }
  EXPECT_EQ(runs->load(), 2);  // at 250 ms (checked at 300 ms), re-armed to 550 ms
  clock.Advance(std::chrono::milliseconds(200));  // 600 ms
  chart.RunUntilStable();
  EXPECT_EQ(runs->load(), 3);
  EXPECT_EQ(chart.RootBlackboard().NextWakeup(), clock.Now() + std::chrono::milliseconds(250));
}

// ---------------------------------------------------------------------------------------------
// Failures of user code
// ---------------------------------------------------------------------------------------------

class ThrowingCondition : public ICondition {
 public:
  bool Eval() override { throw std::runtime_error("guard failure for the test"); }
};

class ThrowingAction : public IAction {
 public:
  void Execute() override { throw std::runtime_error("action failure for the test"); }
};

TEST_F(EngineRules, ThrowingGuardCountsAsFalse) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<BasicState>("A", &chart);
  auto* b = chart.Add<BasicState>("B", &chart);
  chart.AddTransition(start, a, std::make_unique<ThrowingCondition>());
  chart.AddTransition(start, b);
  ::testing::internal::CaptureStderr();
  chart.RunUntilStable();
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "B"));
  EXPECT_EQ(chart.GuardFailures(), 1U);
  EXPECT_THAT(err, ::testing::HasSubstr("guard failure for the test"));
}

TEST_F(EngineRules, ThrowingActionIsCountedAndTheTransitionCompletes) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<BasicState>("A", &chart);
  chart.AddTransition(start, a, nullptr, std::make_unique<ThrowingAction>());
  ::testing::internal::CaptureStderr();
  chart.RunUntilStable();
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_THAT(chart.ActiveStates(), ElementsAre("Root", "A"));
  EXPECT_EQ(chart.ActionFailures(), 1U);
  EXPECT_THAT(err, ::testing::HasSubstr("action failure for the test"));
}

TEST_F(EngineRules, RunUntilStableGivesUpOnAnEndlessLoop) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* x = chart.Add<BasicState>("X", &chart);
  chart.AddTransition(start, x);
  chart.AddTransition(x, x);
  ::testing::internal::CaptureStderr();
  EXPECT_FALSE(chart.RunUntilStable(100));
  ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(chart.TransitionsTaken(), 100U);
}

TEST_F(EngineRules, ObserverSeesEveryTransitionWithItsEnds) {
  Statechart chart("Root", hub, Inline());
  auto* start = chart.Add<StartState>("Root_1", &chart);
  auto* a = chart.Add<BasicState>("A", &chart);
  auto* end = chart.Add<EndState>("Root_3", &chart);
  chart.AddTransition(start, a);
  chart.AddTransition(a, end);
  std::vector<std::pair<State*, State*>> seen;
  chart.SetObserver([&](const TransitionSegmentBase& t) { seen.emplace_back(t.Source(), t.Target()); });
  chart.RunUntilStable();
  ASSERT_EQ(seen.size(), 2U);
  EXPECT_EQ(seen[0].first, start);
  EXPECT_EQ(seen[0].second, a);
  EXPECT_EQ(seen[1].first, a);
  EXPECT_EQ(seen[1].second, end);
}

}  // namespace
}  // namespace kse_test
