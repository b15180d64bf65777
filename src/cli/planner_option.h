// The --planner and --planner-timeout options of `plan`, `check`, `fuzz` and `replay`: a
// registered planner or an exec planner ('exec:COMMAND ARGS', planner/exec_planner.h). An exec
// planner is started once before any work: a command that cannot start or does not answer hello
// is a usage error (exit 2, one line), not a finding.
#pragma once

#include <string>

#include "planner/exec_protocol.h"

namespace CLI {
class App;
}

namespace mg::cli {

struct PlannerChoice {
  std::string name;         // empty: none given (replay: each case's own)
  double timeout_s = 1.0;   // per exec planner call
};

// Adds --planner (checked against the registry, or exec:COMMAND) and --planner-timeout S.
void add_planner_options(CLI::App& app, PlannerChoice& choice, const std::string& help);

// Sets the exec planners' timeout and stderr log directory (empty: mergeguard's stderr) and, when
// `name` is an exec planner, starts it and exchanges hello (UsageError otherwise). Returns its
// hello; an empty identity for a registered planner.
PlannerIdentity start_planner(const std::string& name, const PlannerChoice& choice, const std::string& log_dir = "");

}  // namespace mg::cli
