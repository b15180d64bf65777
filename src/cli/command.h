// Subcommands of the mergeguard command line. Each cmd_<name>.cpp defines one <name>_command();
// commands() lists them and cli_main (cli/cli_main.h) dispatches. Exit codes (spec §10): 0 holds,
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
inline constexpr int kExitInterrupted = 3;  // fuzz or league stopped by SIGINT, SIGTERM or SIGHUP

// args excludes the program and subcommand names.
using CommandFn = std::function<int(const std::vector<std::string>& args)>;

struct Command {
  std::string name;   // e.g. "plan"
  std::string usage;  // one line, e.g. "plan SCENARIO.json [--planner P] [--json]"
  CommandFn run;
  bool hidden = false;  // a maintainer's tool: runs, but the usage does not list it
};

// Every subcommand by name. The list is explicit (command.cpp), not filled by static
// registration objects in the cmd_*.cpp files: they live in a static library (mg_cli), and the
// linker drops an object file that nothing references, its static initialisers with it.
const std::map<std::string, Command>& commands();

Command audit_command();
Command check_command();
Command check_trace_command();
Command corpus_command();
Command fuzz_command();
Command league_command();
Command params_command();
Command plan_command();
Command replay_command();
Command report_command();
Command reproduce_paper_command();
Command rss_command();

// Thrown by argument parsing helpers; cli_main prints "mergeguard <cmd>: <message>" and exits 2.
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
