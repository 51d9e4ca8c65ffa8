#include "kse/simulation/Script.h"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace kse::simulation {

namespace {

std::vector<std::string> Words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

[[noreturn]] void Fail(const std::string& origin, int line, const std::string& why) {
  throw ScriptError(origin + ":" + std::to_string(line) + ": " + why);
}

}  // namespace

std::string Trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

ScriptCommand ParseCommand(const std::string& text, int line) {
  ScriptCommand command;
  command.line = line;
  command.text = Trim(text);
  command.words = Words(command.text);
  if (command.words.empty()) throw ScriptError("an empty command");
  return command;
}

Script ParseScript(std::istream& in, const std::string& origin) {
  Script script;
  script.origin = origin;
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    const std::string line = Trim(raw);
    if (line.empty() || line[0] == '#') continue;
    if (raw[0] == ' ' || raw[0] == '\t') {
      if (script.commands.empty()) Fail(origin, number, "an expected line before any command");
      script.commands.back().output.push_back(line);
      continue;
    }
    ScriptCommand command = ParseCommand(line, number);
    if (command.words[0] == "model") {
      if (command.words.size() != 2) Fail(origin, number, "write: model <statechart name>");
      script.model = command.words[1];
      continue;
    }
    script.commands.push_back(std::move(command));
  }
  if (script.model.empty()) Fail(origin, 1, "no 'model' line");
  if (std::none_of(script.commands.begin(), script.commands.end(),
                   [](const ScriptCommand& command) { return command.words[0] == "start"; })) {
    Fail(origin, 1, "no 'start' command");
  }
  return script;
}

Script ReadScript(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw ScriptError(file.string() + ": cannot read");
  return ParseScript(in, file.string());
}

std::string Transcript(const std::vector<ScriptCommand>& commands) {
  std::string text;
  for (const ScriptCommand& command : commands) {
    text += command.text + "\n";
    for (const std::string& line : command.output) text += "  " + line + "\n";
  }
  return text;
}

}  // namespace kse::simulation
