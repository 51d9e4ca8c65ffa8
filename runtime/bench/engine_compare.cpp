// The engine against a hand-written switch, Boost.Statechart and Qt SCXML, on the same two
// charts, in one binary (issue 17, item 4). Figures only: it never fails on a figure, only when
// an implementation does not do the work it is timed for.
//
// The charts (every implementation models the same states and takes the same transitions):
//
//   chain   START -> N0 -> N1 -> ... -> N7 -> N0: 8 BASIC states, a cycle of 8 transitions.
//           N0..N7 each run an activity when entered; N_i -> N_i+1 has a guard.
//
//   nested  START -> C0; three OR states C0, C1, C2, each START -> N0 -> N1 -> N2 -> END inside,
//           and C_i -> C_(i+1 mod 3) on the OR state itself: 19 states below the root (3 OR,
//           3 x 5 inside, the root's START) and 16 transitions, a cycle of 15 transitions. The
//           OR state's own transition is taken once its END is active (nothing inside can move),
//           so every step asks the OR state's child first: the hierarchy is walked on each
//           transition. BASIC states run an activity when entered; every transition but the
//           STARTs' has a guard.
//
// One transition is one Step() of the engine, one call of the switch's Step(), one
// process_event() of Boost.Statechart, one submitEvent() + event processing of Qt SCXML.
// Guards and activities are out-of-line no-op calls (Guard(), Activity()) for the engine, the
// switch and Boost, counted so that the check below sees the same work done; the Qt chart,
// loaded at run time with the null data model, has no guards or activities (they would only
// make it slower).
//
// Timing: rounds interleave the implementations (chain and nested alternately, every
// implementation once a round), each timed by the thread's CPU clock
// (CLOCK_THREAD_CPUTIME_ID); printed are the median round and the median of the rounds'
// ratios.
//
// Memory: bytes per chart instance, the object itself plus what it holds on the heap once it
// is ready to step (activated, in its first state), as malloc counts it (mallinfo2, chunk
// overhead included) over 100 instances; the number of operator new blocks beside it. The
// engine's MessageHub is shared by every chart of a process (one per robot) and not counted;
// nor is a chart's Definition, built once and shared by its instances as Boost's and Qt's
// compiled charts share their code and tables (printed on a line of its own).
//
//   kse_engine_compare [--rounds N] [--round-ms M] [--only NAME]
// --only times one implementation (e.g. `--only engine`, for a profiler) and skips the memory.

#include <malloc.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/mpl/list.hpp>
#include <boost/statechart/custom_reaction.hpp>
#include <boost/statechart/event.hpp>
#include <boost/statechart/simple_state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <boost/statechart/transition.hpp>

#include <QBuffer>
#include <QByteArray>
#include <QCoreApplication>
#include <QScxmlStateMachine>

#include "statechart_engine/statechart_engine.h"

// ---- counting allocator ---------------------------------------------------------------------
// Live operator new blocks, so that a chart's allocations can be counted around its
// construction (the bytes come from malloc's own count, see HeapInUse()).

namespace {
std::atomic<std::int64_t> g_allocations{0};

void* CountedAlloc(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return p;
}

void CountedFree(void* p) noexcept {
  if (p == nullptr) return;
  g_allocations.fetch_sub(1, std::memory_order_relaxed);
  std::free(p);
}
}  // namespace

