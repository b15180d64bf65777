#include "fuzz/corpus_merge.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "fake_check.h"
#include "fuzz/scenario_gen.h"
#include "tests/support/scratch_files.h"

namespace mg::fuzz {
namespace {

namespace fs = std::filesystem;

// An open finding of the planted check (a vehicle within 30 m) with `vehicles` vehicles, the
// first 10 m ahead of the ego, and the given horizon.
CorpusCase finding(std::size_t vehicles, double horizon_s, std::uint64_t run) {
  CorpusCase c;
  c.scenario = generate_scenario(run_seed(5, 0), {}).value();
  c.scenario.vehicles.clear();
  for (std::size_t i = 0; i < vehicles; ++i) {
    MainVehicle v;
    v.id = static_cast<int>(i) + 1;
    v.lane = static_cast<int>(i % 2);
    v.x_m = c.scenario.ego.x_m + 10.0 + 200.0 * static_cast<double>(i / 2);
    c.scenario.vehicles.push_back(v);
  }
  c.scenario.road.main_lanes = 2;
  c.scenario.params.sim.horizon_s = horizon_s;
  const RunOutcome o = run_properties(c.scenario, test::fake_check, "fake", true);
  c.verdict = verdict_of(o);
  c.failure = o.failures.at(0);
  c.signature = signature_of("fake", c.failure);
  c.provenance = {"mergeguard fuzz", 5, run, 3, 10, true, "2026-01-01T00:00:00Z"};
  return c;
}

// The same signature's case after a fix: its recorded verdict holds (a regression test).
CorpusCase regression(double horizon_s) {
  CorpusCase c = finding(1, horizon_s, 0);
  c.verdict = CaseVerdict{};
  return c;
}

TEST(CorpusMerge, KeepsTheSmallestCaseOfEachSignatureFromOverlappingShards) {
  const auto a = mg::test::fresh_dir("corpus_merge_test_a"), b = mg::test::fresh_dir("corpus_merge_test_b"),
             into = mg::test::fresh_dir("corpus_merge_test_into");
  fs::remove_all(into);
  const std::string stem = finding(1, 5, 0).signature.file_stem();
  write_case(finding(3, 5, 7), (a / (stem + ".json")).string());
  write_case(finding(2, 9, 4), (b / (stem + ".json")).string());  // fewer vehicles wins over a shorter horizon
  const auto decisions = merge_corpora({a.string(), b.string()}, into.string());
  ASSERT_EQ(decisions.size(), 2u);
  EXPECT_EQ(decisions[0].action, CorpusMergeDecision::Action::kAdded);
  EXPECT_EQ(decisions[0].source, (b / (stem + ".json")).string());
  EXPECT_EQ(decisions[1].action, CorpusMergeDecision::Action::kDropped);
  ASSERT_EQ(case_files(into.string()).size(), 1u);
  EXPECT_EQ(load_case(case_files(into.string())[0]).scenario.vehicles.size(), 2u);

  // Merging a smaller one later replaces the target's file in place; a larger one is dropped.
  const auto c = mg::test::fresh_dir("corpus_merge_test_c");
  write_case(finding(2, 5, 9), (c / (stem + ".json")).string());  // same vehicles, shorter horizon
  const auto again = merge_corpora({a.string(), c.string()}, into.string());
  const auto replaced = std::find_if(again.begin(), again.end(), [](const auto& d) { return d.action == CorpusMergeDecision::Action::kReplaced; });
  ASSERT_NE(replaced, again.end());
  EXPECT_EQ(replaced->target, (into / (stem + ".json")).string());
  ASSERT_EQ(case_files(into.string()).size(), 1u);
  EXPECT_EQ(load_case(case_files(into.string())[0]).scenario.params.sim.horizon_s, 5.0);
  for (const auto& d : {a, b, c, into}) fs::remove_all(d);
}

TEST(CorpusMerge, KeepsEveryDistinctRegressionCaseOnceBesideTheOpenFinding) {
  const auto a = mg::test::fresh_dir("corpus_merge_test_ra"), b = mg::test::fresh_dir("corpus_merge_test_rb"),
             into = mg::test::fresh_dir("corpus_merge_test_rinto");
  const std::string stem = finding(1, 5, 0).signature.file_stem();
  write_case(regression(6), (a / (stem + ".json")).string());
  write_case(regression(6), (b / (stem + ".json")).string());  // the same regression case again
  write_case(regression(7), (b / (stem + "-2.json")).string());
  write_case(finding(1, 5, 1), (b / (stem + "-3.json")).string());
  merge_corpora({a.string(), b.string()}, into.string());
  const auto files = case_files(into.string());
  ASSERT_EQ(files.size(), 3u);  // the open finding and two distinct regression cases
  EXPECT_EQ(fs::path(files[0]).filename().string(), stem + "-2.json");
  EXPECT_EQ(fs::path(files[2]).filename().string(), stem + ".json");  // the open finding keeps the plain name
  EXPECT_FALSE(load_case(files[2]).verdict.failed_properties.empty());
  for (const auto& d : {a, b, into}) fs::remove_all(d);
}

TEST(CorpusMerge, ACorruptCaseStopsTheMergeBeforeAnythingIsWritten) {
  const auto a = mg::test::fresh_dir("corpus_merge_test_ca"), into = mg::test::fresh_dir("corpus_merge_test_cinto");
  fs::remove_all(into);
  write_case(finding(1, 5, 0), (a / "good.json").string());
  std::ofstream(a / "bad.json") << "{\"format_version\": 1,";
  try {
    merge_corpora({a.string()}, into.string());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(into));
  fs::remove_all(a);
}

}  // namespace
}  // namespace mg::fuzz
