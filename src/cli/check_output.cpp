#include "cli/check_output.h"

#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/output_path.h"
#include "report/report_json.h"
#include "report/report_markdown.h"

namespace mg::cli {
namespace {

// Everything printed comes from the judgement and its trace (the trace's name is the scenario's
// for a simulated run), never from the scenario file: `check-trace` has none.
void print_human(const CheckResult& r, const std::string& report_dir) {
  std::cout << "scenario:  " << r.trace.name << "\n"
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

}  // namespace

void add_check_output_options(CLI::App& app, CheckOutput& out) {
  app.add_option("--report", out.report_dir, "write report.json, report.md and report.html into this directory");
  app.add_flag("--json", out.json, "print the report JSON on stdout");
}

void prepare_check_output(const CheckOutput& out) {
  if (!out.report_dir.empty()) prepare_output_dir("--report", out.report_dir);
}

int emit_check_result(const CheckResult& result, const CheckOutput& out) {
  if (!out.report_dir.empty()) write_check_reports(out.report_dir, result);
  if (out.json) {
    std::cout << report_json(result).dump(2) << "\n";
  } else {
    print_human(result, out.report_dir);
  }
  return result.holds ? kExitOk : kExitViolation;
}

}  // namespace mg::cli
