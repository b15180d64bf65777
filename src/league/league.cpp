#include "league/league.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <set>
#include <stdexcept>

#include "fuzz/worker_pool.h"

namespace mg::league {
namespace {

using Clock = std::chrono::steady_clock;

Clock::duration seconds(double s) { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s)); }

void validate(const LeagueOptions& o) {
  if (o.planners.empty()) throw std::invalid_argument("--planners: name at least one planner");
  const std::set<std::string> distinct(o.planners.begin(), o.planners.end());
  if (distinct.size() != o.planners.size()) throw std::invalid_argument("--planners: a planner is named twice");
  if (o.jobs < 1 || o.jobs > 1024) throw std::invalid_argument("--jobs must be in [1, 1024]");
  if (!o.runs && !o.time_s) throw std::invalid_argument("a league needs --runs or --time");
  if (o.runs && (*o.runs < 1 || *o.runs > 1'000'000'000ULL)) throw std::invalid_argument("--runs must be in [1, 1e9]");
  if (o.time_s && !(*o.time_s > 0.0 && *o.time_s <= 1e7)) throw std::invalid_argument("--time must be in (0, 1e7] s");
  if (o.gen.max_vehicles < 0 || o.gen.max_vehicles > static_cast<int>(kMaxVehicles))
    throw std::invalid_argument("--max-vehicles must be in [0, " + std::to_string(kMaxVehicles) + "]");
}

PlannerStanding standing_of(const std::string& planner) {
  PlannerStanding s;
  s.planner = planner;
  return s;
}

class League {
 public:
  League(const LeagueOptions& o, const LeagueCheckFactory& make_check) : opt_(o), make_check_(make_check), start_(Clock::now()) {
    if (opt_.time_s) deadline_ = start_ + seconds(*opt_.time_s);
  }

  LeagueResult run() {
    std::vector<std::vector<PlannerStanding>> per_worker(static_cast<std::size_t>(opt_.jobs));
    auto next_report = Clock::now();
    fuzz::run_workers(
        opt_.jobs, [this, &per_worker](int w) { work(per_worker[static_cast<std::size_t>(w)]); },
        [this, &next_report] {
          if (!opt_.on_progress || Clock::now() < next_report) return;
          opt_.on_progress(progress());
          next_report += seconds(opt_.progress_period_s);
        },
        [this] { abort_ = true; });
    if (opt_.on_progress) opt_.on_progress(progress());
    LeagueResult r;
    r.scenarios = scenarios_.load();
    r.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    r.interrupted = opt_.stop != nullptr && opt_.stop->load();
    for (const std::string& p : opt_.planners) r.standings.push_back(standing_of(p));
    for (const auto& worker : per_worker)
      for (std::size_t k = 0; k < worker.size(); ++k) r.standings[k].merge(worker[k]);
    for (PlannerStanding& s : r.standings) s.finish();
    return r;
  }

 private:
  bool should_stop() const {
    return abort_.load() || (opt_.stop != nullptr && opt_.stop->load()) || (deadline_ && Clock::now() >= *deadline_);
  }

  void work(std::vector<PlannerStanding>& standings) {
    std::vector<fuzz::CheckFn> checks;
    for (const std::string& p : opt_.planners) {
      checks.push_back(make_check_(p));
      standings.push_back(standing_of(p));
    }
    while (!should_stop()) {
      const std::uint64_t i = next_.fetch_add(1);
      if (opt_.runs && i >= *opt_.runs) break;
      const Scenario scenario = fuzz::generate_scenario(fuzz::run_seed(opt_.seed, i), opt_.gen).value();
      for (std::size_t k = 0; k < checks.size(); ++k) run_one(i, scenario, opt_.planners[k], checks[k], standings[k]);
      ++scenarios_;
    }
  }

  void run_one(std::uint64_t i, const Scenario& scenario, const std::string& planner, const fuzz::CheckFn& check,
               PlannerStanding& standing) {
    const fuzz::RunOutcome outcome = fuzz::run_properties(scenario, check, planner, /*check_determinism=*/false);
    std::optional<RunMetrics> metrics;
    if (outcome.result) metrics = run_metrics(outcome.result->trace, outcome.result->rule_params);
    standing.add(i, outcome, metrics);
    if (outcome.failures.empty()) return;
    ++failing_;
    const std::lock_guard lock(mutex_);
    for (const fuzz::PropertyFailure& f : outcome.failures) signatures_.insert(fuzz::signature_of(outcome.planner, f));
  }

  fuzz::CampaignProgress progress() {
    fuzz::CampaignProgress p;
    p.scenarios = scenarios_.load();
    p.failing_scenarios = failing_.load();
    {
      const std::lock_guard lock(mutex_);
      p.signatures = signatures_.size();
    }
    p.elapsed_s = std::chrono::duration<double>(Clock::now() - start_).count();
    if (deadline_) p.remaining_s = std::max(0.0, std::chrono::duration<double>(*deadline_ - Clock::now()).count());
    if (opt_.runs && p.scenarios > 0) {
      const double by_runs = static_cast<double>(*opt_.runs - std::min(*opt_.runs, p.scenarios)) * p.elapsed_s /
                             static_cast<double>(p.scenarios);
      p.remaining_s = p.remaining_s ? std::min(*p.remaining_s, by_runs) : by_runs;
    }
    return p;
  }

  const LeagueOptions& opt_;
  const LeagueCheckFactory& make_check_;
  const Clock::time_point start_;
  std::optional<Clock::time_point> deadline_;
  std::atomic<std::uint64_t> next_{0}, scenarios_{0}, failing_{0};  // failing_: failing (planner, scenario) runs
  std::atomic<bool> abort_{false};
  std::mutex mutex_;  // guards signatures_ (for the progress line only)
  std::set<fuzz::Signature> signatures_;
};

// Is (margin, run) a worse example than the kept one: a lower margin, or the same from an earlier run.
bool worse(double margin, std::uint64_t run, const WorstRun& kept) {
  return margin < kept.margin || (margin == kept.margin && run < kept.run);
}

}  // namespace

void PlannerStanding::add(std::uint64_t run, const fuzz::RunOutcome& outcome, const std::optional<RunMetrics>& metrics) {
  ++scenarios;
  if (!outcome.failures.empty()) ++failing;
  std::set<std::string> rules, parties;
  std::set<fuzz::Signature> signatures;  // a signature counts once per run, however often it failed
  for (const fuzz::PropertyFailure& f : outcome.failures) {
    rules.insert(f.rule);
    parties.insert(fuzz::party_class(f.liable_id));
    const fuzz::Signature sig = fuzz::signature_of(outcome.planner, f);
    auto [it, inserted] = worst.try_emplace(sig, WorstRun{sig, 0, run, f.margin, f});
    WorstRun& w = it->second;
    if (!inserted && worse(f.margin, run, w)) {
      w.run = run;
      w.margin = f.margin;
      w.failure = f;
    }
    if (signatures.insert(sig).second) ++w.scenarios;
  }
  for (const std::string& r : rules) ++by_rule[r];
  for (const std::string& p : parties) ++by_party[p];
  if (!metrics) return;
  ++judged;
  peak_lat_accels_mps2.push_back(metrics->peak_lat_accel_mps2);
  halted_us += std::llround(metrics->halted_s * 1e6);
  if (!metrics->merged) return;
  ++merged;
  merge_times_s.push_back(*metrics->merge_time_s);
  path_lengths_m.push_back(*metrics->path_length_m);
}

void PlannerStanding::merge(const PlannerStanding& o) {
  scenarios += o.scenarios;
  failing += o.failing;
  for (const auto& [rule, n] : o.by_rule) by_rule[rule] += n;
  for (const auto& [party, n] : o.by_party) by_party[party] += n;
  merged += o.merged;
  judged += o.judged;
  halted_us += o.halted_us;
  merge_times_s.insert(merge_times_s.end(), o.merge_times_s.begin(), o.merge_times_s.end());
  path_lengths_m.insert(path_lengths_m.end(), o.path_lengths_m.begin(), o.path_lengths_m.end());
  peak_lat_accels_mps2.insert(peak_lat_accels_mps2.end(), o.peak_lat_accels_mps2.begin(), o.peak_lat_accels_mps2.end());
  for (const auto& [sig, w] : o.worst) {
    auto [it, inserted] = worst.try_emplace(sig, w);
    if (inserted) continue;
    WorstRun& kept = it->second;
    const std::uint64_t total = kept.scenarios + w.scenarios;
    if (worse(w.margin, w.run, kept)) kept = w;
    kept.scenarios = total;
  }
}

void PlannerStanding::finish() {
  std::sort(merge_times_s.begin(), merge_times_s.end());
  std::sort(path_lengths_m.begin(), path_lengths_m.end());
  std::sort(peak_lat_accels_mps2.begin(), peak_lat_accels_mps2.end());
}

double PlannerStanding::failing_share() const {
  return scenarios > 0 ? static_cast<double>(failing) / static_cast<double>(scenarios) : 0.0;
}

double PlannerStanding::merge_rate() const {
  return scenarios > 0 ? static_cast<double>(merged) / static_cast<double>(scenarios) : 0.0;
}

std::optional<double> PlannerStanding::mean_halted_s() const {
  if (judged == 0) return std::nullopt;
  return static_cast<double>(halted_us) * 1e-6 / static_cast<double>(judged);
}

LeagueResult run_league(const LeagueOptions& options, const LeagueCheckFactory& make_check) {
  validate(options);
  return League(options, make_check).run();
}

}  // namespace mg::league
