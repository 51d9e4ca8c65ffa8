#include "kse/simulation/Simulator.h"

#include <exception>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <kse/robot/MonitorServer.h>

#include "kse/simulation/Script.h"
#include "kse/simulation/Simulation.h"

namespace kse::simulation {

namespace {

constexpr std::size_t kLongestLine = 64 * 1024;

void AppendStrings(std::string& out, const std::vector<std::string>& items) {
  out += '[';
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i != 0) out += ',';
    kse::robot::AppendJsonString(out, items[i]);
  }
  out += ']';
}

// ---------------------------------------------------------------------------------------------
// --check and --show: conformance cases
// ---------------------------------------------------------------------------------------------

// The actual trace of a case: each command with what it caused.
std::vector<ScriptCommand> Play(const Script& script, bool eager) {
  Simulation::Options options;
  options.eager = eager;
  Simulation simulation(script.model, options);
  for (const ScriptCommand& command : script.commands) {
    if (command.words[0] == "read" && command.words.size() >= 2) simulation.Subscribe(command.words[1]);
  }
  std::vector<ScriptCommand> actual;
  for (const ScriptCommand& command : script.commands) {
    ScriptCommand result = command;
    try {
      result.output = simulation.Execute(command);
    } catch (const ScriptError& e) {
      throw ScriptError(script.origin + ":" + std::to_string(command.line) + ": " + e.what());
    }
    actual.push_back(std::move(result));
  }
  return actual;
}

int CheckCases(const std::vector<std::filesystem::path>& files, bool eager, bool show) {
  int failed = 0;
  for (const auto& file : files) {
    try {
      const Script script = ReadScript(file);
      const std::string actual = Transcript(Play(script, eager));
      const std::string expected = Transcript(script.commands);
      if (show) {
        std::cout << "model " << script.model << "\n" << actual << "\n";
      } else if (expected == actual) {
        std::cout << "PASS " << file.filename().string() << "\n";
      } else {
        ++failed;
        std::cout << "FAIL " << file.string() << (eager ? " (eager)" : "") << "\n--- expected\n"
                  << expected << "--- actual\n" << actual;
      }
    } catch (const std::exception& e) {
      ++failed;
      std::cout << "FAIL " << file.string() << ": " << e.what() << "\n";
    }
  }
  if (!show) {
    std::cout << (files.size() - static_cast<std::size_t>(failed)) << " of " << files.size() << " cases pass"
              << (eager ? " (eager wake-ups)" : "") << "\n";
  }
  return failed == 0 ? 0 : 1;
}

// ---------------------------------------------------------------------------------------------
// --serve: a session on standard input and output
// ---------------------------------------------------------------------------------------------

std::string StateOf(const Simulation& simulation) {
  std::string out = ",\"active\":";
  AppendStrings(out, simulation.ActiveStates());
  const auto runs = simulation.RunningSince();
  std::vector<std::string> names;
  out += ",\"running\":";
  for (const auto& run : runs) names.push_back(run.first);
  AppendStrings(out, names);
  out += ",\"since\":[";
  for (std::size_t i = 0; i < runs.size(); ++i) out += (i ? "," : "") + std::to_string(runs[i].second.count());
  out += ']';
  out += ",\"time\":" + std::to_string(simulation.Elapsed().count());
  out += ",\"started\":";
  out += simulation.Started() ? "true" : "false";
  return out;
}

std::string Refusal(const Simulation& simulation, const std::string& command, const std::string& why) {
  std::string out = "{\"type\":\"result\",\"ok\":false,\"command\":";
  kse::robot::AppendJsonString(out, command);
  out += ",\"error\":";
  kse::robot::AppendJsonString(out, why);
  return out + StateOf(simulation) + "}";
}

// `breakpoints state:<label>... transition:<index>...`: the whole set, replacing the last one.
std::string SetBreakpoints(Simulation& simulation, const ScriptCommand& command) {
  std::set<std::string> states;
  std::set<long> transitions;
  for (std::size_t i = 1; i < command.words.size(); ++i) {
    const std::string& word = command.words[i];
    if (word.rfind("state:", 0) == 0 && word.size() > 6) {
      states.insert(word.substr(6));
    } else if (word.rfind("transition:", 0) == 0) {
      try {
        std::size_t used = 0;
        const long index = std::stol(word.substr(11), &used);
        if (used != word.size() - 11 || index < 0) throw std::invalid_argument(word);
        transitions.insert(index);
      } catch (const std::exception&) {
        return Refusal(simulation, command.text, "not a transition's index: '" + word + "'");
      }
    } else {
      return Refusal(simulation, command.text, "write: breakpoints [state:<label>]... [transition:<index>]...");
    }
  }
  simulation.SetBreakpoints(std::move(states), std::move(transitions));
  std::string out = "{\"type\":\"result\",\"ok\":true,\"command\":";
  kse::robot::AppendJsonString(out, command.text);
  return out + ",\"lines\":[],\"taken\":[]" + StateOf(simulation) + "}";
}

