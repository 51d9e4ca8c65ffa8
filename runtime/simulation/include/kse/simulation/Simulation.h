#pragma once
// One statechart run without a robot: the engine as kse-match runs it, but its clock, its
// messages and its activities are the script's. Activities are stand-ins that run until the
// script finishes (or fails) them; time moves only by `advance`, waking the engine at each
// wake-up time on the way, as Monas' timeout workers did. The conformance suite and the
// simulation in the tool both run through this class (docs/simulation.md).

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "kse/simulation/Script.h"

namespace kse::simulation {

/** Registers a scripted stand-in under each activity name (the model's activities). */
void RegisterScriptedActivities(const std::vector<std::string>& names);

/** A transition segment the engine took. */
struct Taken {
  std::size_t step = 0;   // the engine's step number: segments of one step are one trace line
  long index = -1;        // the model's //@transitions.index (the diagram's edge)
  std::string from;       // labels
  std::string to;
  bool into_connector = false;
};

class Simulation {
 public:
  struct Options {
    /** Wake the engine after every command three times more and at every millisecond of
        `advance`: traces must not change (the engine looks only when something is due). */
    bool eager = false;
    /** The longest `advance` accepted, so that a typo cannot keep a session busy for hours. */
    std::chrono::milliseconds longest_advance = std::chrono::hours(1);
  };

  /** Throws ScriptError when no statechart of that name is linked into the program. */
  Simulation(const std::string& model, Options options);
  explicit Simulation(const std::string& model) : Simulation(model, Options{}) {}
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /** `read` shows what a blackboard subscribed from the start sees; a script names its topics first. */
  void Subscribe(const std::string& topic);

  /**
   * Runs one command and returns the lines it caused (transitions, or what `active`, `running`
   * and `read` print). A command that cannot run (unknown, wrong arguments, finishing an
   * activity that is not running) throws ScriptError and changes nothing. `advance` stops early
   * at a breakpoint: then the command's text becomes the time it did advance (see Executed()).
   */
  std::vector<std::string> Execute(const ScriptCommand& command);

  /** The last command as it ran (an `advance` cut short by a breakpoint says how far it went). */
  const std::string& Executed() const noexcept { return executed_; }
  /** The segments the last command took, in order. */
  const std::vector<Taken>& LastTaken() const noexcept { return last_taken_; }
  /** What stopped the last `advance`: "state <label>" or "transition <index>", else empty. */
  const std::string& StoppedAt() const noexcept { return stopped_at_; }

  /** Breakpoints: a state (its label) that becomes active, a transition (model index) taken. */
  void SetBreakpoints(std::set<std::string> states, std::set<long> transitions);

  bool Started() const noexcept { return started_; }
  /** Time since the simulation began. */
  std::chrono::milliseconds Elapsed() const;
  /** Labels of every active state, root first, in the model's order. */
  std::vector<std::string> ActiveStates() const;
  /** Labels of the active states that have no active child, joined by ", " (`active`). */
  std::string ActiveLeaves() const;
  /** Names of the activities running now, sorted (one per run). */
  std::vector<std::string> Running() const;
  /** The same runs with the simulated time each began at (the wake-up that launched it). */
  std::vector<std::pair<std::string, std::chrono::milliseconds>> RunningSince() const;
  /** Labels of the statechart's states, in the model's order. */
  std::vector<std::string> StateLabels() const;
  std::size_t TransitionCount() const;

 private:
  struct Engine;
  void Run(const ScriptCommand& command, std::vector<std::string>& out);
  void Settle(std::vector<std::string>& out);
  bool SettleWatched(std::vector<std::string>& out);
  void Advance(const ScriptCommand& command, std::chrono::milliseconds by, std::vector<std::string>& out);
  void End(const ScriptCommand& command, const std::string& name, bool fail);
  void Publish(const ScriptCommand& command);
  std::string Read(const ScriptCommand& command);
  void Flush(std::vector<std::string>& out);
  bool HitBreakpoint(const std::set<std::string>& active_before, std::size_t first);

  Options options_;
  std::unique_ptr<Engine> engine_;
  bool started_ = false;
  std::string executed_;
  std::vector<Taken> last_taken_;
  std::vector<Taken> pending_;  // taken, not yet in a trace line
  std::string stopped_at_;
  std::set<std::string> break_states_;
  std::set<long> break_transitions_;
  std::map<std::uint64_t, std::chrono::milliseconds> run_started_;  // by the Director's run id
};

}  // namespace kse::simulation
