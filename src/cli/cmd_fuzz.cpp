// mergeguard fuzz [--time S | --runs N] [--seed S] [--jobs J] [--shard K/N] [--planner P] [--planner-timeout S]
//                 [--planner-start-timeout S] [--search random|guided] [--corpus DIR] [--report DIR] [--json]: a property-based fuzzing campaign
// (spec §9, §10; docs/fuzzing.md). Exit 0 when no scenario failed a property, 1 when one did,
// 3 when a signal (SIGINT, SIGTERM, SIGHUP) stopped it early (its report and summary still written).
// An exec planner's children (one per worker) log their stderr into the report directory, or a
// temporary one without --report; the summary names the files.
#include <unistd.h>

#include <cstdio>
#include <map>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "check/checked_run.h"
#include "cli/command.h"
#include "cli/planner_option.h"
#include "cli/stop_signals.h"
#include "core/atomic_file.h"
#include "core/output_path.h"
#include "fuzz/campaign.h"
#include "fuzz/campaign_report.h"
#include "fuzz/corpus_case.h"
#include "planner/exec_planner.h"
#include "planner/planner.h"
#include "planner/planner_fault.h"
#include "report/report_json.h"
#include "rules/check.h"

namespace mg::cli {
namespace {

void parse_shard(const std::string& text, fuzz::CampaignOptions& o) {
  int k = -1, n = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &k, &n, &extra) != 2 || n < 1 || k < 0 || k >= n)
    throw UsageError("--shard: expected K/N with 0 <= K < N, got '" + text + "'");
  o.shard_index = k;
  o.shard_count = n;
}

// A liability report (report/report_*.h) per new corpus case, in DIR/cases/<case name>/;
// returns case path -> report.html relative to DIR.
std::map<std::string, std::string> write_liability_reports(const std::string& dir, const fuzz::CampaignResult& r) {
  std::map<std::string, std::string> links;
  for (const std::string& path : r.new_cases) {
    const fuzz::CorpusCase c = fuzz::load_case(path);
    // A planner_responds case has no run to report on (the case says why); a planner may also
    // fail to respond only in this run (a timeout on a loaded machine): no report then either.
    if (c.signature.property == fuzz::property::kPlannerResponds) continue;
    const std::string rel = "cases/" + c.signature.file_stem();
    CheckResult result;
    try {
      result = check_scenario(c.scenario, c.signature.planner, PlannerAccount::kDecisions);
    } catch (const PlannerFault&) {
      continue;
    }
    write_check_reports(dir + "/" + rel, result);
    links[path] = rel + "/report.html";
  }
  return links;
}

void print_human(const fuzz::CampaignOptions& o, const fuzz::CampaignResult& r) {
  std::cout << r.scenarios << " scenarios in " << r.seconds << " s (" << r.scenarios_per_second() << "/s)"
            << (r.interrupted ? ", interrupted by " + r.stop_signal : "") << ": " << r.failing_scenarios << " failing, "
            << r.signatures.size() << " signatures\n";
  if (o.search == fuzz::SearchMode::kGuided)
    std::cout << "  guided search: " << r.guided_runs << " runs perturbed low-margin scenarios, " << r.guided_failing_scenarios
              << " of them failing\n";
  for (const auto& [sig, rec] : r.signatures)
    std::cout << "  " << sig.key() << ": " << rec.count << " scenarios, first run " << rec.first_run
              << (rec.known_before ? " (already in the corpus)" : "") << (rec.case_path.empty() ? "" : " -> " + rec.case_path)
              << "\n";
  if (!r.planner_process.is_null()) std::cout << "  " << fuzz::planner_process_text(r) << "\n";
  for (const std::string& line : fuzz::coverage_warnings(o, r))
    if (line.rfind("Warning", 0) == 0) std::cout << line << "\n";
}

