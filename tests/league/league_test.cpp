// The league engine (src/league/league.cpp): every planner on exactly the same scenarios (with
// --runs, --time and a stop), results independent of --jobs, the standings' sums and worst runs,
// and the options' validation.
#include "league/league.h"

#include <atomic>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "check/checked_run.h"
#include "core/scenario.h"
#include "league/league_report.h"
#include "tests/fuzz/fake_check.h"

namespace mg::league {
namespace {

// Records which scenarios (by their JSON) each planner was given; judges with the fake check.
struct Recorder {
  std::mutex mutex;
  std::map<std::string, std::multiset<std::string>> seen;

  LeagueCheckFactory factory() {
    return [this](const std::string& planner) {
      return fuzz::CheckFn([this, planner](const Scenario& s) {
        {
          const std::lock_guard lock(mutex);
          seen[planner].insert(scenario_to_json(s).dump());
        }
        CheckResult r = test::fake_check(s);
        r.planner = planner;
        return r;
      });
    };
  }
};

// Checks made so far by the stopping factory below (all workers, all planners).
std::atomic<int>* check_calls() {
  static std::atomic<int> calls{0};
  return &calls;
}

LeagueOptions options(std::vector<std::string> planners, int jobs) {
  LeagueOptions o;
  o.planners = std::move(planners);
  o.seed = 7;
  o.runs = 40;
  o.jobs = jobs;
  o.gen.max_vehicles = 3;
  return o;
}

TEST(League, EveryPlannerRunsExactlyTheSameScenarios) {
  Recorder rec;
  const LeagueResult r = run_league(options({"a", "b", "c"}, 3), rec.factory());
  EXPECT_EQ(r.scenarios, 40u);
  ASSERT_EQ(rec.seen.size(), 3u);
  EXPECT_EQ(rec.seen["a"].size(), 40u);
  EXPECT_EQ(rec.seen["a"], rec.seen["b"]);
  EXPECT_EQ(rec.seen["a"], rec.seen["c"]);
  ASSERT_EQ(r.standings.size(), 3u);
  EXPECT_EQ(r.standings[0].planner, "a");
  EXPECT_EQ(r.standings[2].planner, "c");
  // The same check for all three: the same failures.
  EXPECT_GT(r.standings[0].failing, 0u);
  EXPECT_EQ(r.standings[0].failing, r.standings[1].failing);
  EXPECT_EQ(r.standings[0].by_rule, (std::map<std::string, std::uint64_t>{{"fake_proximity", r.standings[0].failing}}));
  EXPECT_EQ(r.standings[0].by_party, (std::map<std::string, std::uint64_t>{{"ego", r.standings[0].failing}}));
}

TEST(League, WithATimeBudgetOrAStopEveryPlannerRunsTheSamePrefixOfScenarios) {
  for (const bool stop_midway : {false, true}) {
    Recorder rec;
    LeagueOptions o = options({"a", "b"}, 2);
    o.runs.reset();
    o.time_s = stop_midway ? 600.0 : 0.3;
    std::atomic<bool> stop{false};
    o.stop = &stop;
    const LeagueCheckFactory stopping = [&](const std::string& planner) {
      const fuzz::CheckFn check = rec.factory()(planner);
      return fuzz::CheckFn([&stop, stop_midway, check](const Scenario& s) {
        if (stop_midway && *check_calls() >= 10) stop = true;  // as a signal would, with runs in flight
        ++*check_calls();
        return check(s);
      });
    };
    *check_calls() = 0;
    const LeagueResult r = run_league(o, stopping);
    EXPECT_EQ(r.interrupted, stop_midway);
    EXPECT_GT(r.scenarios, 0u);
    EXPECT_EQ(rec.seen["a"], rec.seen["b"]);
    EXPECT_EQ(rec.seen["a"].size(), r.scenarios);
    EXPECT_EQ(r.standings[0].scenarios, r.scenarios);
    // A prefix: the scenarios of runs 0 .. n-1.
    std::multiset<std::string> prefix;
    for (std::uint64_t i = 0; i < r.scenarios; ++i)
      prefix.insert(scenario_to_json(fuzz::generate_scenario(fuzz::run_seed(o.seed, i), o.gen).value()).dump());
    EXPECT_EQ(rec.seen["a"], prefix);
  }
}

nlohmann::json without_timing(nlohmann::json j) {
  for (const char* key : {"seconds", "jobs", "date"}) j.erase(key);
  return j;
}

TEST(League, TheResultDoesNotDependOnTheJobs) {
  const LeagueCheckFactory real = [](const std::string& planner) {
    return fuzz::CheckFn([planner](const Scenario& s) { return check_scenario(s, planner); });
  };
  LeagueOptions one = options({"rcpp", "mobil", "frenet"}, 1), three = options({"rcpp", "mobil", "frenet"}, 3);
  one.runs = three.runs = 24;
  const nlohmann::json a = without_timing(league_json(one, run_league(one, real), {}));
  const nlohmann::json b = without_timing(league_json(three, run_league(three, real), {}));
  EXPECT_EQ(a, b);
  ASSERT_EQ(a.at("planners").size(), 3u);
  EXPECT_EQ(a.at("planners")[1].at("planner"), "mobil");
  EXPECT_EQ(a.at("planners")[1].at("scenarios"), 24);
}

fuzz::RunOutcome failing(const std::string& planner, double margin) {
  fuzz::RunOutcome o;
  o.planner = planner;
  o.failures.push_back({fuzz::property::kEgoNeverLiable, "rss_longitudinal", Party::ego(), 1.0, margin, ""});
  o.failures.push_back({fuzz::property::kEgoNeverLiable, "rss_longitudinal", Party::ego(), 2.0, margin - 1.0, ""});
  return o;
}

TEST(League, AStandingCountsARunOnceAndKeepsTheWorstRunOfEachSignature) {
  PlannerStanding s;
  s.planner = "p";
  RunMetrics merged;
  merged.merged = true;
  merged.merge_time_s = 5.0;
  merged.path_length_m = 80.0;
  merged.halted_s = 0.5;
  s.add(3, failing("p", -2.0), merged);
  s.add(1, failing("p", -2.0), std::nullopt);  // the same margin from an earlier run: it is the worst
  s.add(2, fuzz::RunOutcome{"p", std::nullopt, {}}, RunMetrics{});
  EXPECT_EQ(s.scenarios, 3u);
  EXPECT_EQ(s.failing, 2u);
  EXPECT_EQ(s.by_rule.at("rss_longitudinal"), 2u);  // once per run, not per failure
  ASSERT_EQ(s.worst.size(), 1u);
  const WorstRun& w = s.worst.begin()->second;
  EXPECT_EQ(w.scenarios, 2u);
  EXPECT_EQ(w.run, 1u);
  EXPECT_DOUBLE_EQ(w.margin, -3.0);
  EXPECT_EQ(s.judged, 2u);
  EXPECT_EQ(s.merged, 1u);
  EXPECT_DOUBLE_EQ(*s.mean_halted_s(), 0.25);
  // Merging is a sum: in either order, the same standing.
  PlannerStanding x, y;
  x.add(5, failing("p", -9.0), std::nullopt);
  y.add(4, failing("p", -9.0), merged);
  PlannerStanding xy = x, yx = y;
  xy.merge(y);
  yx.merge(x);
  xy.finish();
  yx.finish();
  EXPECT_EQ(xy.worst.begin()->second.run, 4u);
  EXPECT_EQ(yx.worst.begin()->second.run, 4u);
  EXPECT_EQ(xy.worst.begin()->second.scenarios, 2u);
  EXPECT_EQ(xy.merge_times_s, yx.merge_times_s);
}

TEST(League, RefusesBadOptions) {
  Recorder rec;
  EXPECT_THROW(run_league(options({}, 1), rec.factory()), std::invalid_argument);
  EXPECT_THROW(run_league(options({"a", "a"}, 1), rec.factory()), std::invalid_argument);
  EXPECT_THROW(run_league(options({"a"}, 0), rec.factory()), std::invalid_argument);
  LeagueOptions neither = options({"a"}, 1);
  neither.runs.reset();
  EXPECT_THROW(run_league(neither, rec.factory()), std::invalid_argument);
}

}  // namespace
}  // namespace mg::league
