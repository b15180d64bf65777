#include "fuzz/campaign.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "fuzz/corpus_case.h"
#include "fuzz/worker_pool.h"
#include "planner/exec_planner.h"

namespace mg::fuzz {
namespace {

using Clock = std::chrono::steady_clock;

// Shrinking may run this long past a --time deadline so that a late failure still gets a case.
constexpr double kShrinkGraceS = 10.0;

struct WorkerStats {
  std::map<std::string, MarginStats> margins;
};

class Campaign {
 public:
  Campaign(const CampaignOptions& options, const CheckFactory& make_check)
      : opt_(options), make_check_(make_check), start_(Clock::now()) {
    if (opt_.time_s) deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(*opt_.time_s));
    if (opt_.runs) shard_runs_ = runs_in_shard(*opt_.runs, opt_.shard_index, opt_.shard_count);
    if (!opt_.corpus_dir.empty()) known_ = corpus_signatures(opt_.corpus_dir);
    if (opt_.search == SearchMode::kGuided) history_ = std::make_unique<PoolHistory>(opt_.guided);
  }

  CampaignResult run() {
    std::vector<WorkerStats> stats(static_cast<std::size_t>(opt_.jobs));
    Ticks ticks(opt_);
    run_workers(
        opt_.jobs, [this, &stats](int w) { work(stats[static_cast<std::size_t>(w)]); }, [this, &ticks] { tick(ticks); },
        [this] {
          abort_ = true;
          if (history_) history_->wake();  // guided runs waiting for the failed worker's batch give up
        });
    if (opt_.on_progress) opt_.on_progress(progress());
    timeline_.push_back(progress());
    return collect(stats);
  }

 private:
  bool externally_stopped() const { return opt_.stop != nullptr && opt_.stop->load(); }
  bool should_stop() const {
    return abort_.load() || externally_stopped() || (opt_.stop_on_failure && failing_.load() > 0) ||
           (opt_.stop_on_new_failure && new_failing_.load() > 0) ||
           (deadline_ && Clock::now() >= *deadline_);
  }

  void work(WorkerStats& stats) {
    const CheckFn check = make_check_();
    while (!should_stop()) {
      const std::uint64_t j = next_.fetch_add(1);
      if (shard_runs_ && j >= *shard_runs_) break;
      run_one(check, static_cast<std::uint64_t>(opt_.shard_index) + static_cast<std::uint64_t>(opt_.shard_count) * j, j, stats);
    }
  }

  // Run i's scenario: the random campaign's, or in a guided run a perturbed elite. The spec is
  // kept (guided search only) so that the run can become an elite itself.
  struct Draw {
    std::shared_ptr<const Candidate> spec;
    rc::Shrinkable<Scenario> scenario;
    bool guided = false;
  };

  // nullopt when a guided run gave up waiting for its pool (the campaign is aborting).
  std::optional<Draw> draw(std::uint64_t i, std::uint64_t j) const {
    if (!history_) return Draw{nullptr, generate_scenario(run_seed(opt_.seed, i), opt_.gen), false};
    std::shared_ptr<const Candidate> candidate;
    if (is_guided_run(opt_.seed, i, j, opt_.guided)) {
      const auto pool = history_->pool_for(j, [this] { return abort_.load(); });
      if (!pool) return std::nullopt;
      if (!pool->empty()) candidate = perturbed(*pool, i);
    }
    const bool guided = candidate != nullptr;
    if (!guided) {
      const rc::Shrinkable<ScenarioSpec> spec = generate_spec(run_seed(opt_.seed, i), opt_.gen);
      candidate = std::make_shared<const Candidate>(Candidate{spec.value(), spec});
    }
    return Draw{candidate, rc::shrinkable::map(candidate->shrinkable, assemble_scenario), guided};
  }

  std::shared_ptr<const Candidate> perturbed(const ElitePool& pool, std::uint64_t i) const {
    rc::Random random(run_seed(opt_.seed ^ 0x7065727475726221ULL, i));  // "perturb!"
    const Candidate& parent = *pool.pick(random).candidate;
    const Perturbation steps = draw_perturbation(parent.spec, random);
    return std::make_shared<const Candidate>(
        Candidate{apply_perturbation(parent.spec, steps),
                  rc::shrinkable::map(parent.shrinkable, [steps](ScenarioSpec s) { return apply_perturbation(std::move(s), steps); })});
  }

  static Offers offers_of(const RunOutcome& outcome, std::uint64_t i, const std::shared_ptr<const Candidate>& spec) {
    Offers offers;
    if (outcome.result)
      for (const RuleResult& r : outcome.result->rules)
        if (r.holds && std::isfinite(r.min_margin)) offers.emplace_back(r.rule_id, Elite{r.min_margin, i, spec});
    return offers;
  }

