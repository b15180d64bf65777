#include "fuzz/scenario_gen.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/input_error.h"
#include "core/rss.h"
#include "fuzz/shrink.h"

namespace mg::fuzz {
namespace {

// True when every main-lane vehicle is at least the RSS longitudinal distance (RCPP eq. 1, the
// scenario's response time, declared limits) behind each vehicle ahead of it in its lane.
bool starts_rss_safe_in_every_lane(const Scenario& s) {
  for (const MainVehicle& rear : s.vehicles) {
    for (const MainVehicle& front : s.vehicles) {
      if (&rear == &front || rear.lane != front.lane || front.x_m < rear.x_m) continue;
      const double d_lon_m = rss_longitudinal_m({rear.speed_mps, front.speed_mps, rear.size.length_m, front.size.length_m,
                                                 s.params.rss.response_time_s, rear.limits.accel_max_mps2,
                                                 rear.limits.brake_min_mps2, front.limits.brake_max_mps2});
      if (front.x_m - rear.x_m < d_lon_m) return false;
    }
  }
  return true;
}

RC_GTEST_PROP(ScenarioGen, EveryGeneratedScenarioStartsRssSafeBetweenMainLaneVehicles, ()) {
  const Scenario s = *gen_scenario(GenConfig{});
  RC_ASSERT(starts_rss_safe_in_every_lane(s));
}

RC_GTEST_PROP(ScenarioGen, EveryFirstShrinkStartsRssSafe, (std::uint64_t seed)) {
  const auto generated = generate_scenario(seed, GenConfig{});
  auto shrinks = generated.shrinks();
  int checked = 0;
  while (auto candidate = shrinks.next()) {
    RC_ASSERT(starts_rss_safe_in_every_lane(candidate->value()));
    if (++checked == 40) break;
  }
}

TEST(ScenarioGen, RssSafetyCheckRejectsAFollowerTooClose) {
  Scenario s = generate_scenario(run_seed(1, 0), {}).value();
  s.vehicles.clear();
  MainVehicle rear;
  rear.id = 1;
  rear.speed_mps = 20.0;
  MainVehicle front = rear;
  front.id = 2;
  front.speed_mps = 0.0;
  front.x_m = 44.8;  // the campaign's finding: 20 m/s, 44.8 m behind a stopped vehicle
  s.vehicles = {rear, front};
  EXPECT_FALSE(starts_rss_safe_in_every_lane(s));
  s.vehicles[1].x_m = 200.0;
  EXPECT_TRUE(starts_rss_safe_in_every_lane(s));
}

RC_GTEST_PROP(ScenarioGen, EveryGeneratedScenarioPassesTheLoader, ()) {
  const Scenario s = *gen_scenario(GenConfig{});
  const Scenario loaded = scenario_from_json(scenario_to_json(s), "generated");
  RC_ASSERT(loaded == s);
}

RC_GTEST_PROP(ScenarioGen, EveryFirstShrinkPassesTheLoader, (std::uint64_t seed)) {
  const auto generated = generate_scenario(seed, GenConfig{});
  auto shrinks = generated.shrinks();
  int checked = 0;
  while (auto candidate = shrinks.next()) {
    RC_ASSERT(is_loadable(candidate->value()));
    if (++checked == 40) break;
  }
}

RC_GTEST_PROP(ScenarioGen, GeneratedScenariosRespectTheDocumentedRanges, ()) {
  const Scenario s = *gen_scenario(GenConfig{});
  RC_ASSERT(s.vehicles.size() <= 6u);
  RC_ASSERT(s.ego.speed_mps <= s.road.speed_limit_mps);
  RC_ASSERT(s.ego.x_m >= s.road.side_lane_start_x_m);
  const double edge_clearance_m = s.road.lane_width_m / 2.0 - std::abs(s.ego.y_m + s.road.lane_width_m) - s.ego.size.width_m / 2.0;
  RC_ASSERT(edge_clearance_m >= range::kEgoEdgeClearanceM - 0.01 || s.ego.y_m == -s.road.lane_width_m);
  const double v = s.ego.speed_mps;
  RC_ASSERT(s.road.side_lane_end_x_m - s.ego.x_m >= v * v / (2 * s.ego.limits.brake_min_mps2));
  RC_ASSERT(s.params.sim.horizon_s >= range::kHorizon.lo);
  RC_ASSERT(s.params.sim.horizon_s <= range::kHorizon.hi);
  for (const MainVehicle& m : s.vehicles) {
    RC_ASSERT(m.lane < s.road.main_lanes);
    RC_ASSERT(m.limits.brake_min_mps2 <= m.limits.brake_max_mps2);
    if (m.noncompliance.type == NonComplianceType::kExceedAccel) RC_ASSERT(m.noncompliance.accel_mps2 > m.limits.accel_max_mps2);
    if (m.noncompliance.type == NonComplianceType::kExceedBrake) RC_ASSERT(m.noncompliance.accel_mps2 > m.limits.brake_max_mps2);
  }
}

TEST(ScenarioGen, GenerationIsDeterministicPerSeed) {
  for (std::uint64_t i = 0; i < 20; ++i)
    EXPECT_EQ(generate_scenario(run_seed(7, i), {}).value(), generate_scenario(run_seed(7, i), {}).value());
  EXPECT_NE(generate_scenario(run_seed(7, 0), {}).value(), generate_scenario(run_seed(7, 1), {}).value());
  EXPECT_NE(run_seed(7, 3), run_seed(8, 3));
}

TEST(ScenarioGen, CoversEveryBehaviourNonComplianceAndVehicleCount) {
  std::set<BehaviourType> behaviours;
  std::set<NonComplianceType> noncompliance;
  std::set<std::size_t> counts;
  std::set<int> lanes;
  bool v2v = false;
  for (std::uint64_t i = 0; i < 400; ++i) {
    const Scenario s = generate_scenario(run_seed(1, i), {}).value();
    counts.insert(s.vehicles.size());
    lanes.insert(s.road.main_lanes);
    for (const MainVehicle& m : s.vehicles) {
      behaviours.insert(m.behaviour.type);
      noncompliance.insert(m.noncompliance.type);
      v2v = v2v || (m.v2v.capable && m.v2v.loss_prob > 0);
    }
  }
  EXPECT_EQ(behaviours.size(), 6u);
  EXPECT_EQ(noncompliance.size(), 4u);
  EXPECT_EQ(counts, (std::set<std::size_t>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(lanes, (std::set<int>{1, 2, 3}));
  EXPECT_TRUE(v2v);
}

TEST(ScenarioGen, CompliantConfigGeneratesNoNonCompliance) {
  GenConfig config;
  config.allow_noncompliance = false;
  for (std::uint64_t i = 0; i < 100; ++i)
    for (const MainVehicle& m : generate_scenario(run_seed(2, i), config).value().vehicles)
      EXPECT_EQ(m.noncompliance.type, NonComplianceType::kNone);
}

TEST(ScenarioGen, ShrinkingOffersFewerVehiclesFirst) {
  for (std::uint64_t i = 0; i < 50; ++i) {
    const auto generated = generate_scenario(run_seed(3, i), {});
    if (generated.value().vehicles.size() < 2) continue;
    auto shrinks = generated.shrinks();
    bool fewer = false;
    while (auto c = shrinks.next())
      if (c->value().vehicles.size() < generated.value().vehicles.size()) { fewer = true; break; }
    EXPECT_TRUE(fewer);
  }
}

}  // namespace
}  // namespace mg::fuzz
