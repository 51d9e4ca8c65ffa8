// Statecharts made from one shared Definition (ADR 0032): each runs on its own, makes its own
// guards, actions and activities, and a definition given objects makes only one statechart.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "test_support.h"

namespace kse_test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// A guard whose outcome is the statechart's own: each one reads its blackboard's "go" flag.
class GoFlag : public ICondition {
 public:
  explicit GoFlag(std::shared_ptr<std::atomic<int>> made) { ++*made; }
  bool Eval() override { return go_; }
  void Set() { go_ = true; }

 private:
  bool go_ = false;
};

class Named : public IActivity {
 public:
  Named(std::string name, std::shared_ptr<std::atomic<int>> runs) : name_(std::move(name)), runs_(std::move(runs)) {}
  int Execute() override {
    ++*runs_;
    return 0;
  }
  std::string GetName() override { return name_; }

 private:
  std::string name_;
  std::shared_ptr<std::atomic<int>> runs_;
};

struct Chart {
  std::shared_ptr<const Definition> definition;
  BasicState* wait = nullptr;
  BasicState* work = nullptr;
  TransitionSegmentBase* go = nullptr;
};

// START -> Wait -[GoFlag]-> Work -> END, Wait and Work running a Named activity.
Chart MakeChart(std::shared_ptr<std::atomic<int>> guards_made, std::shared_ptr<std::atomic<int>> runs) {
  Chart chart;
  auto definition = std::make_shared<Definition>("Shared");
  OrState* root = definition->Root();
  auto* start = definition->Add<StartState>("Start", root);
  chart.wait = definition->Add<BasicState>("Wait", root, Make<Named>("Waiting", runs));
  chart.work = definition->Add<BasicState>("Work", root, Make<Named>("Working", runs));
  auto* end = definition->Add<EndState>("End", root);
  definition->AddTransition(start, chart.wait);
  chart.go = definition->AddTransition(chart.wait, chart.work, Make<GoFlag>(guards_made));
  definition->AddTransition(chart.work, end);
  definition->Complete();
  chart.definition = definition;
  return chart;
}

Options InlineOptions() {
  Options options;
  options.inline_activities = true;
  return options;
}

TEST(SharedDefinition, EachStatechartRunsOnItsOwnWithItsOwnParts) {
  MessageHub hub;
  auto guards_made = Counter();
  auto runs = Counter();
  Chart shape = MakeChart(guards_made, runs);
  Statechart one(shape.definition, hub, InlineOptions());
  Statechart two(shape.definition, hub, InlineOptions());
  one.RunUntilStable();
  two.RunUntilStable();
  EXPECT_EQ(guards_made->load(), 2) << "a guard made for each statechart";
  EXPECT_NE(one.ConditionOf(shape.go), two.ConditionOf(shape.go));
  EXPECT_NE(one.ActivityOf(shape.wait), two.ActivityOf(shape.wait));
  EXPECT_THAT(one.ActiveStates(), ElementsAre("Shared", "Wait"));

  static_cast<GoFlag*>(one.ConditionOf(shape.go))->Set();
  EXPECT_TRUE(one.Step());
  EXPECT_THAT(one.ActiveStates(), ElementsAre("Shared", "Work"));
  EXPECT_THAT(two.ActiveStates(), ElementsAre("Shared", "Wait")) << "the other statechart did not move";
  EXPECT_TRUE(one.IsActive(shape.work));
  EXPECT_FALSE(two.IsActive(shape.work));
  EXPECT_EQ(one.Launches(shape.work), 1U);
  EXPECT_EQ(two.Launches(shape.work), 0U);
  EXPECT_EQ(one.ScopeOf(shape.go), &one.RootBlackboard());
  EXPECT_EQ(two.ScopeOf(shape.go), &two.RootBlackboard());
  EXPECT_EQ(&one.GetDefinition(), &two.GetDefinition());
}

