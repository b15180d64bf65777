// mergeguard check SCENARIO.json [--planner P] [--report DIR] [--json] [--save-trace FILE]:
// simulate, judge every rule, assign liability (spec §8, §10); optionally write the run's
// observable trace (docs/trace_format.md), which `check-trace` judges to the same output. Exit 0
// when every rule holds, 1 otherwise. An exec planner that misbehaves (planner/planner_fault.h)
// fails property planner_responds: exit 1 with the reason, and no report or trace.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "check/checked_run.h"
#include "cli/check_output.h"
#include "cli/command.h"
#include "cli/planner_option.h"
#include "core/observed_trace_json.h"
#include "core/output_path.h"
#include "core/scenario.h"
#include "planner/planner.h"
#include "planner/planner_fault.h"
#include "planner/planner_params.h"
#include "rules/check.h"

namespace mg::cli {
namespace {

int planner_fault_found(const Scenario& scenario, const std::string& planner, const PlannerFault& fault, bool json) {
  if (json)
    std::cout << nlohmann::json{{"scenario", scenario.name}, {"planner", planner}, {"holds", false},
                                {"planner_responds", {{"rule", fault.kind}, {"time_s", fault.time_s}, {"detail", fault.what()}}}}
                     .dump(2)
              << "\n";
  else
    std::cout << "scenario " << scenario.name << ", planner " << planner << ": VIOLATED planner_responds (" << fault.kind
              << "): " << fault.what() << "\n";
  return kExitViolation;
}

int run_check(const std::vector<std::string>& args) {
  CLI::App app("Simulate a scenario, check every rule, assign liability", "mergeguard check");
  std::string path;
  PlannerChoice planner{"rcpp"};
  std::string trace_path;
  CheckOutput output;
  app.add_option("scenario", path, "scenario JSON file")->required();
  add_planner_options(app, planner, "a registered planner (built in: rcpp, rcpp-coop, tripfield, mobil, frenet) or 'exec:COMMAND ARGS'");
  add_check_output_options(app, output);
  app.add_option("--save-trace", trace_path, "write the run's observable trace (docs/trace_format.md) to this file");
  if (!parse_args(app, args)) return kExitOk;
  const Scenario scenario = load_planner_scenario(path);
  prepare_check_output(output);
  if (!trace_path.empty()) check_output_file("--save-trace", trace_path);
  start_planner(planner.name, planner);
  const bool written = !trace_path.empty() || !output.report_dir.empty();
  CheckResult result;
  try {
    result = check_scenario(scenario, planner.name, written ? PlannerAccount::kDecisions : PlannerAccount::kNameOnly);
  } catch (const PlannerFault& fault) {
    return planner_fault_found(scenario, planner.name, fault, output.json);
  }
  if (!trace_path.empty()) write_observed_trace(result.trace, trace_path);
  return emit_check_result(result, output);
}

}  // namespace

Command check_command() {
  return {"check", "check SCENARIO.json [--planner rcpp|rcpp-coop|tripfield|mobil|frenet|exec:CMD] [--planner-timeout S] [--planner-start-timeout S] [--report DIR] [--json] [--save-trace FILE]", run_check};
}

}  // namespace mg::cli
