// Transitions per second of the statechart engine against a hand-written switch machine.
//
// The chart: START -> N0 -> N1 -> ... -> N(n-1) -> N0, every Ni a BASIC state with a no-op
// activity run inline, every transition guarded by an always-true condition. One Step() fires
// exactly one transition (exit, enter, activity). The switch machine does the same work for
// n = 8: an out-of-line guard call, a state change and an out-of-line activity call.
//
// After the runs the program prints the engine/switch figures and their ratio.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "statechart_engine/statechart_engine.h"

namespace {

using namespace statechart_engine;

class AlwaysTrue : public ICondition {
 public:
  bool Eval() override { return true; }
};

class NoOp : public IActivity {
 public:
  int Execute() override { return 0; }
  std::string GetName() override { return "NoOp"; }
};

void EngineChain(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  kse::messaging::ManualClock clock;
  kse::messaging::MessageHub hub(clock);
  Options options;
  options.inline_activities = true;
  Statechart chart("Chain", hub, options);
  auto* start = chart.Add<StartState>("Chain_1", &chart);
  std::vector<BasicState*> nodes;
  nodes.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    nodes.push_back(chart.Add<BasicState>("N" + std::to_string(i), &chart, std::make_unique<NoOp>()));
  }
  chart.AddTransition(start, nodes[0]);
  for (std::size_t i = 0; i < n; ++i) {
    chart.AddTransition(nodes[i], nodes[(i + 1) % n], std::make_unique<AlwaysTrue>());
  }
  chart.Activate();
  chart.Step();
  for (auto _ : state) {
    if (!chart.Step()) {
      state.SkipWithError("no transition fired");
      break;
    }
  }
  state.counters["transitions_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// ---- the hand-written machine ---------------------------------------------------------------

__attribute__((noinline)) bool Guard(int from) {
  benchmark::DoNotOptimize(from);
  return true;
}

__attribute__((noinline)) void Activity(int state) { benchmark::DoNotOptimize(state); }

class SwitchChain8 {
 public:
  bool Step() {
    switch (state_) {
      case 0:
        return Go(0, 1);
      case 1:
        return Go(1, 2);
      case 2:
        return Go(2, 3);
      case 3:
        return Go(3, 4);
      case 4:
        return Go(4, 5);
      case 5:
        return Go(5, 6);
      case 6:
        return Go(6, 7);
      case 7:
        return Go(7, 0);
      default:
        return false;
    }
  }

 private:
  bool Go(int from, int to) {
    if (!Guard(from)) return false;
    state_ = to;
    Activity(to);
    return true;
  }
  int state_ = 0;
};

void SwitchChain(benchmark::State& state) {
  SwitchChain8 machine;
  for (auto _ : state) {
    if (!machine.Step()) {
      state.SkipWithError("no transition fired");
      break;
    }
  }
  state.counters["transitions_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(EngineChain)->Name("EngineChain")->Arg(8)->Arg(64)->Arg(512);
BENCHMARK(SwitchChain)->Name("SwitchChain")->Arg(8);

/// The console output plus a record of each run's transitions per second.
class RecordingReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Iteration) continue;
      auto it = run.counters.find("transitions_per_second");
      if (it != run.counters.end()) {
        rates[run.benchmark_name()] = it->second.value;
      }
    }
  }
  std::map<std::string, double> rates;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RecordingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();

  std::printf("\ntransitions per second (millions):\n");
  for (const auto& entry : reporter.rates) {
    std::printf("  %-20s %10.2f\n", entry.first.c_str(), entry.second / 1e6);
  }
  auto engine = reporter.rates.find("EngineChain/8");
  auto handWritten = reporter.rates.find("SwitchChain/8");
  if (engine != reporter.rates.end() && handWritten != reporter.rates.end() && engine->second > 0) {
    std::printf("switch / engine for n = 8: %.1fx (the engine reaches %.1f%% of the switch)\n",
                handWritten->second / engine->second, 100.0 * engine->second / handWritten->second);
  }
  return 0;
}