  void run_one(const CheckFn& check, std::uint64_t i, std::uint64_t j, WorkerStats& stats) {
    const std::optional<Draw> drawn = draw(i, j);
    if (!drawn) return;
    const Scenario scenario = drawn->scenario.value();
    const bool twice = opt_.determinism_every > 0 && i % static_cast<std::uint64_t>(opt_.determinism_every) == 0;
    const RunOutcome outcome = run_properties(scenario, check, opt_.planner, twice);
    if (outcome.result)
      for (const RuleResult& r : outcome.result->rules) {
        MarginStats& m = stats.margins[r.rule_id];
        m.unit = r.unit;
        m.add(r.min_margin, r.holds);
      }
    // Before shrinking, which can take a minute: guided runs of later batches wait for this one.
    if (history_) history_->complete(j, offers_of(outcome, i, drawn->spec));
    std::map<Signature, PropertyFailure> distinct;  // first failure per signature in this scenario
    for (const PropertyFailure& f : outcome.failures) distinct.try_emplace(signature_of(outcome.planner, f), f);
    if (!distinct.empty()) {
      const bool is_new = std::any_of(distinct.begin(), distinct.end(), [&](const auto& d) { return !known_.count(d.first); });
      note_failing_run(i, drawn->guided, is_new);
    }
    for (const auto& [signature, failure] : distinct) {
      if (claim_for_shrinking(signature, failure, i, drawn->guided))
        shrink_into_corpus(check, signature, failure, i, drawn->scenario);
    }
    if (drawn->guided) ++guided_runs_;
    ++scenarios_;
  }

  // `is_new`: the run fails with a signature the corpus did not hold at the start.
  void note_failing_run(std::uint64_t i, bool guided, bool is_new) {
    {
      std::lock_guard lock(mutex_);
      const double now_s = std::chrono::duration<double>(Clock::now() - start_).count();
      if (!first_failure_run_ || i < *first_failure_run_) first_failure_run_ = i;
      if (!first_failure_s_) first_failure_s_ = now_s;
      if (is_new && (!first_new_failure_run_ || i < *first_new_failure_run_)) first_new_failure_run_ = i;
      if (is_new && !first_new_failure_s_) first_new_failure_s_ = now_s;
    }
    if (guided) ++guided_failing_;
    ++failing_;
    if (is_new) ++new_failing_;
  }

  // Counts the failure; true when run i is now the signature's lowest failing run and its case
  // is to be (re)written.
  bool claim_for_shrinking(const Signature& signature, const PropertyFailure& failure, std::uint64_t i, bool guided) {
    std::lock_guard lock(mutex_);
    auto [it, inserted] = signatures_.try_emplace(signature);
    SignatureRecord& rec = it->second;
    ++rec.count;
    if (inserted) {
      rec.signature = signature;
      rec.known_before = known_.count(signature) > 0;
    } else if (i >= rec.first_run) {
      return false;
    }
    rec.first_run = i;
    rec.first_run_guided = guided;
    rec.example = failure;
    return !opt_.corpus_dir.empty() && !rec.known_before;
  }

  void shrink_into_corpus(const CheckFn& check, const Signature& signature, const PropertyFailure& failure,
                          std::uint64_t i, const rc::Shrinkable<Scenario>& generated) {
    ShrinkBudget budget = opt_.shrink;
    budget.stop = opt_.stop;
    if (deadline_) {
      const double left_s = std::chrono::duration<double>(*deadline_ - Clock::now()).count() + kShrinkGraceS;
      budget.max_seconds = std::max(0.0, std::min(budget.max_seconds, left_s));
    }
    const bool twice = signature.property == property::kDeterminism;
    auto keeps_failure = [&](const Scenario& s) {
      const RunOutcome o = run_properties(s, check, opt_.planner, twice);
      return std::any_of(o.failures.begin(), o.failures.end(),
                         [&](const PropertyFailure& f) { return signature_of(o.planner, f) == signature; });
    };
    const ShrinkOutcome shrunk = shrink_scenario(generated, keeps_failure, budget);

    CorpusCase c;
    c.signature = signature;
    c.scenario = shrunk.scenario;
    c.scenario.name = signature.file_stem();
    c.scenario.description = "Found by mergeguard fuzz (seed " + std::to_string(opt_.seed) + ", run " +
                             std::to_string(i) + "), shrunk in " + std::to_string(shrunk.steps) + " steps.";
    const RunOutcome final_run = run_properties(c.scenario, check, opt_.planner, /*check_determinism=*/true);
    c.verdict = verdict_of(final_run);
    c.failure = failure;
    for (const PropertyFailure& f : final_run.failures)
      if (signature_of(final_run.planner, f) == signature) c.failure = f;
    c.provenance = {"mergeguard fuzz", opt_.seed, i, shrunk.steps, shrunk.attempts, shrunk.minimal, utc_now_iso8601()};
    c.planner_hello = exec_planner_identity(signature.planner);
    std::lock_guard lock(mutex_);
    SignatureRecord& rec = signatures_.at(signature);
    if (rec.first_run != i) return;  // a lower run index failed meanwhile; its case wins
    const std::string path = rec.case_path.empty() ? free_case_path(opt_.corpus_dir, signature.file_stem()) : rec.case_path;
    write_case(c, path);
    rec.case_path = path;
    rec.shrink_steps = shrunk.steps;
    rec.shrink_attempts = shrunk.attempts;
    rec.shrink_minimal = shrunk.minimal;
    rec.case_vehicles = c.scenario.vehicles.size();
  }

