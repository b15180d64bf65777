// mergeguard check SCENARIO.json [--planner P] [--report DIR] [--json] [--save-trace FILE]:
// simulate, judge every rule, assign liability (spec §8, §10); optionally write the run's
// observable trace (docs/trace_format.md), which `check-trace` judges to the same output. Exit 0
// when every rule holds, 1 otherwise.
#include <string>

#include <CLI/CLI.hpp>

#include "cli/check_output.h"
#include "cli/command.h"
#include "core/observed_trace_json.h"
#include "core/output_path.h"
#include "core/scenario.h"
#include "planner/planner.h"
#include "rules/check.h"
#include "sim/checked_run.h"

namespace mg::cli {
namespace {

int run_check(const std::vector<std::string>& args) {
  CLI::App app("Simulate a scenario, check every rule, assign liability", "mergeguard check");
  std::string path;
  std::string planner_name = "rcpp";
  std::string trace_path;
  CheckOutput output;
  app.add_option("scenario", path, "scenario JSON file")->required();
  app.add_option("--planner", planner_name, "a registered planner (built in: rcpp, rcpp-coop, tripfield)")->check(CLI::IsMember(planner_names()));
  add_check_output_options(app, output);
  app.add_option("--save-trace", trace_path, "write the run's observable trace (docs/trace_format.md) to this file");
  if (!parse_args(app, args)) return kExitOk;
  const Scenario scenario = load_scenario(path);
  prepare_check_output(output);
  if (!trace_path.empty()) check_output_file("--save-trace", trace_path);
  const bool written = !trace_path.empty() || !output.report_dir.empty();
  const CheckResult result =
      check_scenario(scenario, planner_name, written ? PlannerAccount::kDecisions : PlannerAccount::kNameOnly);
  if (!trace_path.empty()) write_observed_trace(result.trace, trace_path);
  return emit_check_result(result, output);
}

}  // namespace

Command check_command() {
  return {"check", "check SCENARIO.json [--planner rcpp|rcpp-coop|tripfield] [--report DIR] [--json] [--save-trace FILE]", run_check};
}

}  // namespace mg::cli
