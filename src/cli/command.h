// Subcommand registry of the mergeguard binary. Each cmd_<name>.cpp registers itself with a
// static CommandRegistration; main.cpp dispatches. Exit codes (spec §10): 0 holds,
// 1 violation found, 2 bad input, usage or I/O (one-line error on stderr), 3 a campaign stopped by
// a signal.
#pragma once

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace mg::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitViolation = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInterrupted = 3;  // fuzz stopped by SIGINT, SIGTERM or SIGHUP

// args excludes the program and subcommand names.
using CommandFn = std::function<int(const std::vector<std::string>& args)>;

struct Command {
  std::string usage;  // one line, e.g. "plan SCENARIO.json [--planner P] [--json]"
  CommandFn run;
};

std::map<std::string, Command>& commands();

struct CommandRegistration {
  CommandRegistration(const std::string& name, const std::string& usage, CommandFn fn) {
    commands()[name] = Command{usage, std::move(fn)};
  }
};

// Thrown by argument parsing helpers; main prints "mergeguard <cmd>: <message>" and exits 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace mg::cli

namespace CLI {
class App;
}

namespace mg::cli {
// Parses `args` with a CLI11 app (help and errors become UsageError; --help prints and
// returns false so the command exits 0).
bool parse_args(CLI::App& app, const std::vector<std::string>& args);
}  // namespace mg::cli
