// mergeguard league --planners A,B,... [--runs N | --time S] [--seed S] [--jobs J] [--report DIR] [--json]
//                   [--max-vehicles N] [--families mixed|uniform] [--planner-timeout S] [--planner-start-timeout S]:
// every planner, registered or exec:COMMAND, on exactly the same generated scenarios, one row each
// (docs/league.md). Exit 0 when the league ran to its end (its failures are the table's subject,
// not a verdict), 3 when a signal (SIGINT, SIGTERM, SIGHUP) stopped it early (its report and
// summary still written, for the scenarios every planner completed), 2 on bad input.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "check/checked_run.h"
#include "cli/command.h"
#include "cli/planner_option.h"
#include "cli/stop_signals.h"
#include "core/output_path.h"
#include "league/league.h"
#include "league/league_report.h"
#include "planner/exec_planner.h"
#include "report/report_table.h"

namespace mg::cli {
namespace {

// Starts every exec planner once (hello within the start timeout) before any work; their hellos.
nlohmann::json start_planners(const std::vector<std::string>& planners, const PlannerChoice& choice, const std::string& log_dir) {
  nlohmann::json hellos = nlohmann::json::object();
  for (const std::string& p : planners) {
    const PlannerIdentity id = start_planner(p, choice, log_dir, "--planners");
    if (is_exec_planner(p)) hellos[p] = {{"name", id.name}, {"version", id.version}};
  }
  return hellos;
}

void print_human(const league::LeagueResult& r, const std::string& report_dir) {
  std::cout << r.scenarios << " scenarios in " << r.seconds << " s"
            << (r.interrupted ? ", interrupted by " + r.stop_signal : "") << "\n\n"
            << table_markdown(league::standings_table(r));
  if (!report_dir.empty()) std::cout << "\nreport: " << report_dir << "/league.html\n";
}

int run_league(const std::vector<std::string>& args) {
  CLI::App app("A league of planners on the same generated scenarios", "mergeguard league");
  league::LeagueOptions o;
  std::uint64_t runs = 0;
  double time_s = 0.0;
  std::string report_dir;
  bool json = false;
  std::string families = "mixed";
  PlannerChoice choice;
  app.add_option("--planners", o.planners, "registered planners or 'exec:COMMAND ARGS', comma-separated (a command holds no comma)")
      ->delimiter(',')
      ->required();
  auto* runs_opt = app.add_option("--runs", runs, "scenarios, each driven by every planner; default 1000");
  auto* time_opt = app.add_option("--time", time_s, "wall-clock budget in seconds")->excludes(runs_opt);
  app.add_option("--seed", o.seed, "seed (scenario i is the fuzzing campaign's run i of this seed)");
  app.add_option("--jobs", o.jobs, "parallel workers (results do not depend on it)");
  app.add_option("--report", report_dir, "write league.{json,md,html,svg} and the worst runs' cases and liability reports here");
  app.add_flag("--json", json, "print the league as one JSON document on stdout");
  app.add_option("--max-vehicles", o.gen.max_vehicles, "main-lane vehicles per scenario, 0..N (default 6)");
  app.add_option("--families", families, "mixed (default: uniform plus the targeted families) or uniform")
      ->check(CLI::IsMember({"mixed", "uniform"}));
  add_planner_timeout_options(app, choice);
  if (!parse_args(app, args)) return kExitOk;
  for (const std::string& p : o.planners)
    if (const std::string why = unknown_planner_message(p); !why.empty()) throw UsageError("--planners: " + why);
  o.gen.targeted_families = families == "mixed";
  if (time_opt->count() > 0) o.time_s = time_s;
  else o.runs = runs_opt->count() > 0 ? runs : 1000;

  if (!report_dir.empty()) prepare_output_dir("--report", report_dir);  // before any work
  const bool any_exec = std::any_of(o.planners.begin(), o.planners.end(), is_exec_planner);
  const nlohmann::json hellos = start_planners(o.planners, choice, any_exec ? planner_log_dir(report_dir) : "");
  StopSignalGuard guard;
  o.stop = StopSignalGuard::stop_flag();
  o.on_progress = progress_printer("league", ::isatty(STDERR_FILENO) != 0);
  const league::LeagueCheckFactory make_check = [](const std::string& planner) {
    return fuzz::CheckFn([planner](const Scenario& s) { return check_scenario(s, planner); });
  };
  league::LeagueResult r = league::run_league(o, make_check);
  if (r.interrupted) r.stop_signal = StopSignalGuard::stop_signal_name();
  if (::isatty(STDERR_FILENO)) std::cerr << "\n";
  const league::SavedCases saved = report_dir.empty() ? league::SavedCases{} : league::save_worst_cases(report_dir, o, r);
  if (any_exec) r.planner_processes = {{"hellos", hellos}, {"logs", exec_planner_logs()}};
  if (!report_dir.empty()) league::write_league_report(report_dir, o, r, saved);
  if (json) std::cout << league::league_json(o, r, saved).dump(2) << "\n";
  else print_human(r, report_dir);
  return r.interrupted ? kExitInterrupted : kExitOk;
}

}  // namespace

Command league_command() {
  return {"league",
          "league --planners A,B,... [--runs N | --time S] [--seed S] [--jobs J] [--report DIR] [--json] [--max-vehicles N] "
          "[--families mixed|uniform] [--planner-timeout S] [--planner-start-timeout S]",
          run_league};
}

}  // namespace mg::cli