  CampaignProgress progress() {
    CampaignProgress p;
    p.scenarios = scenarios_.load();
    p.failing_scenarios = failing_.load();
    {
      std::lock_guard lock(mutex_);
      p.signatures = signatures_.size();
    }
    p.elapsed_s = std::chrono::duration<double>(Clock::now() - start_).count();
    if (deadline_) p.remaining_s = std::max(0.0, std::chrono::duration<double>(*deadline_ - Clock::now()).count());
    if (shard_runs_ && p.scenarios > 0) {
      const double left = static_cast<double>(*shard_runs_ - std::min(*shard_runs_, p.scenarios));
      const double by_runs = left * p.elapsed_s / static_cast<double>(p.scenarios);
      p.remaining_s = p.remaining_s ? std::min(*p.remaining_s, by_runs) : by_runs;
    }
    return p;
  }

  static Clock::duration period(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  }

  // When the progress thread next reports, samples the timeline and writes a checkpoint.
  struct Ticks {
    explicit Ticks(const CampaignOptions& o)
        : next_report(Clock::now()), next_checkpoint(Clock::now() + period(o.checkpoint_period_s)), next_sample(Clock::now()) {}
    Clock::time_point next_report, next_checkpoint, next_sample;
    double sample_every_s = 1.0;
  };

  void tick(Ticks& t) {
    if (opt_.on_progress && Clock::now() >= t.next_report) {
      opt_.on_progress(progress());
      t.next_report += period(opt_.progress_period_s);
    }
    if (Clock::now() >= t.next_sample) {
      sample_timeline(t.sample_every_s);
      t.next_sample += period(t.sample_every_s);
    }
    if (opt_.on_checkpoint && Clock::now() >= t.next_checkpoint) {
      opt_.on_checkpoint(snapshot());
      t.next_checkpoint += period(opt_.checkpoint_period_s);
    }
  }

  // Keeps at most kMaxTimelineSamples: when full, every other sample goes and the period doubles.
  void sample_timeline(double& every_s) {
    timeline_.push_back(progress());
    if (timeline_.size() < kMaxTimelineSamples) return;
    std::vector<CampaignProgress> kept;
    for (std::size_t k = 0; k < timeline_.size(); k += 2) kept.push_back(timeline_[k]);
    timeline_ = std::move(kept);
    every_s *= 2.0;
  }

  // Everything but the margins (those are per worker until the end).
  CampaignResult snapshot() {
    CampaignResult r;
    r.scenarios = scenarios_.load();
    r.failing_scenarios = failing_.load();
    r.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    r.interrupted = externally_stopped();
    r.guided_runs = guided_runs_.load();
    r.guided_failing_scenarios = guided_failing_.load();
    {
      std::lock_guard lock(mutex_);
      r.signatures = signatures_;
      r.first_failure_run = first_failure_run_;
      r.first_failure_s = first_failure_s_;
      r.first_new_failure_run = first_new_failure_run_;
      r.first_new_failure_s = first_new_failure_s_;
    }
    for (const auto& [signature, rec] : r.signatures) {
      r.property_failures += rec.count;
      r.by_property[signature.property] += rec.count;
      r.by_rule[signature.rule] += rec.count;
      r.by_party[signature.party] += rec.count;
      if (!rec.case_path.empty()) r.new_cases.push_back(rec.case_path);
    }
    std::sort(r.new_cases.begin(), r.new_cases.end());
    return r;
  }

