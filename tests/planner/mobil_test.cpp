// The `mobil` baseline (src/planner/mobil*.cpp): IDM's free-road and interaction terms against
// Treiber et al. 2000 eq. (1)-(2), MOBIL's criteria (Kesting et al. 2007 eq. (2)-(3)) and its
// decisions on constructed situations, the lane change's path, and the planner stopping before
// the side lane's end when the main lane never opens.
#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/scenario.h"
#include "planner/mobil.h"
#include "planner/mobil_planner.h"
#include "planner/planner.h"

#include "baseline_fixtures.h"

namespace mg {
namespace {

using test::ramp;
using test::real_in;

IdmParams random_idm() {
  IdmParams p;
  p.desired_speed_mps = real_in(50, 400);
  p.time_headway_s = real_in(5, 30);
  p.min_gap_m = real_in(0, 50);
  p.max_accel_mps2 = real_in(3, 30);
  p.comfort_brake_mps2 = real_in(5, 40);
  p.exponent = *rc::gen::element(1.0, 2.0, 4.0, 6.0);
  return p;
}

RC_GTEST_PROP(Idm, FreeRoadTermIsEquationOne, ()) {
  const IdmParams p = random_idm();
  const double v = real_in(0, 400);
  const double expected = p.max_accel_mps2 * (1.0 - std::pow(v / p.desired_speed_mps, p.exponent));
  RC_ASSERT(std::abs(idm_free_road_mps2(v, p) - expected) <= 1e-12 * (1.0 + std::abs(expected)));
  RC_ASSERT(idm_accel_mps2(v, std::nullopt, p) == idm_free_road_mps2(v, p));
}

RC_GTEST_PROP(Idm, InteractionTermIsEquationsOneAndTwo, ()) {
  const IdmParams p = random_idm();
  const double v = real_in(0, 400);
  const IdmLeader leader{real_in(1, 2000), real_in(0, 400)};
  const double dv = v - leader.speed_mps;
  const double s_star = p.min_gap_m + std::max(0.0, v * p.time_headway_s + v * dv / (2.0 * std::sqrt(p.max_accel_mps2 * p.comfort_brake_mps2)));
  RC_ASSERT(std::abs(idm_desired_gap_m(v, dv, p) - s_star) <= 1e-12 * s_star);
  const double interaction = -p.max_accel_mps2 * (s_star / leader.gap_m) * (s_star / leader.gap_m);
  RC_ASSERT(std::abs(idm_interaction_mps2(v, leader, p) - interaction) <= 1e-12 * (1.0 + std::abs(interaction)));
  const double total = idm_accel_mps2(v, leader, p);
  RC_ASSERT(std::abs(total - (idm_free_road_mps2(v, p) + interaction)) <= 1e-9 * (1.0 + std::abs(total)));
  // The interaction only brakes, and more for a closer leader.
  RC_ASSERT(idm_interaction_mps2(v, leader, p) <= 0.0);
  RC_ASSERT(idm_interaction_mps2(v, {leader.gap_m * 0.5, leader.speed_mps}, p) <= idm_interaction_mps2(v, leader, p));
}

TEST(Idm, RestsAtTheStandstillGapBehindAStandingObstacle) {
  const IdmParams p;  // s0 = 2 m: at rest 2 m behind an obstacle, IDM neither pulls nor pushes
  EXPECT_DOUBLE_EQ(idm_accel_mps2(0.0, IdmLeader{p.min_gap_m, 0.0}, p), 0.0);
  EXPECT_LT(idm_accel_mps2(0.0, IdmLeader{0.5 * p.min_gap_m, 0.0}, p), 0.0);
  EXPECT_GT(idm_accel_mps2(0.0, IdmLeader{2.0 * p.min_gap_m, 0.0}, p), 0.0);
  EXPECT_TRUE(std::isfinite(idm_accel_mps2(20.0, IdmLeader{-1.0, 0.0}, p)));  // an overlap: finite, hard braking
}

TEST(Mobil, SafetyCriterionIsEquationTwo) {
  const MobilParams p;  // b_safe = 4
  MobilSituation s;
  EXPECT_TRUE(mobil_safe(s, p));  // no new follower
  s.new_follower_before_mps2 = 0.0;
  s.new_follower_after_mps2 = -4.0;
  EXPECT_TRUE(mobil_safe(s, p));  // a~_n >= -b_safe
  s.new_follower_after_mps2 = -4.01;
  EXPECT_FALSE(mobil_safe(s, p));
}

RC_GTEST_PROP(Mobil, IncentiveCriterionIsEquationThreeWithTheBias, ()) {
  MobilParams p;
  p.politeness = real_in(0, 20);
  p.threshold_mps2 = real_in(0, 10);
  p.bias_mps2 = real_in(0, 10);
  MobilSituation s;
  s.ego_before_mps2 = real_in(-80, 20);
  s.ego_after_mps2 = real_in(-80, 20);
  s.new_follower_before_mps2 = real_in(-80, 20);
  s.new_follower_after_mps2 = real_in(-80, 20);
  const double lhs = s.ego_after_mps2 - s.ego_before_mps2 + p.politeness * (*s.new_follower_after_mps2 - *s.new_follower_before_mps2);
  RC_ASSERT(std::abs(mobil_advantage_mps2(s, p) - lhs) <= 1e-12);
  RC_ASSERT(mobil_incentive(s, p) == (lhs > p.threshold_mps2 - p.bias_mps2));
  RC_ASSERT(mobil_changes_lane(s, p) == (mobil_safe(s, p) && mobil_incentive(s, p)));
}

TEST(Mobil, PolitenessWeighsTheNewFollowersLoss) {
  // The ego gains 0.5 m/s2; the new follower loses 1 m/s2 but stays above -b_safe.
  MobilSituation s{-0.5, 0.0, 0.3, -0.7, std::nullopt, std::nullopt};
  MobilParams selfish, polite;
  selfish.politeness = 0.0;
  polite.politeness = 1.0;
  EXPECT_TRUE(mobil_changes_lane(s, selfish));
  EXPECT_FALSE(mobil_changes_lane(s, polite));  // 0.5 - 1.0 = -0.5 < 0.1 - 0.3
}

MainVehicle main_lane_vehicle(int id, double x_m, double speed_mps) {
  MainVehicle v;
  v.id = id;
  v.x_m = x_m;
  v.speed_mps = speed_mps;
  return v;
}

TEST(Mobil, ChangesIntoAnEmptyMainLane) {
  const Scenario s = ramp();
  const MobilDecision d = decide_mobil(initial_snapshot(s), MobilPlannerParams{});
  EXPECT_TRUE(d.change) << d.reason;
  EXPECT_GT(d.situation.ego_after_mps2, d.situation.ego_before_mps2);  // the lane's end brakes the ego
}

TEST(Mobil, KeepsTheSideLaneAheadOfAFastCloseFollower) {
  Scenario s = ramp();
  s.vehicles = {main_lane_vehicle(1, -12.0, 30.0)};  // 7 m behind, 10 m/s faster
  const MobilDecision d = decide_mobil(initial_snapshot(s), MobilPlannerParams{});
  EXPECT_FALSE(d.safe) << d.reason;
  EXPECT_FALSE(d.change);
  ASSERT_TRUE(d.situation.new_follower_after_mps2.has_value());
  EXPECT_LT(*d.situation.new_follower_after_mps2, -MobilPlannerParams{}.safe_brake_mps2);
}

TEST(Mobil, NeedsRoomBesideTheEgo) {
  Scenario s = ramp();
  s.vehicles = {main_lane_vehicle(1, 2.0, 20.0)};  // alongside: the change would overlap it
  const MobilDecision d = decide_mobil(initial_snapshot(s), MobilPlannerParams{});
  EXPECT_FALSE(d.gaps_open) << d.reason;
  EXPECT_FALSE(d.change);
}

TEST(Mobil, ASlowLeaderInTheMainLaneTakesAwayTheIncentive) {
  Scenario s = ramp();
  s.road.side_lane_end_x_m = 2000.0;                  // the lane's end far away: barely an obstacle
  s.vehicles = {main_lane_vehicle(1, 25.0, 5.0)};     // slow, close ahead in the main lane
  const MobilDecision d = decide_mobil(initial_snapshot(s), MobilPlannerParams{});
  EXPECT_TRUE(d.safe);
  EXPECT_FALSE(d.incentive) << d.reason;
}

RC_GTEST_PROP(Mobil, TheLaneChangePathIsMinimumJerkBetweenTheLanes, ()) {
  const double length = real_in(10, 2000), start_y = -real_in(20, 50), start_x = real_in(-1000, 1000);
  const LaneChangePath path{start_x, start_y, length, 0.0};
  RC_ASSERT(path.y_at(start_x - 1.0) == start_y);
  RC_ASSERT(path.y_at(start_x) == start_y);
  RC_ASSERT(std::abs(path.y_at(path.end_x_m())) < 1e-12);
  RC_ASSERT(path.y_at(path.end_x_m() + 1.0) == 0.0);
  const double h = 1e-4 * length;  // zero slope at both ends, monotone in between
  RC_ASSERT(std::abs(path.y_at(start_x + h) - start_y) < 1e-6 * std::abs(start_y));
  RC_ASSERT(std::abs(path.y_at(path.end_x_m() - h)) < 1e-6 * std::abs(start_y));
  const double u = real_in(0, 10) / 10.0;
  RC_ASSERT(path.y_at(start_x + u * length) <= path.y_at(start_x + std::min(1.0, u + 0.05) * length) + 1e-12);
  RC_ASSERT(std::abs(min_jerk_blend(0.5) - 0.5) < 1e-15);
}

TEST(MobilPlanner, ChangesAlongItsPathAndEndsInTheMainLane) {
  const Scenario s = ramp();
  MobilPlanner planner;
  const PlanOutput out = planner.plan(initial_snapshot(s));
  ASSERT_TRUE(std::holds_alternative<MobilChangingLane>(planner.phase()));
  EXPECT_EQ(out.mode, "lane_change");
  const LaneChangePath& path = std::get<MobilChangingLane>(planner.phase()).path;
  EXPECT_DOUBLE_EQ(path.length_m, 20.0 * MobilPlannerParams{}.lane_change_duration_s);
  EXPECT_DOUBLE_EQ(out.path.back().y_m, 0.0);
  EXPECT_LE(out.path.front().x_m, s.ego.x_m);
}

// A kinematic rollout of the planner's commands (the speed controller of the simulator, a point
// mass on the path, traffic at constant speed).
struct Rolled {
  double x_m = 0.0, y_m = 0.0, speed_mps = 0.0;
  bool changed = false;
};

Rolled roll(Scenario s, double horizon_s) {
  MobilPlanner planner;
  WorldSnapshot w = initial_snapshot(s);
  Rolled r{s.ego.x_m, s.ego.y_m, s.ego.speed_mps, false};
  const double dt = s.params.sim.planner_cycle_s;
  for (double t = 0.0; t < horizon_s; t += dt) {
    w.time_s = t;
    const PlanOutput out = planner.plan(w);
    r.changed = r.changed || out.mode == "lane_change";
    const double a = std::clamp(std::clamp(5.0 * (out.target_speed_mps - r.speed_mps), -out.accel_limit_mps2, out.accel_limit_mps2),
                                -s.ego.limits.brake_max_mps2, s.ego.limits.accel_max_mps2);
    r.speed_mps = std::max(0.0, r.speed_mps + a * dt);
    r.x_m += r.speed_mps * dt;
    w.ego.x_m = r.x_m;
    w.ego.vx_mps = r.speed_mps;
    w.ego.accel_mps2 = a;
    for (ObservedVehicle& o : w.others) o.state.x_m += o.state.vx_mps * dt;
  }
  return r;
}

TEST(MobilPlanner, StopsBeforeTheSideLaneEndWhenTheMainLaneNeverOpens) {
  Scenario s = ramp();
  // A standing jam in the main lane along the whole side lane, bumper gaps of 3.2 m.
  for (int i = 0; i < 40; ++i) s.vehicles.push_back(main_lane_vehicle(i + 1, -50.0 + 8.0 * i, 0.0));
  const Rolled r = roll(s, 40.0);
  EXPECT_FALSE(r.changed);
  EXPECT_LT(r.speed_mps, 0.05);
  EXPECT_LE(r.x_m + 0.5 * s.ego.size.length_m, s.road.side_lane_end_x_m);
  EXPECT_GE(r.x_m + 0.5 * s.ego.size.length_m, s.road.side_lane_end_x_m - 2.0 * MobilPlannerParams{}.min_gap_m);
}

TEST(MobilPlanner, ItsDefaultsLieInTheirRanges) {
  const MobilPlannerParams defaults;
  EXPECT_TRUE(params_in_range(mobil_parameter_table(), defaults));
  EXPECT_EQ(first_out_of_range(mobil_parameter_table(), defaults), "");
  MobilPlannerParams bad;
  bad.politeness = -1.0;
  EXPECT_NE(first_out_of_range(mobil_parameter_table(), bad).find("politeness"), std::string::npos);
}

TEST(MobilPlanner, EveryParameterIsDocumentedWithItsDefault) {
  const MobilPlannerParams defaults;
  for (const auto& row : mobil_parameter_table()) {
    const std::optional<double> documented = test::documented_default(row.name);
    ASSERT_TRUE(documented.has_value()) << row.name << " is not in docs/baselines.md";
    EXPECT_DOUBLE_EQ(*documented, row.value(defaults)) << row.name;
  }
}

}  // namespace
}  // namespace mg
