#include <cstdio>

#include "statechart_engine/statechart_engine.h"

int main() {
  kse::messaging::MessageHub hub;
  statechart_engine::Options options;
  options.inline_activities = true;
  auto chart = statechart_engine::StatechartFactory::Instance().Create("Consumer", hub, options);
  if (!chart) return 1;
  chart->Chart().RunUntilStable();
  const auto active = chart->Chart().ActiveStates();
  const bool ok = active.size() == 2 && active[1] == "Node_0_3" && PLAYER_PLAYING == 3 &&
                  !ballAway(WorldInfo());
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", active.back().c_str());
  return ok ? 0 : 1;
}
