// A league of planners (docs/league.md): every planner on exactly the same generated scenarios.
// Scenario i is the fuzzing campaign's run i (fuzz/scenario_gen.h: generate_scenario(run_seed(seed,
// i)), targeted families included), checked with each planner in turn by the campaign's pipeline
// (fuzz/properties.h run_properties: simulate, observe, judge, evaluate the properties). A
// planner's run fails when a property fails; its standing counts failing runs by rule and by
// liable party, and measures the run's efficiency from its observed trace (league/league_metrics.h).
//
// Workers (fuzz/worker_pool.h) take scenario indices from a shared counter and run every planner
// on each, so that with --time, too, all planners see the same scenarios: the indices a stopped
// league completed are 0 .. n-1. Each worker keeps its own standings; they are merged at the end
// by order-independent sums and sorted samples, so that for a seed and --runs the result does not
// depend on --jobs.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/campaign.h"
#include "fuzz/properties.h"
#include "fuzz/scenario_gen.h"
#include "league/league_metrics.h"

namespace mg::league {

struct LeagueOptions {
  std::vector<std::string> planners;   // registered names or exec:COMMAND, distinct
  std::uint64_t seed = 1;
  std::optional<std::uint64_t> runs;   // scenarios
  std::optional<double> time_s;        // wall-clock budget for starting new scenarios
  int jobs = 1;
  fuzz::GenConfig gen;
  const std::atomic<bool>* stop = nullptr;  // set (e.g. by SIGINT) to stop after the scenarios in flight
  std::function<void(const fuzz::CampaignProgress&)> on_progress;  // about every progress_period_s
  double progress_period_s = 1.0;
};

// Makes one check function for `planner`, for one worker (per-thread planner and simulator).
using LeagueCheckFactory = std::function<fuzz::CheckFn(const std::string& planner)>;

// The worst run of one failure signature: the one with the lowest margin (ties: the lowest run).
struct WorstRun {
  fuzz::Signature signature;
  std::uint64_t scenarios = 0;    // runs that failed with the signature
  std::uint64_t run = 0;
  double margin = 0.0;            // the failure's margin in its rule's unit
  fuzz::PropertyFailure failure;  // as it happened in that run
};

// One planner's results, summable over workers.
struct PlannerStanding {
  std::string planner;
  std::uint64_t scenarios = 0;
  std::uint64_t failing = 0;                       // runs with at least one property failure
  std::map<std::string, std::uint64_t> by_rule;    // runs failing through the rule
  std::map<std::string, std::uint64_t> by_party;   // runs failing with a party of that class liable
  std::uint64_t merged = 0;
  std::vector<double> merge_times_s;               // of the merged runs (sorted once finished)
  std::vector<double> path_lengths_m;              // of the merged runs
  std::vector<double> peak_lat_accels_mps2;        // of every judged run
  std::uint64_t judged = 0;                        // runs with a trace (no planner fault, no exception)
  std::int64_t halted_us = 0;                      // time halted over the judged runs, microseconds (exact sums)
  std::map<fuzz::Signature, WorstRun> worst;

  void add(std::uint64_t run, const fuzz::RunOutcome& outcome, const std::optional<RunMetrics>& metrics);
  void merge(const PlannerStanding& other);
  void finish();  // sorts the samples

  double failing_share() const;
  double merge_rate() const;
  std::optional<double> mean_halted_s() const;
};

struct LeagueResult {
  std::uint64_t scenarios = 0;          // scenarios every planner ran
  double seconds = 0.0;
  bool interrupted = false;
  std::string stop_signal;              // set by the CLI
  std::vector<PlannerStanding> standings;  // in the options' order
  // The exec planners' hellos by name, {"name", "version"}, and their stderr logs (set by the CLI).
  nlohmann::json planner_processes;
};

// Validates the options (std::invalid_argument naming the option) and runs.
LeagueResult run_league(const LeagueOptions& options, const LeagueCheckFactory& make_check);

}  // namespace mg::league
