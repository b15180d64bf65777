// Planners in any language: `--planner 'exec:COMMAND ARGS'` runs COMMAND
// through /bin/sh and speaks the JSON Lines protocol of docs/planner_protocol.md with it
// (planner/exec_protocol.h). Each thread (one campaign worker, or the main thread of `check`,
// `plan`, `replay`) owns one child per command, reused across scenarios through `reset` and
// restarted on the next scenario after a fault. A fault (timeout, bad reply, exit) is thrown as
// PlannerFault (planner/planner_fault.h): a finding, never an error of mergeguard.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "planner/exec_protocol.h"
#include "planner/planner.h"

namespace mg {

inline constexpr std::string_view kExecPlannerPrefix = "exec:";

// "exec:" followed by a command.
bool is_exec_planner(const std::string& name);

struct ExecOptions {
  double timeout_s = 1.0;  // per call: the reply must arrive within it (--planner-timeout)
  // hello, at each start of a child: a planner may load a model or a runtime first, which a call
  // never waits for (--planner-start-timeout)
  double start_timeout_s = 30.0;
  // Children started by make_exec_planner append their stderr to <log_dir>/planner-worker-<k>.log
  // (k = 0, 1, ... in the order threads start one); empty: their stderr is mergeguard's.
  std::string log_dir;
};
// Applies to children started afterwards; set it before a command starts any.
void set_exec_options(const ExecOptions& options);

// The command cannot be started or does not answer hello: a usage error (exit 2).
struct ExecStartError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Starts `name`'s command, exchanges hello and says bye: what a command line checks before any
// work. Throws ExecStartError with one line naming the process and what went wrong.
PlannerIdentity start_exec_planner(const std::string& name);

// A fresh planner (one simulation) speaking through this thread's child for `name`.
std::unique_ptr<Planner> make_exec_planner(const std::string& name);

// The hello of the last child started for `name` (nullopt: none has answered yet).
std::optional<PlannerIdentity> exec_planner_identity(const std::string& name);

// The log files of the children started by make_exec_planner so far, in order.
std::vector<std::string> exec_planner_logs();

}  // namespace mg
