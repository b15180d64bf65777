#include "fuzz/shrink.h"

#include <gtest/gtest.h>

#include "fake_check.h"
#include "fuzz/scenario_gen.h"

namespace mg::fuzz {
namespace {

bool planted_failure(const Scenario& s) { return !test::fake_check(s).holds; }

// The first generated scenario (from seed 1 on) that fails the planted check with >= 3 vehicles,
// from the uniform generator: a targeted family's scenario keeps its family's partner when it
// shrinks (ScenarioFamilies tests), so the nominal values below are the uniform family's.
rc::Shrinkable<Scenario> first_failing(std::size_t min_vehicles) {
  GenConfig uniform;
  uniform.targeted_families = false;
  for (std::uint64_t i = 0;; ++i) {
    auto g = generate_scenario(run_seed(1, i), uniform);
    if (g.value().vehicles.size() >= min_vehicles && planted_failure(g.value())) return g;
  }
}

TEST(Shrink, KeepsTheFailureAndRemovesEveryVehicleItDoesNotNeed) {
  const auto start = first_failing(3);
  const ShrinkOutcome out = shrink_scenario(start, planted_failure, {});
  EXPECT_TRUE(planted_failure(out.scenario));
  EXPECT_TRUE(out.minimal);
  EXPECT_GT(out.steps, 0);
  ASSERT_EQ(out.scenario.vehicles.size(), 1u);
  EXPECT_TRUE(is_loadable(out.scenario));
}

TEST(Shrink, DrivesUnneededParametersToTheirNominalValues) {
  const ShrinkOutcome out = shrink_scenario(first_failing(3), planted_failure, {});
  const MainVehicle& v = out.scenario.vehicles.at(0);
  EXPECT_EQ(v.behaviour.type, BehaviourType::kConstantSpeed);
  EXPECT_EQ(v.noncompliance.type, NonComplianceType::kNone);
  EXPECT_FALSE(v.v2v.capable);
  EXPECT_EQ(v.speed_mps, range::kSpeed.nominal);
  EXPECT_EQ(v.size.length_m, range::kLength.nominal);
  EXPECT_EQ(out.scenario.params.sim.horizon_s, range::kHorizon.nominal);
  EXPECT_EQ(out.scenario.ego.speed_mps, range::kEgoSpeed.nominal);
  EXPECT_EQ(v.x_m - out.scenario.ego.x_m, range::kFirstOffset.nominal);  // the simplest failing offset
}

TEST(Shrink, StopsAtTheAttemptBudget) {
  ShrinkBudget budget;
  budget.max_attempts = 3;
  const ShrinkOutcome out = shrink_scenario(first_failing(3), planted_failure, budget);
  EXPECT_LE(out.attempts, 3);
  EXPECT_FALSE(out.minimal);
  EXPECT_TRUE(planted_failure(out.scenario));
}

TEST(Shrink, AStopFlagEndsShrinkingWithTheBestSoFar) {
  std::atomic<bool> stop{true};
  ShrinkBudget budget;
  budget.stop = &stop;
  const auto start = first_failing(3);
  const ShrinkOutcome out = shrink_scenario(start, planted_failure, budget);
  EXPECT_EQ(out.attempts, 0);
  EXPECT_EQ(out.scenario, start.value());
}

}  // namespace
}  // namespace mg::fuzz
