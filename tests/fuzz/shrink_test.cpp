#include "fuzz/shrink.h"

#include <cmath>

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

namespace mg::fuzz {
namespace {

// Planted failure that needs two vehicles together: at least two within 30 m of the ego.
bool two_near(const Scenario& s) {
  int near = 0;
  for (const MainVehicle& v : s.vehicles) near += std::abs(v.x_m - s.ego.x_m) < test::kFakeProximityM ? 1 : 0;
  return near >= 2;
}

// A scenario the shrink tree cannot simplify (no shrinks at all) keeping four vehicles, two of
// which the failure needs: the removal pass takes out the other two, one at a time.
//   lane 0:  [1] far behind      [2] near the ego      [3] far ahead     [4] near the ego (lane 1)
TEST(Shrink, VehiclesTheTreeCouldNotRemoveAreRemovedOneByOne) {
  Scenario s = generate_scenario(run_seed(5, 0), {}).value();
  s.road.main_lanes = 2;
  s.vehicles.clear();
  const double offsets[] = {-300.0, 10.0, 300.0, -10.0};
  for (int k = 0; k < 4; ++k) {
    MainVehicle v;
    v.id = k + 1;
    v.lane = k == 3 ? 1 : 0;
    v.x_m = s.ego.x_m + offsets[k];
    s.vehicles.push_back(v);
  }
  ASSERT_TRUE(is_loadable(s));
  ASSERT_TRUE(two_near(s));
  const ShrinkOutcome out = shrink_scenario(rc::shrinkable::just(s), two_near, {});
  EXPECT_TRUE(out.minimal);
  ASSERT_EQ(out.scenario.vehicles.size(), 2u);
  EXPECT_EQ(out.scenario.vehicles[0].id, 2);
  EXPECT_EQ(out.scenario.vehicles[1].id, 4);
  EXPECT_EQ(out.steps, 2);
}

TEST(Shrink, ALocalMinimumWithThreeOrMoreVehiclesSurvivesNoSingleOrPairRemoval) {
  GenConfig uniform;
  uniform.targeted_families = false;
  int checked = 0;
  for (std::uint64_t i = 0; i < 400 && checked < 5; ++i) {
    const auto g = generate_scenario(run_seed(21, i), uniform);
    if (g.value().vehicles.size() < 4 || !two_near(g.value())) continue;
    ++checked;
    const ShrinkOutcome out = shrink_scenario(g, two_near, {});
    ASSERT_TRUE(two_near(out.scenario));
    ASSERT_TRUE(out.minimal);
    EXPECT_EQ(out.scenario.vehicles.size(), 2u);  // exactly the two it needs
    const auto& v = out.scenario.vehicles;
    for (std::size_t a = 0; a < v.size(); ++a) {
      Scenario one = out.scenario;
      one.vehicles.erase(one.vehicles.begin() + static_cast<long>(a));
      EXPECT_FALSE(two_near(one));
    }
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace mg::fuzz
