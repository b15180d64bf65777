// The --planner, --planner-timeout and --planner-start-timeout options of `plan`, `check`, `fuzz`
// and `replay` (`league` takes the timeouts): a registered planner or an exec planner
// ('exec:COMMAND ARGS', planner/exec_planner.h). An exec planner is started once before any work:
// a command that cannot start or does not answer hello within the start timeout is a usage error
// (exit 2, one line), not a finding.
#pragma once

#include <string>

#include "planner/exec_protocol.h"

namespace CLI {
class App;
}

namespace mg::cli {

struct PlannerChoice {
  std::string name;               // empty: none given (replay: each case's own)
  double timeout_s = 1.0;         // per exec planner call
  double start_timeout_s = 30.0;  // for an exec planner's hello, at each start of its process
};

// "" when `name` is a registered planner or exec:COMMAND; otherwise the one-line complaint,
// naming the registered planners.
std::string unknown_planner_message(const std::string& name);

// Adds --planner (checked against the registry, or exec:COMMAND), --planner-timeout S and
// --planner-start-timeout S.
void add_planner_options(CLI::App& app, PlannerChoice& choice, const std::string& help);
// The two timeouts alone (a command that names its planners otherwise, as `league`).
void add_planner_timeout_options(CLI::App& app, PlannerChoice& choice);

// Sets the exec planners' timeouts and stderr log directory (empty: mergeguard's stderr) and, when
// `name` is an exec planner, starts it and exchanges hello (UsageError otherwise). Returns its
// hello; an empty identity for a registered planner.
// `option` names the option the planner came from in the error.
PlannerIdentity start_planner(const std::string& name, const PlannerChoice& choice, const std::string& log_dir = "",
                              const std::string& option = "--planner");

// Where exec planners' children write their stderr: `report_dir`, or a fresh temporary directory
// (commands name it in their summary) when there is none.
std::string planner_log_dir(const std::string& report_dir);

}  // namespace mg::cli