// I/O failures during the campaign (a full disk) end it with a one-line error and exit 2 (main);
// cases already written stay.
int run_fuzz(const std::vector<std::string>& args) {
  CLI::App app("Property-based fuzzing campaign", "mergeguard fuzz");
  fuzz::CampaignOptions o;
  o.planner = "rcpp";
  o.corpus_dir = "corpus/cases";
  std::uint64_t runs = 0;
  double time_s = 0.0;
  std::string shard = "0/1";
  std::string report_dir;
  bool json = false;
  auto* runs_opt = app.add_option("--runs", runs, "number of scenarios of the whole campaign (all shards); default 1000");
  auto* time_opt = app.add_option("--time", time_s, "wall-clock budget in seconds")->excludes(runs_opt);
  app.add_option("--seed", o.seed, "campaign seed (run i uses a seed derived from it and i)");
  app.add_option("--jobs", o.jobs, "parallel workers (results do not depend on it)");
  app.add_option("--shard", shard, "K/N: run only the indices i with i mod N = K");
  PlannerChoice choice{"rcpp"};
  add_planner_options(app, choice, "a registered planner (built in: rcpp, rcpp-coop, tripfield, mobil, frenet) or 'exec:COMMAND ARGS'");
  app.add_option("--corpus", o.corpus_dir, "corpus directory (minimal cases are added here, one per new signature)");
  app.add_option("--report", report_dir, "write report.json, report.md, report.html here");
  app.add_flag("--json", json, "print one JSON summary on stdout");
  app.add_option("--max-vehicles", o.gen.max_vehicles, "main-lane vehicles per scenario, 0..N (default 6)");
  std::string families = "mixed";
  app.add_option("--families", families, "mixed (default: uniform plus the targeted families) or uniform")
      ->check(CLI::IsMember({"mixed", "uniform"}));
  std::string search = "random";
  app.add_option("--search", search, "random (every run uniform) or guided (a share of the runs perturbs low-margin scenarios)")
      ->check(CLI::IsMember({"random", "guided"}));
  app.add_flag("--stop-on-failure", o.stop_on_failure, "stop starting runs after the first failing scenario (its case is still shrunk)");
  app.add_flag("--stop-on-new-failure", o.stop_on_new_failure,
               "stop starting runs after the first failing scenario with a signature the corpus does not hold yet");
  app.add_option("--determinism-every", o.determinism_every, "check determinism on every k-th run (0: never; default 8)");
  app.add_option("--shrink-attempts", o.shrink.max_attempts, "candidate checks per shrink (default 600)");
  app.add_option("--shrink-time", o.shrink.max_seconds, "seconds per shrink (default 60)");
  if (!parse_args(app, args)) return kExitOk;
  o.planner = choice.name;
  parse_shard(shard, o);
  o.gen.targeted_families = families == "mixed";
  o.search = *fuzz::search_mode_from_string(search);
  if (time_opt->count() > 0) o.time_s = time_s;
  else o.runs = runs_opt->count() > 0 ? runs : 1000;

  const std::string planner = o.planner;
  const fuzz::CheckFactory make_check = [planner] {
    return fuzz::CheckFn([planner](const Scenario& s) { return check_scenario(s, planner); });
  };
  // Before any work: an overnight campaign must not lose its cases or report in the morning.
  if (!o.corpus_dir.empty()) prepare_output_dir("--corpus", o.corpus_dir);
  if (!report_dir.empty()) prepare_output_dir("--report", report_dir);
  if (!o.corpus_dir.empty()) remove_stale_temporaries(o.corpus_dir);  // of campaigns killed while writing
  const std::string log_dir = is_exec_planner(o.planner) ? planner_log_dir(report_dir) : "";
  const PlannerIdentity hello = start_planner(o.planner, choice, log_dir);
  StopSignalGuard guard;
  o.stop = StopSignalGuard::stop_flag();
  o.on_progress = progress_printer("fuzz", ::isatty(STDERR_FILENO) != 0);
  if (!report_dir.empty())  // a killed campaign still leaves a report at most a minute old
    o.on_checkpoint = [&o, &report_dir](const fuzz::CampaignResult& r) { fuzz::write_campaign_report(report_dir, o, r, {}); };
  fuzz::CampaignResult result = fuzz::run_campaign(o, make_check);
  if (result.interrupted) result.stop_signal = StopSignalGuard::stop_signal_name();
  if (::isatty(STDERR_FILENO)) std::cerr << "\n";
  const auto liability_reports = report_dir.empty() ? std::map<std::string, std::string>{} : write_liability_reports(report_dir, result);
  if (is_exec_planner(o.planner))  // after the liability reports: their runs have a log too
    result.planner_process = {{"hello", {{"name", hello.name}, {"version", hello.version}}}, {"logs", exec_planner_logs()}};
  if (!report_dir.empty()) fuzz::write_campaign_report(report_dir, o, result, liability_reports);
  if (json) std::cout << fuzz::campaign_summary_json(o, result).dump(2) << "\n";
  else print_human(o, result);
  if (result.interrupted) return kExitInterrupted;
  return result.failing_scenarios > 0 ? kExitViolation : kExitOk;
}

}  // namespace

Command fuzz_command() {
  return {"fuzz",
          "fuzz [--time S | --runs N] [--seed S] [--jobs J] [--shard K/N] [--planner P|exec:CMD] [--planner-timeout S] [--planner-start-timeout S] [--search random|guided] [--corpus DIR] [--report DIR] [--json]",
          run_fuzz};
}

}  // namespace mg::cli
