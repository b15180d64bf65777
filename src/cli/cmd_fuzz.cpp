// mergeguard fuzz [--time S | --runs N] [--seed S] [--jobs J] [--shard K/N] [--planner P]
//                 [--corpus DIR] [--report DIR] [--json]: a property-based fuzzing campaign
// (DESIGN §9, §10; docs/fuzzing.md). Exit 0 when no scenario failed a property, 1 when one did.
#include <unistd.h>

#include <csignal>
#include <map>
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/input_error.h"
#include "fuzz/campaign.h"
#include "fuzz/campaign_report.h"
#include "fuzz/corpus_case.h"
#include "planner/planner.h"
#include "rules/check.h"
#include "rules/report_json.h"

namespace mg::cli {
namespace {

std::atomic<bool> g_stop{false};

extern "C" void on_sigint(int) { g_stop.store(true); }  // lock-free atomic: async-signal-safe

// Ctrl-C stops the campaign after the runs in flight (shrinking keeps its best so far); a second
// Ctrl-C kills as usual (SA_RESETHAND). The previous handler is restored on scope exit.
class SigintGuard {
 public:
  SigintGuard() {
    g_stop = false;
    struct sigaction sa {};
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &sa, &previous_);
  }
  ~SigintGuard() { sigaction(SIGINT, &previous_, nullptr); }
  SigintGuard(const SigintGuard&) = delete;
  SigintGuard& operator=(const SigintGuard&) = delete;

 private:
  struct sigaction previous_ {};
};

std::string clock_time(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  return buf;
}

// One status line on stderr: rewritten in place on a terminal, one line per 10 s in logs.
std::function<void(const fuzz::CampaignProgress&)> progress_printer(bool tty) {
  return [tty, last_logged = -1e9](const fuzz::CampaignProgress& p) mutable {
    if (!tty && p.elapsed_s - last_logged < 10.0) return;
    last_logged = p.elapsed_s;
    char line[256];
    std::snprintf(line, sizeof line, "fuzz: %llu scenarios (%.1f/s), %llu violations, %zu signatures, %s elapsed, %s left",
                  static_cast<unsigned long long>(p.scenarios), p.elapsed_s > 0 ? p.scenarios / p.elapsed_s : 0.0,
                  static_cast<unsigned long long>(p.failing_scenarios), p.signatures, clock_time(p.elapsed_s).c_str(),
                  p.remaining_s ? clock_time(*p.remaining_s).c_str() : "--:--:--");
    std::cerr << (tty ? "\r" : "") << line << (tty ? "\033[K" : "\n") << std::flush;
  };
}

void parse_shard(const std::string& text, fuzz::CampaignOptions& o) {
  int k = -1, n = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d/%d%c", &k, &n, &extra) != 2 || n < 1 || k < 0 || k >= n)
    throw UsageError("--shard: expected K/N with 0 <= K < N, got '" + text + "'");
  o.shard_index = k;
  o.shard_count = n;
}

// A liability report (rules/report_*.h) per new corpus case, in DIR/cases/<case name>/;
// returns case path -> report.html relative to DIR.
std::map<std::string, std::string> write_liability_reports(const std::string& dir, const fuzz::CampaignResult& r) {
  std::map<std::string, std::string> links;
  for (const std::string& path : r.new_cases) {
    const fuzz::CorpusCase c = fuzz::load_case(path);
    const std::string rel = "cases/" + c.signature.file_stem();
    write_check_reports(dir + "/" + rel, c.scenario, check_scenario(c.scenario, c.signature.planner));
    links[path] = rel + "/report.html";
  }
  return links;
}

void print_human(const fuzz::CampaignOptions& o, const fuzz::CampaignResult& r) {
  std::cout << r.scenarios << " scenarios in " << r.seconds << " s (" << r.scenarios_per_second() << "/s)"
            << (r.interrupted ? ", interrupted" : "") << ": " << r.failing_scenarios << " failing, "
            << r.signatures.size() << " signatures\n";
  for (const auto& [sig, rec] : r.signatures)
    std::cout << "  " << sig.key() << ": " << rec.count << " scenarios, first run " << rec.first_run
              << (rec.known_before ? " (already in the corpus)" : "") << (rec.case_path.empty() ? "" : " -> " + rec.case_path)
              << "\n";
  for (const std::string& line : fuzz::coverage_warnings(o, r))
    if (line.rfind("Warning", 0) == 0) std::cout << line << "\n";
}

int run_fuzz_checked(const std::vector<std::string>& args) {
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
  app.add_option("--planner", o.planner, "rcpp, rcpp-coop or tripfield")->check(CLI::IsMember(planner_names()));
  app.add_option("--corpus", o.corpus_dir, "corpus directory (minimal cases are added here, one per new signature)");
  app.add_option("--report", report_dir, "write report.json, report.md, report.html here");
  app.add_flag("--json", json, "print one JSON summary on stdout");
  app.add_option("--max-vehicles", o.gen.max_vehicles, "main-lane vehicles per scenario, 0..N (default 6)");
  std::string families = "mixed";
  app.add_option("--families", families, "mixed (default: uniform plus the targeted families) or uniform")
      ->check(CLI::IsMember({"mixed", "uniform"}));
  app.add_option("--determinism-every", o.determinism_every, "check determinism on every k-th run (0: never; default 8)");
  app.add_option("--shrink-attempts", o.shrink.max_attempts, "candidate checks per shrink (default 600)");
  app.add_option("--shrink-time", o.shrink.max_seconds, "seconds per shrink (default 60)");
  if (!parse_args(app, args)) return kExitOk;
  parse_shard(shard, o);
  o.gen.targeted_families = families == "mixed";
  if (time_opt->count() > 0) o.time_s = time_s;
  else o.runs = runs_opt->count() > 0 ? runs : 1000;

  const std::string planner = o.planner;
  const fuzz::CheckFactory make_check = [planner] {
    return fuzz::CheckFn([planner](const Scenario& s) { return check_scenario(s, planner); });
  };
  SigintGuard guard;
  o.stop = &g_stop;
  o.on_progress = progress_printer(::isatty(STDERR_FILENO) != 0);
  if (!report_dir.empty())  // a killed campaign still leaves a report at most a minute old
    o.on_checkpoint = [&o, &report_dir](const fuzz::CampaignResult& r) { fuzz::write_campaign_report(report_dir, o, r, {}); };
  const fuzz::CampaignResult result = fuzz::run_campaign(o, make_check);
  if (::isatty(STDERR_FILENO)) std::cerr << "\n";
  if (!report_dir.empty()) fuzz::write_campaign_report(report_dir, o, result, write_liability_reports(report_dir, result));
  if (json) std::cout << fuzz::campaign_summary_json(o, result).dump(2) << "\n";
  else print_human(o, result);
  return result.failing_scenarios > 0 ? kExitViolation : kExitOk;
}

// I/O failures (an unwritable corpus or report directory, a full disk) end the campaign with a
// one-line error and exit 2 instead of an uncaught exception; cases already written stay.
int run_fuzz(const std::vector<std::string>& args) {
  try {
    return run_fuzz_checked(args);
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {  // std::filesystem::filesystem_error included
    throw UsageError(e.what());
  }
}

const CommandRegistration kRegistration(
    "fuzz",
    "fuzz [--time S | --runs N] [--seed S] [--jobs J] [--shard K/N] [--planner P] [--corpus DIR] [--report DIR] [--json]",
    run_fuzz);

}  // namespace
}  // namespace mg::cli
