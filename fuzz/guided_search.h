// Robustness-guided search (docs/fuzzing.md "Guided search"). A campaign measures every rule's
// robustness margin on every scenario; guided search keeps, per rule, the few holding scenarios
// with the lowest margins seen so far (an elite pool) and spends a share of its runs on small
// perturbations of them, so that a rule running within centimetres of a violation is pushed over
// it, the way falsification tools (S-TaLiRo, VerifAI) climb toward low robustness. The other
// runs stay uniform, so coverage does not collapse onto the pool.
//
// Determinism: a shard's runs j = 0, 1, ... are grouped in batches of GuidedParams::batch_runs.
// A guided run of batch k draws its parent from the pool as it stood after batches 0..k-lag,
// which is fixed by the results of those runs alone, not by which worker finished first. A run
// is guided or uniform by a hash of (seed, run index), and a uniform run is exactly the random
// campaign's scenario of that index.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include "fuzz/scenario_spec.h"

namespace mg::fuzz {

enum class SearchMode { kRandom, kGuided };
std::string to_string(SearchMode mode);
std::optional<SearchMode> search_mode_from_string(const std::string& text);

struct GuidedParams {
  double guided_share = 0.5;        // of the runs after the warm-up batches
  std::size_t pool_size = 4;        // elites kept per rule
  std::uint64_t batch_runs = 64;    // shard-local runs per batch
  std::uint64_t lag_batches = 2;    // a run of batch k reads the pool of batches 0..k-lag
};

// True when run `run_index` of a campaign is a guided run: outside the first lag_batches batches
// of the shard, and chosen by a hash of (seed, run index) with probability guided_share.
bool is_guided_run(std::uint64_t campaign_seed, std::uint64_t run_index, std::uint64_t shard_run,
                   const GuidedParams& params);

// One small step of one scalar of a ScenarioSpec, inside the generator's range of that scalar.
struct KnobStep {
  int knob = 0;              // index into the knob table (guided_search.cpp)
  std::size_t vehicle = 0;   // for per-vehicle knobs; a step whose vehicle is gone does nothing
  double delta = 0.0;
};
using Perturbation = std::vector<KnobStep>;

// One to three knobs (positions, speeds, declared limits, behaviour timings, V2V latencies,
// rule-relevant parameters), each moved by a Gaussian step of 1 %, 3 % or 10 % of its range.
Perturbation draw_perturbation(const ScenarioSpec& parent, rc::Random random);
// Applies the steps, clamped to each knob's range and snapped to its grid.
ScenarioSpec apply_perturbation(ScenarioSpec spec, const Perturbation& steps);
// The knob table (for documentation and tests), and a knob's value in a spec (nullopt when the
// vehicle does not exist).
struct KnobInfo {
  std::string name;
  RealRange range;
  bool per_vehicle = false;
};
std::vector<KnobInfo> knobs();
std::optional<double> knob_value(const ScenarioSpec& spec, int knob, std::size_t vehicle);

// The elites: per rule, the pool_size holding scenarios of lowest margin, ties to the lower
// run. The spec is kept as its Shrinkable so that a failing child shrinks like any scenario.
struct Candidate {
  ScenarioSpec spec;
  rc::Shrinkable<ScenarioSpec> shrinkable;
};
struct Elite {
  double margin = 0.0;
  std::uint64_t run = 0;                       // campaign run index
  std::shared_ptr<const Candidate> candidate;  // shared by the run's offers and the pool's snapshots
};

class ElitePool {
 public:
  explicit ElitePool(std::size_t pool_size = 4) : pool_size_(pool_size) {}
  void offer(const std::string& rule, const Elite& elite);
  bool empty() const { return by_rule_.empty(); }
  // A parent: a rule uniformly among those with elites, then one of its elites uniformly.
  const Elite& pick(rc::Random& random) const;
  const std::map<std::string, std::vector<Elite>>& by_rule() const { return by_rule_; }

 private:
  std::size_t pool_size_;
  std::map<std::string, std::vector<Elite>> by_rule_;  // each sorted by (margin, run)
};

// What one finished run offers the pool: (rule, elite) for every rule that held with a finite
// margin.
using Offers = std::vector<std::pair<std::string, Elite>>;

// The pool over a shard's batches, shared by the campaign's workers. Every run the shard starts
// must be reported (with its offers, possibly none) so that its batch completes.
class PoolHistory {
 public:
  explicit PoolHistory(const GuidedParams& params);
  void complete(std::uint64_t shard_run, Offers offers);
  // The pool a guided run of shard run j reads: after batches 0..batch(j)-lag. Waits for those
  // batches; returns nullptr if `abandon()` becomes true first (the campaign is aborting).
  std::shared_ptr<const ElitePool> pool_for(std::uint64_t shard_run, const std::function<bool()>& abandon);
  // Wakes waiters so that they re-check `abandon`.
  void wake();

 private:
  GuidedParams params_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::uint64_t, std::pair<std::uint64_t, Offers>> pending_;  // batch -> (runs done, offers)
  std::uint64_t committed_batches_ = 0;                                // batches 0..n-1 are in the pool
  // [b]: the pool after batches < b, for the last lag_batches + 1 values of b only: a run still
  // waiting is in an uncommitted batch k, so it never needs a pool older than k - lag + 1.
  std::map<std::uint64_t, std::shared_ptr<const ElitePool>> pools_;
};

}  // namespace mg::fuzz
