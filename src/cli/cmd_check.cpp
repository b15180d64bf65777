// mergeguard check SCENARIO.json [--planner P] [--report DIR] [--json] [--save-trace FILE]:
// simulate, judge every rule, assign liability (spec §8, §10); optionally write the run's
// observable trace (docs/trace_format.md). Exit 0 when every rule holds, 1 otherwise.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/observed_trace_json.h"
#include "core/output_path.h"
#include "core/scenario.h"
#include "planner/planner.h"
#include "rules/check.h"
#include "sim/checked_run.h"
#include "rules/report_json.h"
#include "rules/report_markdown.h"
#include "sim/observed_run.h"

namespace mg::cli {
namespace {

void print_human(const Scenario& s, const CheckResult& r, const std::string& report_dir) {
  std::cout << "scenario:  " << s.name << "\n"
            << "planner:   " << r.planner << "\n"
            << "verdict:   " << (r.holds ? "holds" : "violated") << "\n"
            << "liable:    " << party_name(r.liable_id) << "\n";
  if (r.collision) std::cout << "collision: liable " << party_name(r.collision_liable_id) << "\n";
  if (!r.liability_detail.empty()) std::cout << "why:       " << r.liability_detail << "\n";
  for (const RuleResult& rule : r.rules) {
    if (rule.holds) continue;
    std::cout << "violated:  " << rule.rule_id << " (" << rule.paper_ref << ") at t = "
              << format_number(*rule.first_violation_time_s, 2) << " s, liable " << party_name(rule.liable_id)
              << ", margin " << format_number(rule.min_margin) << " " << rule.unit << "\n";
  }
  if (!report_dir.empty()) std::cout << "report:    " << report_dir << "/report.{json,md,html}\n";
}

int run_check(const std::vector<std::string>& args) {
  CLI::App app("Simulate a scenario, check every rule, assign liability", "mergeguard check");
  std::string path;
  std::string planner_name = "rcpp";
  std::string report_dir;
  std::string trace_path;
  bool json = false;
  app.add_option("scenario", path, "scenario JSON file")->required();
  app.add_option("--planner", planner_name, "a registered planner (built in: rcpp, rcpp-coop, tripfield)")->check(CLI::IsMember(planner_names()));
  app.add_option("--report", report_dir, "write report.json, report.md and report.html into this directory");
  app.add_flag("--json", json, "print the report JSON on stdout");
  app.add_option("--save-trace", trace_path, "write the run's observable trace (docs/trace_format.md) to this file");
  if (!parse_args(app, args)) return kExitOk;
  const Scenario scenario = load_scenario(path);
  if (!report_dir.empty()) prepare_output_dir("--report", report_dir);
  if (!trace_path.empty()) check_output_file("--save-trace", trace_path);
  const CheckResult result = check_scenario(scenario, planner_name);
  if (!trace_path.empty()) write_observed_trace(result.trace, trace_path);
  if (!report_dir.empty()) write_check_reports(report_dir, result);
  if (json) {
    std::cout << report_json(result).dump(2) << "\n";
  } else {
    print_human(scenario, result, report_dir);
  }
  return result.holds ? kExitOk : kExitViolation;
}

}  // namespace

Command check_command() {
  return {"check", "check SCENARIO.json [--planner rcpp|rcpp-coop|tripfield] [--report DIR] [--json] [--save-trace FILE]", run_check};
}

}  // namespace mg::cli