  CampaignResult collect(const std::vector<WorkerStats>& stats) {
    CampaignResult r = snapshot();
    r.timeline = timeline_;
    for (const WorkerStats& s : stats)
      for (const auto& [rule, m] : s.margins) r.margins[rule].merge(m);
    return r;
  }

  const CampaignOptions& opt_;
  const CheckFactory& make_check_;
  const Clock::time_point start_;
  std::optional<Clock::time_point> deadline_;
  std::optional<std::uint64_t> shard_runs_;
  std::set<Signature> known_;
  std::atomic<std::uint64_t> next_{0}, scenarios_{0}, failing_{0}, guided_runs_{0}, guided_failing_{0}, new_failing_{0};
  std::unique_ptr<PoolHistory> history_;  // guided search only
  std::atomic<bool> abort_{false};
  std::mutex mutex_;  // guards signatures_, first_failure_* and corpus writes
  std::map<Signature, SignatureRecord> signatures_;
  std::optional<std::uint64_t> first_failure_run_;
  std::optional<double> first_failure_s_;
  std::optional<std::uint64_t> first_new_failure_run_;
  std::optional<double> first_new_failure_s_;
  std::vector<CampaignProgress> timeline_;  // the progress thread's only
};

void validate(const CampaignOptions& o) {
  if (o.jobs < 1 || o.jobs > 1024) throw std::invalid_argument("--jobs must be in [1, 1024]");
  if (o.shard_count < 1 || o.shard_index < 0 || o.shard_index >= o.shard_count)
    throw std::invalid_argument("--shard K/N needs 0 <= K < N");
  if (!o.runs && !o.time_s) throw std::invalid_argument("a campaign needs --runs or --time");
  // A negative --runs wraps around to a huge count: caught here as an absurd value.
  if (o.runs && (*o.runs < 1 || *o.runs > 1'000'000'000'000ULL)) throw std::invalid_argument("--runs must be in [1, 1e12]");
  if (o.shrink.max_attempts < 0 || !(o.shrink.max_seconds >= 0.0 && o.shrink.max_seconds <= 1e6))
    throw std::invalid_argument("--shrink-attempts must be >= 0 and --shrink-time in [0, 1e6] s");
  if (o.time_s && !(*o.time_s > 0.0 && *o.time_s <= 1e7)) throw std::invalid_argument("--time must be in (0, 1e7] s");
  if (o.determinism_every < 0) throw std::invalid_argument("determinism period must be >= 0");
  if (!(o.guided.guided_share >= 0.0 && o.guided.guided_share <= 1.0) || o.guided.pool_size < 1 || o.guided.batch_runs < 1 ||
      o.guided.lag_batches < 1)
    throw std::invalid_argument("guided search needs a share in [0, 1], a pool and batches of at least one");
  if (o.gen.max_vehicles < 0 || o.gen.max_vehicles > static_cast<int>(kMaxVehicles))
    throw std::invalid_argument("--max-vehicles must be in [0, " + std::to_string(kMaxVehicles) + "]");
}

int bin_of(double margin) {
  int b = 0;
  while (b < static_cast<int>(kMarginBinEdges.size()) && margin >= kMarginBinEdges[static_cast<std::size_t>(b)]) ++b;
  return b;
}

}  // namespace

void MarginStats::add(double margin, bool holds) {
  ++scenarios;
  if (!holds) ++violated;
  if (std::isinf(margin) && margin > 0.0) return;  // never applied: not exercised
  min = exercised == 0 ? margin : std::min(min, margin);
  ++exercised;
  sum_micro += static_cast<std::int64_t>(std::llround(std::clamp(margin, -1e9, 1e9) * 1e6));
  ++bins[static_cast<std::size_t>(bin_of(margin))];
}

void MarginStats::merge(const MarginStats& other) {
  if (other.scenarios == 0) return;
  if (unit.empty()) unit = other.unit;
  if (other.exercised > 0) min = exercised == 0 ? other.min : std::min(min, other.min);
  scenarios += other.scenarios;
  exercised += other.exercised;
  violated += other.violated;
  sum_micro += other.sum_micro;
  for (std::size_t b = 0; b < bins.size(); ++b) bins[b] += other.bins[b];
}

std::uint64_t runs_in_shard(std::uint64_t runs, int shard_index, int shard_count) {
  const auto k = static_cast<std::uint64_t>(shard_index);
  const auto n = static_cast<std::uint64_t>(shard_count);
  return runs > k ? (runs - k + n - 1) / n : 0;
}

CampaignResult run_campaign(const CampaignOptions& options, const CheckFactory& make_check) {
  validate(options);
  return Campaign(options, make_check).run();
}

}  // namespace mg::fuzz
