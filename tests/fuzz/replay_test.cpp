#include "fuzz/replay.h"

#include <gtest/gtest.h>

#include "fake_check.h"
#include "fuzz/scenario_gen.h"

namespace mg::fuzz {
namespace {

CorpusCase recorded_case() {
  CorpusCase c;
  c.scenario = generate_scenario(run_seed(9, 0), {}).value();
  MainVehicle v;
  v.x_m = c.scenario.ego.x_m - 12.0;
  c.scenario.vehicles = {v};
  const RunOutcome o = run_properties(c.scenario, test::fake_check, "fake", true);
  c.verdict = verdict_of(o);
  c.failure = o.failures.at(0);
  c.signature = signature_of("fake", c.failure);
  return c;
}

TEST(Replay, ACaseReplaysFromItsJsonAlone) {
  const CorpusCase c = case_from_json(case_to_json(recorded_case()), "case.json");
  const ReplayResult r = replay_case(c, test::fake_check);
  EXPECT_TRUE(r.reproduces);
  EXPECT_TRUE(r.differences.empty());
}

TEST(Replay, AChangedScenarioDoesNotReproduce) {
  CorpusCase c = recorded_case();
  c.scenario.vehicles[0].x_m -= 40.0;  // now far enough: the planted rule holds
  const ReplayResult r = replay_case(c, test::fake_check);
  EXPECT_FALSE(r.reproduces);
  ASSERT_FALSE(r.differences.empty());
  EXPECT_EQ(r.differences[0], "holds: expected false, got true");
}

TEST(Replay, MarginsWithinToleranceReproduceAndBeyondDoNot) {
  CaseVerdict expected = recorded_case().verdict;
  CaseVerdict actual = expected;
  actual.violations[0].margin += 0.005;
  EXPECT_TRUE(compare_verdicts(expected, actual).empty());
  actual.violations[0].margin += 1.0;
  EXPECT_EQ(compare_verdicts(expected, actual).size(), 2u);  // one missing, one unexpected
}

TEST(Replay, ADifferentLiablePartyDoesNotReproduce) {
  CaseVerdict expected = recorded_case().verdict;
  CaseVerdict actual = expected;
  actual.violations[0].liable_id = Party::vehicle(1);
  EXPECT_FALSE(compare_verdicts(expected, actual).empty());
}

TEST(Replay, ALostPropertyFailureDoesNotReproduce) {
  CaseVerdict expected = recorded_case().verdict;
  CaseVerdict actual = expected;
  actual.failed_properties.clear();
  const auto diffs = compare_verdicts(expected, actual);
  ASSERT_EQ(diffs.size(), 1u);
  EXPECT_NE(diffs[0].find("failed properties"), std::string::npos);
}

}  // namespace
}  // namespace mg::fuzz