TEST(SharedDefinition, StatechartsOnManyThreadsShareOneDefinition) {
  MessageHub hub;
  auto guards_made = Counter();
  auto runs = Counter();
  Chart shape = MakeChart(guards_made, runs);
  std::vector<std::thread> threads;
  std::atomic<int> settled{0};
  for (int i = 0; i < 8; ++i) {
    threads.emplace_back([&] {
      Statechart chart(shape.definition, hub, InlineOptions());
      chart.RunUntilStable();
      if (chart.IsActive(shape.wait)) ++settled;
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(settled.load(), 8);
  EXPECT_EQ(runs->load(), 8) << "each statechart ran its own Wait once";
}

TEST(SharedDefinition, TheStructureIsRefusedWhenTheDefinitionIsNotComplete) {
  MessageHub hub;
  auto definition = std::make_shared<Definition>("Incomplete");
  definition->Add<StartState>("Start", definition->Root());
  EXPECT_THROW(Statechart(definition, hub), std::logic_error);
  auto bad = std::make_shared<Definition>("NoStart");
  bad->Add<BasicState>("Lonely", bad->Root());
  try {
    bad->Complete();
    FAIL() << "an OR state without START completes";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("'NoStart' needs exactly one START child"));
  }
}

TEST(SharedDefinition, GivenObjectsMakeOneStatechartOnly) {
  MessageHub hub;
  auto definition = std::make_shared<Definition>("Given");
  auto* start = definition->Add<StartState>("Start", definition->Root());
  auto* work = definition->Add<BasicState>("Work", definition->Root(), std::make_unique<CountingActivity>(Counter()));
  definition->AddTransition(start, work);
  definition->Complete();
  EXPECT_TRUE(definition->HasGivenParts());
  Statechart first(definition, hub, InlineOptions());
  first.Activate();
  Statechart second(definition, hub, InlineOptions());
  try {
    second.Activate();
    FAIL() << "a second statechart took the given activity";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("'Given'"));
    EXPECT_THAT(e.what(), HasSubstr("makes one statechart only"));
  }
}

TEST(SharedDefinition, ACreatedPartIsMadeByItsFunctionForEachStatechart) {
  MessageHub hub;
  auto made = Counter();
  auto runs = Counter();
  auto definition = std::make_shared<Definition>("Created");
  auto* start = definition->Add<StartState>("Start", definition->Root());
  auto* work = definition->Add<BasicState>("Work", definition->Root(), Part<IActivity>::Created([made, runs] {
                                             ++*made;
                                             return std::make_unique<CountingActivity>(runs);
                                           }));
  definition->AddTransition(start, work);
  definition->Complete();
  Statechart one(definition, hub, InlineOptions());
  Statechart two(definition, hub, InlineOptions());
  one.RunUntilStable();
  two.RunUntilStable();
  EXPECT_EQ(made->load(), 2);
  EXPECT_EQ(runs->load(), 2);
  EXPECT_NE(one.ActivityOf(work), two.ActivityOf(work));
}

TEST(SharedDefinition, AStatechartMadeFromADefinitionCannotAddStates) {
  MessageHub hub;
  Chart shape = MakeChart(Counter(), Counter());
  Statechart chart(shape.definition, hub);
  EXPECT_THROW(chart.Add<BasicState>("More", chart.Root()), std::logic_error);
}

TEST(SharedDefinition, AnActivityByNameIsMadeForEachStatechart) {
  MessageHub hub;
  static auto runs = Counter();
  struct Registered : IActivity {
    int Execute() override {
      ++*runs;
      return 0;
    }
    std::string GetName() override { return "DefinitionTestActivity"; }
  };
  static const ActivityRegistrar<Registered> registrar("DefinitionTestActivity");
  auto definition = std::make_shared<Definition>("ByName");
  auto* start = definition->Add<StartState>("Start", definition->Root());
  auto* work = definition->Add<BasicState>("Work", definition->Root(),
                                           ActivityFactory::Instance().PartNamed("DefinitionTestActivity"));
  auto* none = definition->Add<BasicState>("None", definition->Root(),
                                           ActivityFactory::Instance().PartNamed("NoSuchDefinitionTestActivity"));
  definition->AddTransition(start, work);
  definition->AddTransition(work, none);
  definition->Complete();
  EXPECT_FALSE(definition->HasGivenParts());
  EXPECT_FALSE(none->HasActivity()) << "an unknown name gives no activity, as Create() gives none";
  Statechart one(definition, hub, InlineOptions());
  Statechart two(definition, hub, InlineOptions());
  one.RunUntilStable();
  two.RunUntilStable();
  EXPECT_EQ(runs->load(), 2);
  EXPECT_THAT(one.ActiveStates(), ElementsAre("ByName", "None"));
}

}  // namespace
}  // namespace kse_test
