// A fuzzing campaign (spec §9, §10 `mergeguard fuzz`): generate scenario i of the campaign
// from run_seed(seed, i), check it, evaluate every property, and shrink the first (lowest run
// index) failure of each new signature into one corpus case.
//
// Determinism: run i's scenario depends only on (seed, i). Shard K of N runs the indices
// i = K, K+N, K+2N, ... so shards are disjoint and together form the unsharded campaign. Workers
// take indices from a shared counter; each signature's case is shrunk from its lowest failing
// run index (a worker that finds a lower one re-shrinks and replaces the file), so with --runs
// the counts, signatures and cases do not depend on --jobs. Workers share nothing mutable but
// the counters and the signature table (under a mutex); each has its own check function.
// With --search guided (fuzz/guided_search.h) a share of the runs perturbs low-margin scenarios
// of earlier batches; the same guarantees hold (a shard steers by its own runs only).
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/guided_search.h"
#include "fuzz/properties.h"
#include "fuzz/scenario_gen.h"
#include "fuzz/shrink.h"

namespace mg::fuzz {

// Makes one check function per worker (per-thread planner, simulator and FCL objects).
using CheckFactory = std::function<CheckFn()>;

struct CampaignProgress {
  std::uint64_t scenarios = 0;
  std::uint64_t failing_scenarios = 0;
  std::size_t signatures = 0;
  double elapsed_s = 0.0;
  std::optional<double> remaining_s;   // estimate with --runs (after the first runs), exact with --time
};

inline constexpr std::size_t kMaxTimelineSamples = 512;

// Margin histogram bin edges (in each rule's unit); bins are (-inf,e0), [e0,e1), ..., [e_last,inf).
inline constexpr std::array<double, 7> kMarginBinEdges = {-10.0, -1.0, -0.1, 0.0, 0.1, 1.0, 10.0};

// One rule's robustness margins over a campaign. A rule is *exercised* by a scenario when it
// applied at least once in its trace (a finite minimum margin); the statistics (min, mean,
// histogram) are over the exercised scenarios only, so a rule that never applied has no
// statistics instead of a sentinel +infinity folded into the top bin.
struct MarginStats {
  std::string unit;
  std::uint64_t scenarios = 0;   // checked scenarios (the rule was evaluated)
  std::uint64_t exercised = 0;   // ... in which it applied at least once
  std::uint64_t violated = 0;
  double min = 0.0;              // meaningful when exercised > 0
  std::int64_t sum_micro = 0;   // sum of margins in micro-units, clamped to +-1e9: exact, order-independent
  std::optional<double> mean() const {
    if (exercised == 0) return std::nullopt;
    return static_cast<double>(sum_micro) * 1e-6 / static_cast<double>(exercised);
  }
  std::array<std::uint64_t, kMarginBinEdges.size() + 1> bins{};
  // `margin` is the rule's minimum over the trace: +infinity when the rule never applied.
  void add(double margin, bool holds);
  void merge(const MarginStats& other);
};

struct SignatureRecord {
  Signature signature;
  std::uint64_t count = 0;            // scenarios that failed with it
  std::uint64_t first_run = 0;        // lowest failing run index
  bool first_run_guided = false;      // ... was a guided run (--search guided)
  bool known_before = false;          // already in the corpus when the campaign started
  PropertyFailure example;            // the failure at first_run (before shrinking)
  std::string case_path;              // written case (new signatures with a corpus only)
  int shrink_steps = 0;
  int shrink_attempts = 0;
  bool shrink_minimal = false;
  std::size_t case_vehicles = 0;      // vehicles left in the minimal case
};

struct CampaignResult {
  std::uint64_t scenarios = 0;
  std::uint64_t failing_scenarios = 0;   // scenarios with at least one property failure
  std::uint64_t property_failures = 0;   // (scenario, signature) pairs
  double seconds = 0.0;
  bool interrupted = false;
  std::string stop_signal;                     // e.g. "SIGTERM" when interrupted (set by the CLI)
  // An exec planner's process (set by the CLI): {"hello": {name, version}, "logs": [stderr log
  // files, one per worker]}; null for registered planners.
  nlohmann::json planner_process;
  std::map<Signature, SignatureRecord> signatures;
  std::map<std::string, std::uint64_t> by_property, by_rule, by_party;  // (scenario, signature) counts
  std::map<std::string, MarginStats> margins;  // per rule, over every checked scenario (rule_coverage.h)
  std::uint64_t guided_runs = 0;               // runs that perturbed an elite (--search guided)
  std::uint64_t guided_failing_scenarios = 0;  // ... of which failed a property
  std::optional<std::uint64_t> first_failure_run;  // lowest failing run index
  std::optional<double> first_failure_s;           // seconds from the start to the first failing run (timing)
  // The same for the failing runs with a signature the corpus did not hold when the campaign
  // started (every failing run when there is no corpus).
  std::optional<std::uint64_t> first_new_failure_run;
  std::optional<double> first_new_failure_s;
  std::vector<std::string> new_cases;          // paths, sorted
  // Progress samples over the campaign (for the report's findings-over-time plot; timing, like
  // `seconds`): at most kMaxTimelineSamples, thinned by halving as the campaign goes on.
  std::vector<CampaignProgress> timeline;
  double scenarios_per_second() const { return seconds > 0.0 ? static_cast<double>(scenarios) / seconds : 0.0; }
};

struct CampaignOptions {
  std::uint64_t seed = 1;
  std::optional<std::uint64_t> runs;   // total run indices of the whole campaign (all shards)
  std::optional<double> time_s;        // wall-clock budget for generating new runs
  int jobs = 1;
  int shard_index = 0;                 // K of --shard K/N
  int shard_count = 1;                 // N
  std::string planner;                 // recorded when the check throws (else the result's planner)
  std::string corpus_dir;              // cases are written here; empty: failures are counted only
  GenConfig gen;
  SearchMode search = SearchMode::kRandom;
  GuidedParams guided;
  bool stop_on_failure = false;        // stop starting runs after the first failing scenario
  // ... after the first failing scenario with a signature the corpus did not hold at the start:
  // a campaign against a corpus of known open findings stops at the first finding it lacks.
  bool stop_on_new_failure = false;
  int determinism_every = 8;           // run i is checked twice when i % determinism_every == 0
  ShrinkBudget shrink;                 // `stop` is replaced by the campaign's own
  const std::atomic<bool>* stop = nullptr;  // set (e.g. by SIGINT) to stop after the runs in flight
  std::function<void(const CampaignProgress&)> on_progress;  // called about every progress_period_s
  double progress_period_s = 1.0;
  // Called about every checkpoint_period_s with the result so far (without margins), e.g. to
  // rewrite the report so that a killed campaign still leaves a recent one.
  std::function<void(const CampaignResult&)> on_checkpoint;
  double checkpoint_period_s = 60.0;
};

// Validates the options (InputError on nonsense such as jobs < 1 or K >= N) and runs.
CampaignResult run_campaign(const CampaignOptions& options, const CheckFactory& make_check);

// Number of run indices of [0, runs) that belong to shard K of N.
std::uint64_t runs_in_shard(std::uint64_t runs, int shard_index, int shard_count);

}  // namespace mg::fuzz
