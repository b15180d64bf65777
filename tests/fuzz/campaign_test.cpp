#include "fuzz/campaign.h"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "fake_check.h"
#include "fuzz/campaign_report.h"
#include "fuzz/corpus_case.h"
#include "fuzz/replay.h"
#include "tests/support/scratch_files.h"

namespace mg::fuzz {
namespace {

namespace fs = std::filesystem;

CheckFactory fake_factory() {
  return [] { return CheckFn(test::fake_check); };
}

CampaignOptions options(std::uint64_t runs, int jobs, const fs::path& corpus) {
  CampaignOptions o;
  o.seed = 11;
  o.runs = runs;
  o.jobs = jobs;
  o.planner = "fake";
  o.corpus_dir = corpus.string();
  o.gen.max_vehicles = 3;
  return o;
}

nlohmann::json case_without_date(const std::string& path) {
  auto j = case_to_json(load_case(path));
  j["provenance"].erase("date");
  return j;
}

TEST(Campaign, ResultsDoNotDependOnTheNumberOfJobs) {
  const auto a = mg::test::unused_path("campaign_test_jobs1"), b = mg::test::unused_path("campaign_test_jobs3");
  const CampaignResult one = run_campaign(options(200, 1, a), fake_factory());
  const CampaignResult three = run_campaign(options(200, 3, b), fake_factory());
  EXPECT_EQ(one.scenarios, 200u);
  EXPECT_EQ(three.scenarios, 200u);
  EXPECT_GT(one.failing_scenarios, 0u);
  EXPECT_EQ(one.failing_scenarios, three.failing_scenarios);
  EXPECT_EQ(one.by_property, three.by_property);
  EXPECT_EQ(one.by_rule, three.by_rule);
  ASSERT_EQ(one.signatures.size(), three.signatures.size());
  for (const auto& [sig, rec] : one.signatures) {
    EXPECT_EQ(rec.count, three.signatures.at(sig).count);
    EXPECT_EQ(rec.first_run, three.signatures.at(sig).first_run);
  }
  const MarginStats& m1 = one.margins.at("fake_proximity");
  const MarginStats& m3 = three.margins.at("fake_proximity");
  EXPECT_EQ(m1.bins, m3.bins);
  EXPECT_EQ(m1.sum_micro, m3.sum_micro);
  ASSERT_EQ(one.new_cases.size(), 1u);
  ASSERT_EQ(three.new_cases.size(), 1u);
  EXPECT_EQ(case_without_date(one.new_cases[0]), case_without_date(three.new_cases[0]));
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(Campaign, ShardsAreDisjointSlicesThatMakeUpTheCampaign) {
  std::mutex mutex;
  std::multiset<std::string> seen;
  const CheckFactory recording = [&] {
    return CheckFn([&](const Scenario& s) {
      std::lock_guard lock(mutex);
      seen.insert(scenario_to_json(s).dump());
      return test::fake_check(s);
    });
  };
  auto o = options(90, 2, {});
  o.corpus_dir.clear();
  o.determinism_every = 0;
  run_campaign(o, recording);
  const std::multiset<std::string> whole = seen;
  seen.clear();
  std::uint64_t total = 0;
  for (int k = 0; k < 4; ++k) {
    o.shard_index = k;
    o.shard_count = 4;
    const auto r = run_campaign(o, recording);
    EXPECT_EQ(r.scenarios, runs_in_shard(90, k, 4));
    total += r.scenarios;
  }
  EXPECT_EQ(total, 90u);
  EXPECT_EQ(seen, whole);  // same scenarios, each exactly once
}

// Records every checked scenario (as its JSON text) besides running the fake check.
struct Recorder {
  std::mutex mutex;
  std::multiset<std::string> seen;
  CheckFactory factory() {
    return [this] {
      return CheckFn([this](const Scenario& s) {
        std::lock_guard lock(mutex);
        seen.insert(scenario_to_json(s).dump());
        return test::fake_check(s);
      });
    };
  }
};

CampaignOptions guided(CampaignOptions o) {
  o.search = SearchMode::kGuided;
  o.guided.batch_runs = 16;  // guided runs from run 32 on
  o.determinism_every = 0;
  return o;
}

TEST(Campaign, GuidedResultsAndScenariosDoNotDependOnTheNumberOfJobs) {
  const auto a = mg::test::unused_path("campaign_test_guided1"), b = mg::test::unused_path("campaign_test_guided3");
  Recorder one_seen, three_seen;
  const CampaignResult one = run_campaign(guided(options(300, 1, a)), one_seen.factory());
  const CampaignResult three = run_campaign(guided(options(300, 3, b)), three_seen.factory());
  EXPECT_EQ(one.scenarios, 300u);
  EXPECT_GT(one.guided_runs, 100u);
  EXPECT_EQ(one.guided_runs, three.guided_runs);
  EXPECT_EQ(one.guided_failing_scenarios, three.guided_failing_scenarios);
  EXPECT_EQ(one.failing_scenarios, three.failing_scenarios);
  EXPECT_EQ(one.first_failure_run, three.first_failure_run);
  EXPECT_EQ(one.margins.at("fake_proximity").sum_micro, three.margins.at("fake_proximity").sum_micro);
  ASSERT_EQ(one.new_cases.size(), 1u);
  ASSERT_EQ(three.new_cases.size(), 1u);
  EXPECT_EQ(case_without_date(one.new_cases[0]), case_without_date(three.new_cases[0]));
  fs::remove_all(a);
  fs::remove_all(b);
  // Without a corpus nothing is shrunk (shrink candidates depend on which worker found a
  // failure first): the campaign's own runs are then the same scenarios.
  one_seen.seen.clear();
  three_seen.seen.clear();
  run_campaign(guided(options(300, 1, {})), one_seen.factory());
  run_campaign(guided(options(300, 3, {})), three_seen.factory());
  EXPECT_EQ(one_seen.seen.size(), 300u);
  EXPECT_EQ(one_seen.seen, three_seen.seen);
}

TEST(Campaign, GuidedShardsPartitionTheRunsAndKeepTheRandomCampaignsUniformRuns) {
  auto o = guided(options(200, 2, {}));
  o.corpus_dir.clear();
  std::uint64_t total = 0;
  std::multiset<std::string> uniform_expected;
  Recorder shards;
  for (int k = 0; k < 2; ++k) {
    o.shard_index = k;
    o.shard_count = 2;
    const auto r = run_campaign(o, shards.factory());
    EXPECT_EQ(r.scenarios, runs_in_shard(200, k, 2));
    EXPECT_GT(r.guided_runs, 0u);
    total += r.scenarios;
    std::uint64_t uniform = 0;
    for (std::uint64_t j = 0; j < runs_in_shard(200, k, 2); ++j) {
      const std::uint64_t i = static_cast<std::uint64_t>(k) + 2 * j;
      if (is_guided_run(o.seed, i, j, o.guided)) continue;
      uniform_expected.insert(scenario_to_json(generate_scenario(run_seed(o.seed, i), o.gen).value()).dump());
      ++uniform;
    }
    EXPECT_EQ(r.scenarios - r.guided_runs, uniform);
  }
  EXPECT_EQ(total, 200u);
  for (const std::string& s : uniform_expected) EXPECT_GE(shards.seen.count(s), 1u);
}

TEST(Campaign, StopOnFailureStartsNoRunAfterTheFirstFailingOne) {
  auto o = options(100000, 1, {});
  o.corpus_dir.clear();
  o.stop_on_failure = true;
  const auto r = run_campaign(o, fake_factory());
  ASSERT_TRUE(r.first_failure_run.has_value());
  ASSERT_TRUE(r.first_failure_s.has_value());
  EXPECT_EQ(r.failing_scenarios, 1u);
  EXPECT_EQ(r.scenarios, *r.first_failure_run + 1);  // one job: the runs go in order
}

// fake_check's failure and a second one: rule "fake_fast" fails (ego liable) when the ego starts
// faster than 30 m/s.
CheckResult two_failures_check(const Scenario& s) {
  CheckResult r = test::fake_check(s);
  RuleResult fast;
  fast.rule_id = "fake_fast";
  fast.unit = "m/s";
  fast.min_margin = 30.0 - s.ego.speed_mps;
  fast.holds = fast.min_margin >= 0.0;
  if (!fast.holds) {
    fast.liable_id = Party::ego();
    fast.first_violation_time_s = 0.0;
  }
  r.holds = r.holds && fast.holds;
  r.rules.push_back(fast);
  return r;
}

TEST(Campaign, StopOnNewFailureRunsPastTheSignaturesOfTheCorpus) {
  const auto corpus = mg::test::unused_path("campaign_test_stop_on_new");
  run_campaign(options(200, 1, corpus), fake_factory());  // the corpus now holds fake_proximity's case
  auto o = options(100000, 1, corpus);
  o.stop_on_new_failure = true;
  const auto r = run_campaign(o, [] { return CheckFn(two_failures_check); });
  ASSERT_TRUE(r.first_failure_run.has_value());
  ASSERT_TRUE(r.first_new_failure_run.has_value());
  ASSERT_TRUE(r.first_new_failure_s.has_value());
  EXPECT_LT(*r.first_failure_run, *r.first_new_failure_run);  // a known failure did not stop it
  EXPECT_EQ(r.scenarios, *r.first_new_failure_run + 1);        // one job: the runs go in order
  std::uint64_t fast_first_run = 0;
  for (const auto& [sig, rec] : r.signatures) {
    if (sig.rule == "fake_fast") fast_first_run = rec.first_run;
    EXPECT_EQ(rec.known_before, sig.rule == "fake_proximity") << sig.rule;
  }
  EXPECT_EQ(fast_first_run, *r.first_new_failure_run);
}

// A planted failure in a small window of two scalars, with a margin that measures the distance
// to it (in window half-widths): ego speed 17.3 +- 0.3 m/s and ego X 30 +- 3 m. About one uniform
// scenario in 1,500 falls inside; hill climbing on the margin gets there sooner.
CheckResult narrow_window_check(const Scenario& s) {
  CheckResult r = test::fake_check(s);
  RuleResult& rule = r.rules.front();
  rule.rule_id = "fake_window";
  rule.min_margin = std::max(std::abs(s.ego.speed_mps - 17.3) / 0.3, std::abs(s.ego.x_m - 30.0) / 3.0) - 1.0;
  rule.holds = rule.min_margin >= 0.0;
  rule.liable_id = rule.holds ? Party::nobody() : Party::ego();
  r.holds = rule.holds;
  return r;
}

TEST(Campaign, GuidedSearchReachesANarrowFailureInFewerRunsThanRandom) {
  std::vector<std::uint64_t> random_first, guided_first;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    auto o = options(6000, 2, {});
    o.corpus_dir.clear();
    o.seed = seed;
    o.determinism_every = 0;
    const CheckFactory factory = [] { return CheckFn(narrow_window_check); };
    const auto random = run_campaign(o, factory);
    o.search = SearchMode::kGuided;
    const auto guided = run_campaign(o, factory);
    random_first.push_back(random.first_failure_run.value_or(6000));
    guided_first.push_back(guided.first_failure_run.value_or(6000));
  }
  std::sort(random_first.begin(), random_first.end());
  std::sort(guided_first.begin(), guided_first.end());
  EXPECT_LT(guided_first[2] * 2, random_first[2]) << "medians: guided " << guided_first[2] << ", random " << random_first[2];
}

TEST(Campaign, AResumedCampaignDoesNotReAddKnownSignatures) {
  const auto dir = mg::test::unused_path("campaign_test_resume");
  const auto first = run_campaign(options(100, 2, dir), fake_factory());
  ASSERT_EQ(first.new_cases.size(), 1u);
  auto o = options(100, 2, dir);
  o.seed = 12;
  const auto second = run_campaign(o, fake_factory());
  EXPECT_GT(second.failing_scenarios, 0u);
  EXPECT_TRUE(second.new_cases.empty());
  for (const auto& [sig, rec] : second.signatures) EXPECT_TRUE(rec.known_before) << sig.key();
  EXPECT_EQ(case_files(dir.string()).size(), 1u);
  fs::remove_all(dir);
}

TEST(Campaign, ACaseThatNowHoldsDoesNotHideANewFailureOfItsSignature) {
  const auto dir = mg::test::unused_path("campaign_test_fixed");
  const auto first = run_campaign(options(100, 2, dir), fake_factory());
  ASSERT_EQ(first.new_cases.size(), 1u);
  CorpusCase fixed = load_case(first.new_cases[0]);
  fixed.verdict = CaseVerdict{};  // as after `replay --update` once the bug is fixed: it holds
  write_case(fixed, first.new_cases[0]);
  const auto second = run_campaign(options(100, 2, dir), fake_factory());
  ASSERT_EQ(second.new_cases.size(), 1u);
  EXPECT_EQ(fs::path(second.new_cases[0]).filename(), fixed.signature.file_stem() + "-2.json");
  EXPECT_TRUE(load_case(first.new_cases[0]).verdict.holds);  // the regression case is left alone
  fs::remove_all(dir);
}

TEST(Campaign, EveryNewCaseIsMinimalAndReplays) {
  const auto dir = mg::test::unused_path("campaign_test_replay");
  const auto r = run_campaign(options(60, 2, dir), fake_factory());
  ASSERT_FALSE(r.new_cases.empty());
  for (const std::string& path : r.new_cases) {
    const CorpusCase c = load_case(path);
    EXPECT_EQ(c.scenario.vehicles.size(), 1u);
    EXPECT_TRUE(c.provenance.shrink_minimal);
    EXPECT_TRUE(replay_case(c, test::fake_check).reproduces) << path;
    EXPECT_EQ(fs::path(path).filename(), c.signature.file_stem() + ".json");  // a fresh corpus
  }
  fs::remove_all(dir);
}

TEST(Campaign, AStopRequestEndsTheCampaignAndKeepsWhatItFound) {
  const auto dir = mg::test::unused_path("campaign_test_stop");
  std::atomic<bool> stop{false};
  std::atomic<int> calls{0};
  const CheckFactory stopping = [&] {
    return CheckFn([&](const Scenario& s) {
      if (++calls == 300) stop = true;  // like SIGINT in the middle of the campaign
      return test::fake_check(s);
    });
  };
  auto o = options(1000000000, 2, dir);
  o.stop = &stop;
  const auto r = run_campaign(o, stopping);
  EXPECT_TRUE(r.interrupted);
  EXPECT_LT(r.scenarios, 400u);
  ASSERT_EQ(r.new_cases.size(), 1u);
  EXPECT_NO_THROW(load_case(r.new_cases[0]));
  fs::remove_all(dir);
}

TEST(Campaign, AThrowingCheckBecomesACaseThatReplays) {
  const auto dir = mg::test::unused_path("campaign_test_throw");
  const CheckFn throwing = [](const Scenario& s) -> CheckResult {
    if (s.vehicles.size() >= 2) throw std::runtime_error("two vehicles are too many");
    return test::fake_check(s);
  };
  auto o = options(50, 1, dir);
  const auto r = run_campaign(o, [&] { return throwing; });
  const Signature crash{"fake", property::kCheckCompletes, kRuleException, "none"};
  ASSERT_TRUE(r.signatures.count(crash));
  const CorpusCase c = load_case(r.signatures.at(crash).case_path);
  EXPECT_EQ(c.scenario.vehicles.size(), 2u);
  EXPECT_EQ(c.failure.detail, "two vehicles are too many");
  EXPECT_TRUE(replay_case(c, throwing).reproduces);
  fs::remove_all(dir);
}

TEST(Campaign, ATimeBudgetEndsTheCampaign) {
  auto o = options(0, 2, {});
  o.runs.reset();
  o.time_s = 0.5;
  o.corpus_dir.clear();
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_campaign(o, fake_factory());
  // A generous bound (sanitizers, a loaded machine): it catches a campaign that ignores its budget.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
  EXPECT_GT(r.scenarios, 0u);
  EXPECT_TRUE(r.new_cases.empty());  // no corpus: failures are counted only
}

TEST(Campaign, ACorruptCorpusIsRefusedBeforeAnythingRuns) {
  const auto dir = mg::test::unused_path("campaign_test_corrupt");
  fs::create_directories(dir);
  { std::ofstream(dir / "bad.json") << "{\"format_version\": 99}"; }
  std::atomic<int> calls{0};
  const CheckFactory counting = [&] { return CheckFn([&](const Scenario& s) { ++calls; return test::fake_check(s); }); };
  EXPECT_THROW(run_campaign(options(10, 1, dir), counting), InputError);
  EXPECT_EQ(calls.load(), 0);
  fs::remove_all(dir);
}

TEST(Campaign, CheckpointsReportTheResultSoFar) {
  // The checks of the second half wait (bounded) until a checkpoint was taken, so at least one is
  // taken mid-campaign however slowly the monitor thread is scheduled.
  std::atomic<int> calls{0};
  std::atomic<int> checkpoints_taken{0};
  const CheckFactory slow = [&] {
    return CheckFn([&](const Scenario& s) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
      if (++calls > 100) {
        while (checkpoints_taken == 0 && std::chrono::steady_clock::now() < deadline)
          std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      return test::fake_check(s);
    });
  };
  auto o = options(200, 2, {});
  o.corpus_dir.clear();
  o.checkpoint_period_s = 0.05;
  std::vector<CampaignResult> checkpoints;
  o.on_checkpoint = [&](const CampaignResult& r) {
    checkpoints.push_back(r);
    ++checkpoints_taken;
  };
  const CampaignResult final_result = run_campaign(o, slow);
  ASSERT_FALSE(checkpoints.empty());
  for (const CampaignResult& c : checkpoints) {
    EXPECT_LE(c.scenarios, final_result.scenarios);
    std::uint64_t sum = 0;
    for (const auto& [property, n] : c.by_property) sum += n;
    EXPECT_EQ(sum, c.property_failures);
  }
  EXPECT_EQ(final_result.property_failures, final_result.by_rule.at("fake_proximity"));
}

TEST(Campaign, NonsenseOptionsAreRejected) {
  auto o = options(10, 0, {});
  EXPECT_THROW(run_campaign(o, fake_factory()), std::invalid_argument);
  o = options(10, 1, {});
  o.shard_index = 3;
  o.shard_count = 3;
  EXPECT_THROW(run_campaign(o, fake_factory()), std::invalid_argument);
  o = options(0, 1, {});
  EXPECT_THROW(run_campaign(o, fake_factory()), std::invalid_argument);
  o = options(10, 1, {});
  o.shrink.max_attempts = -1;
  EXPECT_THROW(run_campaign(o, fake_factory()), std::invalid_argument);
  o = options(10, 1, {});
  o.guided.lag_batches = 0;  // a guided run would wait for its own batch
  EXPECT_THROW(run_campaign(o, fake_factory()), std::invalid_argument);
}

// The progress samples behind the report's findings-over-time plot: in time order, never
// decreasing, ending at the campaign's final counts.
TEST(CampaignTimeline, SamplesTheCampaignInOrderAndEndsAtItsResult) {
  CampaignOptions o = options(0, 1, "");
  o.runs.reset();
  o.time_s = 2.5;
  const CampaignResult r = run_campaign(o, [] { return CheckFn(test::fake_check); });
  ASSERT_GE(r.timeline.size(), 2u);
  EXPECT_LE(r.timeline.size(), kMaxTimelineSamples);
  for (std::size_t k = 1; k < r.timeline.size(); ++k) {
    EXPECT_GE(r.timeline[k].elapsed_s, r.timeline[k - 1].elapsed_s);
    EXPECT_GE(r.timeline[k].scenarios, r.timeline[k - 1].scenarios);
    EXPECT_GE(r.timeline[k].failing_scenarios, r.timeline[k - 1].failing_scenarios);
  }
  EXPECT_EQ(r.timeline.back().scenarios, r.scenarios);
  EXPECT_EQ(r.timeline.back().failing_scenarios, r.failing_scenarios);
  const auto dir = mg::test::unused_path("campaign_test_timeline");
  fs::create_directories(dir);
  write_campaign_report(dir.string(), o, r, {});
  std::ifstream in(dir / "report.html");
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("<h2>Findings over time</h2>"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mg::fuzz
