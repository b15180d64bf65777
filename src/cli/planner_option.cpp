#include "cli/planner_option.h"

#include <algorithm>
#include <cstdlib>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "planner/exec_planner.h"
#include "planner/planner.h"

namespace mg::cli {

void add_planner_options(CLI::App& app, PlannerChoice& choice, const std::string& help) {
  const CLI::Validator known(
      [](std::string& name) -> std::string {
        const std::vector<std::string> names = planner_names();
        if (is_exec_planner(name) || std::find(names.begin(), names.end(), name) != names.end()) return "";
        std::string list;
        for (const std::string& n : names) list += n + ", ";
        return "unknown planner '" + name + "' (known: " + list + "or exec:COMMAND)";
      },
      "PLANNER");
  app.add_option("--planner", choice.name, help)->check(known);
  // CLI::Range lets NaN through (every comparison with it is false).
  const CLI::Validator seconds(
      [](std::string& text) -> std::string {
        const double s = std::strtod(text.c_str(), nullptr);
        return s >= 0.001 && s <= 3600.0 ? "" : "expected seconds in [0.001, 3600], got '" + text + "'";
      },
      "S");
  app.add_option("--planner-timeout", choice.timeout_s, "seconds an exec planner may take per call (default 1)")->check(seconds);
}

PlannerIdentity start_planner(const std::string& name, const PlannerChoice& choice, const std::string& log_dir) {
  set_exec_options({choice.timeout_s, log_dir});
  if (!is_exec_planner(name)) return {};
  try {
    return start_exec_planner(name);
  } catch (const ExecStartError& e) {
    throw UsageError(std::string("--planner: ") + e.what());
  }
}

}  // namespace mg::cli