std::string Result(const Simulation& simulation, const std::vector<std::string>& lines) {
  std::string out = "{\"type\":\"result\",\"ok\":true,\"command\":";
  kse::robot::AppendJsonString(out, simulation.Executed());
  out += ",\"lines\":";
  AppendStrings(out, lines);
  out += ",\"taken\":[";
  bool first = true;
  for (const Taken& taken : simulation.LastTaken()) {
    if (!first) out += ',';
    first = false;
    out += "{\"tr\":" + std::to_string(taken.index) + ",\"from\":";
    kse::robot::AppendJsonString(out, taken.from);
    out += ",\"to\":";
    kse::robot::AppendJsonString(out, taken.to);
    out += '}';
  }
  out += ']';
  if (!simulation.StoppedAt().empty()) {
    out += ",\"stopped\":";
    kse::robot::AppendJsonString(out, simulation.StoppedAt());
  }
  return out + StateOf(simulation) + "}";
}

int Serve(const std::string& model, const std::vector<std::string>& activities) {
  std::unique_ptr<Simulation> simulation;
  try {
    simulation = std::make_unique<Simulation>(model);
  } catch (const std::exception& e) {
    std::string out = "{\"type\":\"error\",\"error\":";
    kse::robot::AppendJsonString(out, e.what());
    std::cout << out << "}" << std::endl;
    return 2;
  }
  std::string ready = "{\"type\":\"ready\",\"model\":";
  kse::robot::AppendJsonString(ready, model);
  ready += ",\"states\":";
  AppendStrings(ready, simulation->StateLabels());
  ready += ",\"transitions\":" + std::to_string(simulation->TransitionCount());
  ready += ",\"activities\":";
  AppendStrings(ready, activities);
  std::cout << ready << "}" << std::endl;

  for (std::string line; std::getline(std::cin, line);) {
    if (line.size() > kLongestLine) {
      std::cout << Refusal(*simulation, "", "a command longer than 64 KiB") << std::endl;
      continue;
    }
    const std::string text = Trim(line);
    if (text.empty() || text[0] == '#') continue;
    if (text == "quit") break;
    const ScriptCommand command = ParseCommand(text);
    if (command.words[0] == "breakpoints") {
      std::cout << SetBreakpoints(*simulation, command) << std::endl;
      continue;
    }
    try {
      const auto lines = simulation->Execute(command);
      std::cout << Result(*simulation, lines) << std::endl;
    } catch (const ScriptError& e) {
      std::cout << Refusal(*simulation, text, e.what()) << std::endl;
    } catch (const std::exception& e) {
      // the engine itself went wrong (an activity never started): the session cannot go on
      std::string out = "{\"type\":\"error\",\"error\":";
      kse::robot::AppendJsonString(out, e.what());
      std::cout << out << "}" << std::endl;
      return 1;
    }
  }
  return 0;
}

std::vector<std::string> SplitList(const std::string& list) {
  std::vector<std::string> names;
  std::istringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    if (!name.empty()) names.push_back(name);
  }
  return names;
}

}  // namespace

int RunSimulator(int argc, char** argv) {
  const std::string program = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "kse-simulator";
  const std::string usage = "usage: " + program +
                            " [--activities A,B,...] [--eager] (--check <case>... | --show <case>... | --serve <Model>)\n";
  bool eager = false;
  std::string mode;
  std::vector<std::string> activities;
  std::vector<std::string> rest;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--eager") {
      eager = true;
    } else if (arg == "--activities" && i + 1 < argc) {
      activities = SplitList(argv[++i]);
    } else if (arg == "--check" || arg == "--show" || arg == "--serve") {
      if (!mode.empty()) {
        std::cerr << usage;
        return 2;
      }
      mode = arg;
    } else if (arg == "-h" || arg == "--help") {
      std::cout << usage;
      return 0;
    } else if (!arg.empty() && arg[0] == '-') {
      std::cerr << program << ": unknown option '" << arg << "'\n" << usage;
      return 2;
    } else {
      rest.push_back(arg);
    }
  }
  // a case file named alone is checked, as the conformance driver always did
  if (mode.empty() && !rest.empty()) mode = "--check";
  if (mode.empty() || rest.empty() || (mode == "--serve" && rest.size() != 1)) {
    std::cerr << usage;
    return 2;
  }
  RegisterScriptedActivities(activities);
  if (mode == "--serve") return Serve(rest[0], activities);
  return CheckCases(std::vector<std::filesystem::path>(rest.begin(), rest.end()), eager, mode == "--show");
}

}  // namespace kse::simulation
