#include "rules/definition1_monitor.h"

#include <gtest/gtest.h>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

// A Def. 1 merge decided at t = 0 into the gap (follower 1, leader 2) with v_e* = 22 m/s and
// rho_m = 4 s. Ego at X = 0, all at 20 m/s.
Trace with_decision(Trace t, int follower, int leader, double ve_star) {
  Decision d;
  d.time_s = 0.0;
  d.mode = DecisionMode::kDef1Merge;
  d.gap = Gap{follower, leader};
  d.ve_star_mps = ve_star;
  d.merge_duration_s = 4.0;
  t.decisions.push_back(d);
  return t;
}

Scenario gap_scenario(double follower_x, double leader_x) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, follower_x, 20.0), vehicle(2, leader_x, 20.0)};
  return s;
}

// Ineq. (1): LHS = X_o + 20*2 + 2*16/8 = X_o + 44. D_lon with the follower at 20 + 2*2 = 24 m/s
// behind the ego at 22: 4.8 + [24*0.5 + 0.25 + 25^2/8 - 22^2/16] = 4.8 + 60.125 = 64.925 m.
// RHS = 0 + 22*2 - 64.925 = -20.925. Margin = -20.925 - (X_o + 44).
TEST(Def1Monitor, Ineq1HoldsWhenFollowerFarBehind) {
  const Scenario s = gap_scenario(-80.0, 200.0);
  const MonitorOutput out = test::run(monitor_def1_1_gap, s, with_decision(constant_accel_trace(s, 1.0), 1, 2, 22.0));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, -20.925 - (-80.0 + 44.0), 1e-9);  // 15.075 m
}

TEST(Def1Monitor, Ineq1FailsForCloseFollowerAndBlamesEgo) {
  const Scenario s = gap_scenario(-40.0, 200.0);
  const MonitorOutput out = test::run(monitor_def1_1_gap, s, with_decision(constant_accel_trace(s, 1.0), 1, 2, 22.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, kEgoId);
  EXPECT_NEAR(out.result.min_margin, -20.925 - 4.0, 1e-9);  // -24.925 m
}

// Ineq. (2) with v_e* = 20: D_lon(ego rear at 20, leader at 20) = 45.175 m;
// margin = (X_o + 80 - 45.175) - (0 + 80) = X_o - 45.175.
TEST(Def1Monitor, Ineq2MarginIsLeaderDistanceMinusDlon) {
  const Scenario ok = gap_scenario(-200.0, 60.0);
  const MonitorOutput held = test::run(monitor_def1_2_gap, ok, with_decision(constant_accel_trace(ok, 1.0), 1, 2, 20.0));
  EXPECT_TRUE(held.result.holds);
  EXPECT_NEAR(held.result.min_margin, 60.0 - 45.175, 1e-9);
  const Scenario bad = gap_scenario(-200.0, 40.0);
  const MonitorOutput broke = test::run(monitor_def1_2_gap, bad, with_decision(constant_accel_trace(bad, 1.0), 1, 2, 20.0));
  ASSERT_FALSE(broke.result.holds);
  EXPECT_NEAR(broke.result.min_margin, 40.0 - 45.175, 1e-9);
}

TEST(Def1Monitor, FollowerAcceleratingBeyondItsLimitInTheWindowIsLiable) {
  // Follower accelerates at 3 > a_accel^max 2 (+0.05 tolerance): margin 2.05 - 3 = -0.95 m/s2
  // from T_dec = 0.
  const Scenario s = gap_scenario(-80.0, 200.0);
  const MonitorOutput out =
      test::run(monitor_def1_1_follower, s, with_decision(constant_accel_trace(s, 3.0, {0.0, 3.0, 0.0}), 1, 2, 22.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, 1);
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.0, 1e-12);
  EXPECT_NEAR(out.result.min_margin, -0.95, 1e-9);
}

TEST(Def1Monitor, FollowerAtItsLimitHoldsAndOnlyTheWindowCounts) {
  // At a = 2 the margin is the tolerance 0.05; a = 3 after the window [0, 2] s does not count.
  const Scenario s = gap_scenario(-80.0, 200.0);
  Trace t = with_decision(constant_accel_trace(s, 4.0, {0.0, 2.0, 0.0}), 1, 2, 22.0);
  for (auto& st : t.steps) {
    if (st.time_s > 2.1) st.others[0].accel_mps2 = 3.0;
  }
  const MonitorOutput out = test::run(monitor_def1_1_follower, s, t);
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 0.05, 1e-9);
}

TEST(Def1Monitor, LeaderBrakingBeyondBmaxInTheWindowIsLiable) {
  // Leader brakes at 9 > b_max 8: margin 8.05 - 9 = -0.95 m/s2.
  const Scenario s = gap_scenario(-80.0, 60.0);
  const MonitorOutput out =
      test::run(monitor_def1_2_leader, s, with_decision(constant_accel_trace(s, 1.0, {0.0, 0.0, -9.0}), 1, 2, 20.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, 2);
  EXPECT_NEAR(out.result.min_margin, -0.95, 1e-9);
}

// Def. 1.3: stop point = x + 4.8/2 + v^2/(2*8); side lane ends at 300 m.
TEST(Def1Monitor, HaltRuleMarginIsDistanceFromStopPointToSideLaneEnd) {
  Scenario s = base_scenario();
  s.ego.x_m = 250.0;
  const MonitorOutput held = test::run(monitor_def1_3_halt, s, constant_accel_trace(s, 0.0));
  EXPECT_NEAR(held.result.min_margin, 300.0 - (252.4 + 400.0 / 16.0), 1e-9);  // 22.6 m
  s.ego.speed_mps = 30.0;
  const MonitorOutput broke = test::run(monitor_def1_3_halt, s, constant_accel_trace(s, 0.0));
  ASSERT_FALSE(broke.result.holds);
  EXPECT_EQ(broke.result.liable_id, kEgoId);
  EXPECT_NEAR(broke.result.min_margin, 300.0 - (252.4 + 900.0 / 16.0), 1e-9);  // -8.65 m
}

TEST(Def1Monitor, HaltRuleDoesNotApplyWhileTheEgoHoldsTheRightOfWay) {
  Scenario s = base_scenario();
  s.ego.x_m = 250.0;
  s.ego.speed_mps = 30.0;
  s.vehicles = {vehicle(1, -200.0, 20.0)};
  const MonitorOutput out = test::run(monitor_def1_3_halt, s, with_decision(constant_accel_trace(s, 0.5), 1, -1, 30.0));
  EXPECT_TRUE(out.result.holds);
}

}  // namespace
}  // namespace mg
