#pragma once
// A simulation script: the commands given to a statechart (start, publish, finish, advance, ...),
// each with the lines it caused. A conformance case is a script with the lines it must cause; a
// simulation in the tool writes the same format, so a run a user made is a case as it stands.
// The format: tests/conformance/README.md, "The script".

#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace kse::simulation {

struct ScriptCommand {
  int line = 0;                      // in its script (0 for a command typed in a session)
  std::vector<std::string> words;    // the command and its arguments
  std::string text;                  // the whole line, trimmed
  std::vector<std::string> output;   // the indented lines after it: what it caused
};

struct Script {
  std::string origin;  // a file's path, for messages
  std::string model;   // the statechart's name (its `model` line)
  std::vector<ScriptCommand> commands;
};

/** A script or a command that cannot be run; what() is "origin:line: why". */
class ScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/** Reads a script; throws ScriptError for a missing `model` or `start`, or stray lines. */
Script ParseScript(std::istream& in, const std::string& origin);
Script ReadScript(const std::filesystem::path& file);
/** One command line (no expected lines); throws ScriptError for an empty line. */
ScriptCommand ParseCommand(const std::string& text, int line = 0);
/** The commands and their lines in the script format (what ParseScript reads back). */
std::string Transcript(const std::vector<ScriptCommand>& commands);

std::string Trim(const std::string& text);

}  // namespace kse::simulation