void* operator new(std::size_t size) { return CountedAlloc(size); }
void* operator new[](std::size_t size) { return CountedAlloc(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return CountedAlloc(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return CountedAlloc(size);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept { CountedFree(p); }
void operator delete[](void* p) noexcept { CountedFree(p); }
void operator delete(void* p, std::size_t) noexcept { CountedFree(p); }
void operator delete[](void* p, std::size_t) noexcept { CountedFree(p); }

namespace {

// ---- the work every implementation does ------------------------------------------------------

std::uint64_t g_guards = 0;
std::uint64_t g_activities = 0;

// Out of line, as a generated guard or activity is (the engine calls them through a vtable);
// noipa: the compiler must not learn that a guard always holds.
__attribute__((noinline, noipa)) bool Guard(int transition) {
  ++g_guards;
  asm volatile("" : : "r"(transition) : "memory");
  return true;
}

__attribute__((noinline, noipa)) void Activity(int state) {
  ++g_activities;
  asm volatile("" : : "r"(state) : "memory");
}

double ThreadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

constexpr int kChainStates = 8;
constexpr int kComposites = 3;
constexpr int kLeaves = 3;                           // N0..N2 in each OR state
constexpr int kNestedCycle = kComposites * (kLeaves + 2);  // START->N0, N0->N1, N1->N2, N2->END, C->C'

// ---- (a) the engine ------------------------------------------------------------------------

namespace se = statechart_engine;

class EngineGuard : public se::ICondition {
 public:
  explicit EngineGuard(int id) : id_(id) {}
  bool Eval() override { return Guard(id_); }

 private:
  int id_;
};

class EngineActivity : public se::IActivity {
 public:
  explicit EngineActivity(int id) : id_(id) {}
  int Execute() override {
    Activity(id_);
    return 0;
  }
  std::string GetName() override { return "Activity"; }

 private:
  int id_;
};

se::Options InlineOptions() {
  se::Options options;
  options.inline_activities = true;
  return options;
}

// Each chart's structure is one Definition shared by all its instances, as generated code
// builds it; an instance holds its configuration and makes its guards and activities.
std::shared_ptr<const se::Definition> MakeChainDefinition() {
  {
    auto definition = std::make_shared<se::Definition>("Chain");
    se::OrState* root = definition->Root();
    auto* start = definition->Add<se::StartState>("Chain_START", root);
    std::vector<se::BasicState*> nodes;
    for (int i = 0; i < kChainStates; ++i) {
      nodes.push_back(definition->Add<se::BasicState>("N" + std::to_string(i), root,
                                                      se::Make<EngineActivity>(i)));
    }
    definition->AddTransition(start, nodes[0]);
    for (int i = 0; i < kChainStates; ++i) {
      definition->AddTransition(nodes[static_cast<std::size_t>(i)],
                                nodes[static_cast<std::size_t>((i + 1) % kChainStates)],
                                se::Make<EngineGuard>(i));
    }
    definition->Complete();
    return definition;
  }
}

std::shared_ptr<const se::Definition> MakeNestedDefinition() {
  {
    auto definition = std::make_shared<se::Definition>("Nested");
    se::OrState* root = definition->Root();
    auto* start = definition->Add<se::StartState>("Nested_START", root);
    std::vector<se::OrState*> composites;
    for (int c = 0; c < kComposites; ++c) {
      const std::string name = "C" + std::to_string(c);
      auto* composite = definition->Add<se::OrState>(name, root);
      composites.push_back(composite);
      auto* inner_start = definition->Add<se::StartState>(name + "_START", composite);
      std::vector<se::State*> path{inner_start};
      for (int k = 0; k < kLeaves; ++k) {
        path.push_back(definition->Add<se::BasicState>(name + "_N" + std::to_string(k), composite,
                                                       se::Make<EngineActivity>(c * 10 + k)));
      }
      path.push_back(definition->Add<se::EndState>(name + "_END", composite));
      definition->AddTransition(path[0], path[1]);
      for (std::size_t k = 1; k + 1 < path.size(); ++k) {
        definition->AddTransition(path[k], path[k + 1],
                                  se::Make<EngineGuard>(c * 10 + static_cast<int>(k)));
      }
    }
    definition->AddTransition(start, composites[0]);
    for (int c = 0; c < kComposites; ++c) {
      definition->AddTransition(composites[static_cast<std::size_t>(c)],
                                composites[static_cast<std::size_t>((c + 1) % kComposites)],
                                se::Make<EngineGuard>(100 + c));
    }
    definition->Complete();
    return definition;
  }
}

const std::shared_ptr<const se::Definition>& ChainDefinition() {
  static const std::shared_ptr<const se::Definition> shared = MakeChainDefinition();
  return shared;
}

const std::shared_ptr<const se::Definition>& NestedDefinition() {
  static const std::shared_ptr<const se::Definition> shared = MakeNestedDefinition();
  return shared;
}

std::unique_ptr<se::Statechart> EngineChain(kse::messaging::MessageHub& hub) {
  auto chart = std::make_unique<se::Statechart>(ChainDefinition(), hub, InlineOptions());
  chart->Activate();
  return chart;
}

std::unique_ptr<se::Statechart> EngineNested(kse::messaging::MessageHub& hub) {
  auto chart = std::make_unique<se::Statechart>(NestedDefinition(), hub, InlineOptions());
  chart->Activate();
  return chart;
}

// ---- (b) the hand-written switch -----------------------------------------------------------

// Step() is a call, as the others' are (inlined, the loop around it could be merged with it).
#define KSE_SWITCH_STEP __attribute__((noinline))

class SwitchChain {
 public:
  KSE_SWITCH_STEP bool Step() {
    switch (state_) {
      case -1:
        return Enter(0);
      case 0: return Go(0, 1);
      case 1: return Go(1, 2);
      case 2: return Go(2, 3);
      case 3: return Go(3, 4);
      case 4: return Go(4, 5);
      case 5: return Go(5, 6);
      case 6: return Go(6, 7);
      case 7: return Go(7, 0);
      default: return false;
    }
  }

 private:
  bool Go(int from, int to) { return Guard(from) && Enter(to); }
  bool Enter(int to) {
    state_ = to;
    Activity(to);
    return true;
  }
  int state_ = -1;  // START
};

// The OR states as a switch on the composite and, inside, on its child; the inside first, then
// the OR state's own transition.
class SwitchNested {
 public:
  KSE_SWITCH_STEP bool Step() {
    if (composite_ < 0) {
      composite_ = 0;
      inner_ = kStart;
      return true;
    }
    switch (composite_) {
      case 0: return StepIn<0>();
      case 1: return StepIn<1>();
      case 2: return StepIn<2>();
      default: return false;
    }
  }

 private:
  enum Inner { kStart = -1, kN0 = 0, kN1 = 1, kN2 = 2, kEnd = 3 };

  template <int C>
  bool StepIn() {
    switch (inner_) {
      case kStart:
        return Enter(C, kN0);
      case kN0:
        if (Guard(C * 10 + 1)) return Enter(C, kN1);
        break;
      case kN1:
        if (Guard(C * 10 + 2)) return Enter(C, kN2);
        break;
      case kN2:
        if (Guard(C * 10 + 3)) {
          inner_ = kEnd;
          return true;
        }
        break;
      default:
        break;
    }
    if (Guard(100 + C)) {
      composite_ = (C + 1) % kComposites;
      inner_ = kStart;
      return true;
    }
    return false;
  }
  bool Enter(int c, int leaf) {
    inner_ = leaf;
    Activity(c * 10 + leaf);
    return true;
  }
  int composite_ = -1;  // the root's START
  int inner_ = kStart;
};

// ---- (c) Boost.Statechart ------------------------------------------------------------------

namespace sc = boost::statechart;

struct EvStep : sc::event<EvStep> {};

struct BoostChainStart;
struct BoostChain : sc::state_machine<BoostChain, BoostChainStart> {};

template <int I>
struct BoostNode : sc::simple_state<BoostNode<I>, BoostChain> {
  using reactions = sc::custom_reaction<EvStep>;
  BoostNode() { Activity(I); }
  sc::result react(const EvStep&) {
    if (Guard(I)) return this->template transit<BoostNode<(I + 1) % kChainStates>>();
    return this->forward_event();
  }
};

struct BoostChainStart : sc::simple_state<BoostChainStart, BoostChain> {
  using reactions = sc::transition<EvStep, BoostNode<0>>;
};

struct BoostNestedStart;
struct BoostNested : sc::state_machine<BoostNested, BoostNestedStart> {};

template <int C>
struct BoostInnerStart;
// The inner initial state as a one-element list: named bare, the template would be instantiated
// (to ask whether it is a list) before the OR state it lives in is complete.
template <int C>
struct BoostComposite
    : sc::simple_state<BoostComposite<C>, BoostNested, boost::mpl::list<BoostInnerStart<C>>> {
  using reactions = sc::custom_reaction<EvStep>;
  sc::result react(const EvStep&) {
    if (Guard(100 + C)) return this->template transit<BoostComposite<(C + 1) % kComposites>>();
    return this->forward_event();
  }
};

template <int C>
struct BoostInnerEnd : sc::simple_state<BoostInnerEnd<C>, BoostComposite<C>> {};

template <int C, int K>
struct BoostLeaf : sc::simple_state<BoostLeaf<C, K>, BoostComposite<C>> {
  using reactions = sc::custom_reaction<EvStep>;
  using Next = std::conditional_t<(K + 1 < kLeaves), BoostLeaf<C, K + 1>, BoostInnerEnd<C>>;
  BoostLeaf() { Activity(C * 10 + K); }
  sc::result react(const EvStep&) {
    if (Guard(C * 10 + K + 1)) return this->template transit<Next>();
    return this->forward_event();
  }
};

template <int C>
struct BoostInnerStart : sc::simple_state<BoostInnerStart<C>, BoostComposite<C>> {
  using reactions = sc::transition<EvStep, BoostLeaf<C, 0>>;
};

struct BoostNestedStart : sc::simple_state<BoostNestedStart, BoostNested> {
  using reactions = sc::transition<EvStep, BoostComposite<0>>;
};

// ---- (d) Qt SCXML --------------------------------------------------------------------------

QByteArray ScxmlChain() {
  QByteArray xml =
      "<scxml xmlns=\"http://www.w3.org/2005/07/scxml\" version=\"1.0\" datamodel=\"null\""
      " initial=\"start\">\n<state id=\"start\"><transition event=\"step\" target=\"n0\"/></state>\n";
  for (int i = 0; i < kChainStates; ++i) {
    xml += "<state id=\"n" + QByteArray::number(i) + "\"><transition event=\"step\" target=\"n" +
           QByteArray::number((i + 1) % kChainStates) + "\"/></state>\n";
  }
  return xml + "</scxml>\n";
}

QByteArray ScxmlNested() {
  QByteArray xml =
      "<scxml xmlns=\"http://www.w3.org/2005/07/scxml\" version=\"1.0\" datamodel=\"null\""
      " initial=\"start\">\n<state id=\"start\"><transition event=\"step\" target=\"c0\"/></state>\n";
  for (int c = 0; c < kComposites; ++c) {
    const QByteArray id = "c" + QByteArray::number(c);
    xml += "<state id=\"" + id + "\" initial=\"" + id + "_start\">\n";
    xml += "  <transition event=\"step\" target=\"c" + QByteArray::number((c + 1) % kComposites) +
           "\"/>\n";
    xml += "  <state id=\"" + id + "_start\"><transition event=\"step\" target=\"" + id +
           "_n0\"/></state>\n";
    for (int k = 0; k < kLeaves; ++k) {
      const QByteArray next = k + 1 < kLeaves ? id + "_n" + QByteArray::number(k + 1) : id + "_end";
      xml += "  <state id=\"" + id + "_n" + QByteArray::number(k) +
             "\"><transition event=\"step\" target=\"" + next + "\"/></state>\n";
    }
    xml += "  <state id=\"" + id + "_end\"/>\n</state>\n";
  }
  return xml + "</scxml>\n";
}

// Qt SCXML processes submitted events from its event loop hook: a posted call, delivered here
// without running an event loop.
void QtProcess() { QCoreApplication::sendPostedEvents(nullptr, 0); }

std::unique_ptr<QScxmlStateMachine> QtMachine(const QByteArray& xml) {
  QBuffer buffer;
  buffer.setData(xml);
  buffer.open(QIODevice::ReadOnly);
  std::unique_ptr<QScxmlStateMachine> machine(QScxmlStateMachine::fromData(&buffer));
  if (!machine || !machine->parseErrors().isEmpty()) {
    std::fprintf(stderr, "kse_engine_compare: Qt SCXML did not load the chart: %s\n",
                 machine ? machine->parseErrors().first().toString().toLocal8Bit().constData() : "");
    std::exit(1);
  }
  machine->start();
  QtProcess();
  if (!machine->isRunning()) {
    std::fprintf(stderr, "kse_engine_compare: the Qt SCXML machine did not start\n");
    std::exit(1);
  }
  return machine;
}

// ---- the runs ------------------------------------------------------------------------------

/// One implementation on one chart: steps it n times, false when a step did nothing.
struct Contender {
  Contender(const char* n, std::function<bool(std::uint64_t)> r) : name(n), run(std::move(r)) {}
  const char* name;
  std::function<bool(std::uint64_t n)> run;
  std::uint64_t per_round = 1;  // calibrated
  std::vector<double> rates;    // transitions per CPU second, one per round
};

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// malloc's own count: Qt allocates much of its data with malloc, not operator new. Chunk
// headers and rounding are included, as they are memory a chart takes.
std::int64_t HeapInUse() {
  const struct mallinfo2 info = mallinfo2();
  return static_cast<std::int64_t>(info.uordblks + info.hblkhd);
}

struct Memory {
  double bytes = 0;
  double allocations = 0;
};

/// Bytes per instance: `keep` constructs one ready-to-step instance and keeps it.
template <class Make>
Memory Measure(std::size_t object_size, Make make) {
  constexpr int kInstances = 100;
  make();  // process-wide first-use costs (singletons, registries) are not a chart's
  const std::int64_t bytes = HeapInUse();
  const std::int64_t allocations = g_allocations.load();
  for (int i = 0; i < kInstances; ++i) make();
  Memory memory;
  memory.bytes = static_cast<double>(HeapInUse() - bytes) / kInstances +
                 static_cast<double>(object_size);
  memory.allocations = static_cast<double>(g_allocations.load() - allocations) / kInstances;
  return memory;
}

struct Work {
  std::uint64_t guards;
  std::uint64_t activities;
};

/// Guards and activities called for one run of n transitions.
Work WorkOf(Contender& contender, std::uint64_t n) {
  const std::uint64_t guards = g_guards;
  const std::uint64_t activities = g_activities;
  if (!contender.run(n)) return {~0ULL, ~0ULL};
  return {g_guards - guards, g_activities - activities};
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 15;
  double round_ms = 40;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc) {
      rounds = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--round-ms") == 0 && i + 1 < argc) {
      round_ms = std::max(1.0, std::atof(argv[++i]));
    } else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
      only = argv[++i];
    } else {
      std::fprintf(stderr, "usage: kse_engine_compare [--rounds N] [--round-ms M] [--only NAME]\n");
      return 2;
    }
  }
  int qt_argc = 1;
  char qt_name[] = "kse_engine_compare";
  char* qt_argv[] = {qt_name, nullptr};
  QCoreApplication app(qt_argc, qt_argv);

  kse::messaging::ManualClock clock;
  kse::messaging::MessageHub hub(clock);

  // Instances that are timed; each starts in its chart's START and is stepped in whole cycles
  // during calibration, so every implementation is at the same place when rounds begin.
  auto engine_chain = EngineChain(hub);
  auto engine_nested = EngineNested(hub);
  SwitchChain switch_chain;
  SwitchNested switch_nested;
  BoostChain boost_chain;
  boost_chain.initiate();
  BoostNested boost_nested;
  boost_nested.initiate();
  auto qt_chain = QtMachine(ScxmlChain());
  auto qt_nested = QtMachine(ScxmlNested());
  const QString step = QStringLiteral("step");

  auto engine = [](se::Statechart& chart) {
    return [&chart](std::uint64_t n) {
      for (std::uint64_t i = 0; i < n; ++i) {
        if (!chart.Step()) return false;
      }
      return true;
    };
  };
  auto hand = [](auto& machine) {
    return [&machine](std::uint64_t n) {
      for (std::uint64_t i = 0; i < n; ++i) {
        if (!machine.Step()) return false;
      }
      return true;
    };
  };
  auto boost = [](auto& machine) {
    return [&machine](std::uint64_t n) {
      for (std::uint64_t i = 0; i < n; ++i) machine.process_event(EvStep());
      return true;
    };
  };
  auto qt = [&step](QScxmlStateMachine& machine) {
    return [&machine, &step](std::uint64_t n) {
      for (std::uint64_t i = 0; i < n; ++i) {
        machine.submitEvent(step);
        QtProcess();
      }
      return machine.isRunning();
    };
  };

  struct Chart {
    const char* name;
    std::uint64_t cycle;  // transitions that come back to where the chart was
    std::vector<Contender> contenders;  // [0] the switch, [2] Boost
  };
  std::vector<Chart> charts;
  charts.push_back({"chain (8 states)", kChainStates,
                    {{"switch", hand(switch_chain)},
                     {"engine", engine(*engine_chain)},
                     {"Boost.Statechart", boost(boost_chain)},
                     {"Qt SCXML", qt(*qt_chain)}}});
  charts.push_back({"nested (3 OR x 5, 19 states)", kNestedCycle,
                    {{"switch", hand(switch_nested)},
                     {"engine", engine(*engine_nested)},
                     {"Boost.Statechart", boost(boost_nested)},
                     {"Qt SCXML", qt(*qt_nested)}}});

  // Same work: from START, the step out of it and one cycle must call as many guards and
  // activities in the engine and in Boost as in the switch (and leave each at the cycle's start).
  bool same = true;
  for (Chart& chart : charts) {
    const Work reference = WorkOf(chart.contenders[0], chart.cycle + 1);
    for (std::size_t i = 1; i < 3; ++i) {
      const Work work = WorkOf(chart.contenders[i], chart.cycle + 1);
      if (work.guards != reference.guards || work.activities != reference.activities) {
        std::fprintf(stderr,
                     "kse_engine_compare: %s on the %s chart called %llu guards and %llu activities "
                     "in one cycle, the switch %llu and %llu\n",
                     chart.contenders[i].name, chart.name,
                     static_cast<unsigned long long>(work.guards),
                     static_cast<unsigned long long>(work.activities),
                     static_cast<unsigned long long>(reference.guards),
                     static_cast<unsigned long long>(reference.activities));
        same = false;
      }
    }
    if (!chart.contenders[3].run(chart.cycle + 1)) same = false;
  }
  if (!same) return 1;

  // Calibration: whole cycles per round, about round_ms of CPU each.
  for (Chart& chart : charts) {
    for (Contender& contender : chart.contenders) {
      std::uint64_t n = chart.cycle * 16;
      for (;;) {
        const double begin = ThreadSeconds();
        contender.run(n);
        const double seconds = ThreadSeconds() - begin;
        if (seconds > round_ms / 4000) {
          const double per_round = static_cast<double>(n) * (round_ms / 1000) / seconds;
          contender.per_round =
              std::max<std::uint64_t>(1, static_cast<std::uint64_t>(per_round) / chart.cycle) *
              chart.cycle;
          break;
        }
        n *= 4;
      }
    }
  }

  for (int round = 0; round < rounds; ++round) {
    for (Chart& chart : charts) {
      for (Contender& contender : chart.contenders) {
        if (!only.empty() && only != contender.name) continue;
        const double begin = ThreadSeconds();
        const bool ok = contender.run(contender.per_round);
        const double seconds = ThreadSeconds() - begin;
        if (!ok) {
          std::fprintf(stderr, "kse_engine_compare: %s on the %s chart stopped stepping\n",
                       contender.name, chart.name);
          return 1;
        }
        contender.rates.push_back(static_cast<double>(contender.per_round) / seconds);
      }
    }
  }

  std::printf("Transitions per second of thread CPU time, median of %d interleaved rounds of ~%.0f ms\n",
              rounds, round_ms);
  for (Chart& chart : charts) {
    // A ratio is the median of the rounds' ratios: the machine's speed drifts (other work, the
    // other hardware thread of the core) more between rounds than within one.
    auto ratio = [](const Contender& contender, const Contender& base) {
      if (contender.rates.empty() || base.rates.empty()) return 0.0;
      std::vector<double> ratios;
      for (std::size_t i = 0; i < contender.rates.size(); ++i) {
        ratios.push_back(contender.rates[i] / base.rates[i]);
      }
      return Median(ratios);
    };
    std::printf("\n%s\n  %-18s %12s %10s %10s\n", chart.name, "", "M trans/s", "x switch", "x Boost");
    for (Contender& contender : chart.contenders) {
      if (contender.rates.empty()) continue;
      std::printf("  %-18s %12.2f %10.3f %10.2f\n", contender.name, Median(contender.rates) / 1e6,
                  ratio(contender, chart.contenders[0]), ratio(contender, chart.contenders[2]));
    }
  }

  if (!only.empty()) return 0;

  // Memory per instance, ready to step.
  std::vector<std::unique_ptr<se::Statechart>> engines;
  std::vector<std::unique_ptr<BoostChain>> boost_chains;
  std::vector<std::unique_ptr<BoostNested>> boost_nesteds;
  std::vector<std::unique_ptr<QScxmlStateMachine>> qts;
  const Memory engine_chain_memory = Measure(0, [&] { engines.push_back(EngineChain(hub)); });
  const Memory engine_nested_memory = Measure(0, [&] { engines.push_back(EngineNested(hub)); });
  const Memory boost_chain_memory = Measure(0, [&] {
    boost_chains.push_back(std::make_unique<BoostChain>());
    boost_chains.back()->initiate();
  });
  const Memory boost_nested_memory = Measure(0, [&] {
    boost_nesteds.push_back(std::make_unique<BoostNested>());
    boost_nesteds.back()->initiate();
  });
  const Memory qt_chain_memory = Measure(0, [&] { qts.push_back(QtMachine(ScxmlChain())); });
  const Memory qt_nested_memory = Measure(0, [&] { qts.push_back(QtMachine(ScxmlNested())); });
  const Memory switch_memory{static_cast<double>(sizeof(SwitchChain)), 0};
  const Memory switch_nested_memory{static_cast<double>(sizeof(SwitchNested)), 0};

  std::printf("\nBytes per chart instance, ready to step (heap + object; allocations)\n");
  std::printf("  %-18s %16s %22s\n", "", "chain", "nested");
  auto line = [&](const char* name, const Memory& chain, const Memory& nested) {
    std::printf("  %-18s %9.0f B (%4.0f) %15.0f B (%4.0f)   x Boost %.1f / %.1f\n", name, chain.bytes,
                chain.allocations, nested.bytes, nested.allocations,
                chain.bytes / boost_chain_memory.bytes, nested.bytes / boost_nested_memory.bytes);
  };
  line("switch", switch_memory, switch_nested_memory);
  line("engine", engine_chain_memory, engine_nested_memory);
  line("Boost.Statechart", boost_chain_memory, boost_nested_memory);
  line("Qt SCXML", qt_chain_memory, qt_nested_memory);

  // Once per chart, not per instance: what every engine instance above shares.
  std::vector<std::shared_ptr<const se::Definition>> definitions;
  const Memory chain_definition = Measure(0, [&] { definitions.push_back(MakeChainDefinition()); });
  const Memory nested_definition = Measure(0, [&] { definitions.push_back(MakeNestedDefinition()); });
  std::printf("  %-18s %9.0f B (%4.0f) %15.0f B (%4.0f)   once per chart, shared by its instances\n",
              "engine definition", chain_definition.bytes, chain_definition.allocations,
              nested_definition.bytes, nested_definition.allocations);
  return 0;
}
