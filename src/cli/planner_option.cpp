#include "cli/planner_option.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "planner/exec_planner.h"
#include "planner/planner.h"

namespace mg::cli {

std::string unknown_planner_message(const std::string& name) {
  const std::vector<std::string> names = planner_names();
  if (is_exec_planner(name) || std::find(names.begin(), names.end(), name) != names.end()) return "";
  std::string list;
  for (const std::string& n : names) list += n + ", ";
  return "unknown planner '" + name + "' (known: " + list + "or exec:COMMAND)";
}

void add_planner_options(CLI::App& app, PlannerChoice& choice, const std::string& help) {
  const CLI::Validator known([](std::string& name) { return unknown_planner_message(name); }, "PLANNER");
  app.add_option("--planner", choice.name, help)->check(known);
  add_planner_timeout_options(app, choice);
}

void add_planner_timeout_options(CLI::App& app, PlannerChoice& choice) {
  // CLI::Range lets NaN through (every comparison with it is false).
  const CLI::Validator seconds(
      [](std::string& text) -> std::string {
        const double s = std::strtod(text.c_str(), nullptr);
        return s >= 0.001 && s <= 3600.0 ? "" : "expected seconds in [0.001, 3600], got '" + text + "'";
      },
      "S");
  app.add_option("--planner-timeout", choice.timeout_s, "seconds an exec planner may take per call (default 1)")->check(seconds);
  app.add_option("--planner-start-timeout", choice.start_timeout_s,
                 "seconds an exec planner may take to answer hello when its process starts (default 30)")
      ->check(seconds);
}

PlannerIdentity start_planner(const std::string& name, const PlannerChoice& choice, const std::string& log_dir,
                              const std::string& option) {
  set_exec_options({choice.timeout_s, choice.start_timeout_s, log_dir});
  if (!is_exec_planner(name)) return {};
  try {
    return start_exec_planner(name);
  } catch (const ExecStartError& e) {
    throw UsageError(option + ": " + e.what());
  }
}

std::string planner_log_dir(const std::string& report_dir) {
  if (!report_dir.empty()) return report_dir;
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("mergeguard-planner-logs-" + std::to_string(::getpid()));
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw UsageError("cannot create the planner log directory " + dir.string() + ": " + ec.message());
  return dir.string();
}

}  // namespace mg::cli
