#include "rules/definition1_monitor.h"

#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

// The ego (X = 0, 20 m/s, side lane) is seen to start merging at t = 0: it moves toward the main
// lane at 1.75 m/s, its start observed at t = 0.06 s and its midpoint at t = 1 s (2 (1 - 0) s <
// rho_m = 4 s, so Definition 1 is read with rho = 4 s). The gap it enters is (follower 1,
// leader 2); Definition 1 is read in the decision window [0, 0.06 s], and with every vehicle at
// 20 m/s the geometry, hence each margin, is the same at every step of it. v_e* is the feasible
// value nearest the ego's 20 m/s at the midpoint.
//
//   main lane   --[1]---------(X_o)                 [ego at the midpoint]     [2]-->
//   side lane                       [ego]  ->  lateral 1.75 m/s
Trace merging_at_t0(Trace t) { return test::with_lateral_move(std::move(t), 0.0, 1.75); }

Scenario gap_scenario(double follower_x, double leader_x) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, follower_x, 20.0), vehicle(2, leader_x, 20.0)};
  return s;
}

// Ineq. (1) at v_e* = 20: LHS = X_o + 20*2 + 2*16/8 = X_o + 44. D_lon with the follower at
// 20 + 2*2 = 24 m/s behind the ego at 20: 4.8 + [24*0.5 + 0.25 + 25^2/8 - 20^2/16] = 70.175 m.
// RHS = 0 + 20*2 - 70.175 = -30.175. Margin = -30.175 - (X_o + 44) = -X_o - 74.175.
TEST(Def1Monitor, Ineq1HoldsWhenFollowerFarBehind) {
  const Scenario s = gap_scenario(-80.0, 200.0);
  const MonitorOutput out = test::run(monitor_def1_1_gap, s, merging_at_t0(constant_accel_trace(s, 1.0)));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 80.0 - 74.175, 1e-9);  // 5.825 m
}

// With a speed limit of 22 m/s the best v_e* toward a follower alone is 22 m/s: LHS as above,
// D_lon(24 behind 22) = 4.8 + [12 + 0.25 + 78.125 - 22^2/16] = 64.925 m, RHS = 44 - 64.925.
// Margin = -20.925 - (X_o + 44) in the paper's model; the bounded-rate ego (20 -> 22 m/s at
// 2 m/s2) is 1 m further back at rho/2, and both must hold: a follower 55 m behind fails by
// 10.925 m at every v_e*. (The
// other gap of the lane, behind vehicle 1, is worse: ineq. (1.2) toward it at v_e* = 0 over
// rho/2 = 2 s is -55 + 20*2 - 4.8 = -19.8 m. Closer than 35.2 m it would be feasible, see
// merge_attempts_test.cpp.)
TEST(Def1Monitor, Ineq1FailsForCloseFollowerAndBlamesEgo) {
  Scenario s = gap_scenario(-55.0, 200.0);
  s.vehicles.pop_back();  // the follower alone: no leader constrains v_e*
  s.road.speed_limit_mps = 22.0;
  const MonitorOutput out = test::run(monitor_def1_1_gap, s, merging_at_t0(constant_accel_trace(s, 1.0)));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -20.925 + 11.0 - 1.0, 1e-6);  // -10.925 m
}

// Ineq. (2) with v_e* = 20: D_lon(ego rear at 20, leader at 20) = 45.175 m;
// margin = (X_o + 20 tau - 45.175) - (0 + 20 tau) = X_o - 45.175.
TEST(Def1Monitor, Ineq2MarginIsLeaderDistanceMinusDlon) {
  const Scenario ok = gap_scenario(-200.0, 60.0);
  const MonitorOutput held = test::run(monitor_def1_2_gap, ok, merging_at_t0(constant_accel_trace(ok, 1.0)));
  EXPECT_TRUE(held.result.holds);
  EXPECT_NEAR(held.result.min_margin, 60.0 - 45.175, 1e-9);
  // A gap too short from both ends (follower 40 m behind, leader 40 m ahead, speed limit 22 m/s):
  // no v_e* satisfies both inequalities, the ego merged without the right of way and breaks (1.2).
  Scenario bad = gap_scenario(-40.0, 40.0);
  bad.road.speed_limit_mps = 22.0;
  const MonitorOutput broke = test::run(monitor_def1_2_gap, bad, merging_at_t0(constant_accel_trace(bad, 1.0)));
  ASSERT_FALSE(broke.result.holds);
  EXPECT_EQ(broke.result.liable_id, Party::ego());
  EXPECT_LT(broke.result.min_margin, 0.0);
}

TEST(Def1Monitor, NoObservedMergeNoGapRuleApplies) {
  // The same too-short gap with the ego staying in its lane: no attempt, nothing to judge.
  Scenario s = gap_scenario(-40.0, 40.0);
  s.road.speed_limit_mps = 22.0;
  const Trace t = constant_accel_trace(s, 1.0);
  for (MonitorFn fn : {monitor_def1_1_gap, monitor_def1_2_gap}) {
    const MonitorOutput out = test::run(fn, s, t);
    EXPECT_TRUE(out.result.holds);
    EXPECT_FALSE(std::isfinite(out.result.min_margin));
  }
}

TEST(Def1Monitor, FollowerAcceleratingBeyondItsLimitInTheWindowIsLiable) {
  // Follower accelerates at 3 > a_accel^max 2 (+0.05 tolerance): margin 2.05 - 3 = -0.95 m/s2
  // from T_dec = 0 (the gap is feasible from the first step of the window).
  const Scenario s = gap_scenario(-80.0, 200.0);
  const MonitorOutput out =
      test::run(monitor_def1_1_follower, s, merging_at_t0(constant_accel_trace(s, 3.0, {0.0, 3.0, 0.0})));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.0, 1e-12);
  EXPECT_NEAR(out.result.min_margin, -0.95, 1e-9);
}

TEST(Def1Monitor, FollowerAtItsLimitHoldsAndOnlyTheWindowCounts) {
  // At a = 2 the margin is the tolerance 0.05; a = 3 after the window [0, rho/2 = 2] s does not count.
  const Scenario s = gap_scenario(-80.0, 200.0);
  Trace t = merging_at_t0(constant_accel_trace(s, 4.0, {0.0, 2.0, 0.0}));
  for (auto& st : t.steps) {
    if (st.time_s > 2.1) st.others[0].accel_mps2 = 3.0;
  }
  const MonitorOutput out = test::run(monitor_def1_1_follower, s, t);
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 0.05, 1e-9);
}

TEST(Def1Monitor, FollowerLimitIsNotJudgedWithoutADef1RightOfWay) {
  // The same over-accelerating follower while the ego stays in its lane: no Def. 1 window.
  const Scenario s = gap_scenario(-80.0, 200.0);
  const MonitorOutput out = test::run(monitor_def1_1_follower, s, constant_accel_trace(s, 3.0, {0.0, 3.0, 0.0}));
  EXPECT_TRUE(out.result.holds);
}

TEST(Def1Monitor, LeaderBrakingBeyondBmaxInTheWindowIsLiable) {
  // Leader brakes at 9 > b_max 8: margin 8.05 - 9 = -0.95 m/s2.
  const Scenario s = gap_scenario(-80.0, 60.0);
  const MonitorOutput out =
      test::run(monitor_def1_2_leader, s, merging_at_t0(constant_accel_trace(s, 1.0, {0.0, 0.0, -9.0})));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(2));
  EXPECT_NEAR(out.result.min_margin, -0.95, 1e-9);
}

// A platoon at 30 m/s, 15 m apart, from alongside the ego at x = 250 back to x = 190: no gap of
// the lane satisfies ineq. (1.1)/(1.2) (the gaps are far shorter than D_lon at 30 m/s; ahead of
// the front vehicle the ego cannot get, behind the last one it cannot drop in rho_m = 4 s at b_min).
std::vector<MainVehicle> dense_platoon() {
  return {vehicle(1, 250.0, 30.0), vehicle(2, 235.0, 30.0), vehicle(3, 220.0, 30.0), vehicle(4, 205.0, 30.0),
          vehicle(5, 190.0, 30.0)};
}

// Def. 1.3: stop point = x + 4.8/2 + v^2/(2*8); side lane ends at 300 m.
TEST(Def1Monitor, HaltRuleMarginIsDistanceFromStopPointToSideLaneEnd) {
  Scenario s = base_scenario();
  s.ego.x_m = 250.0;
  s.vehicles = dense_platoon();
  const MonitorOutput held = test::run(monitor_def1_3_halt, s, constant_accel_trace(s, 0.0));
  EXPECT_NEAR(held.result.min_margin, 300.0 - (252.4 + 400.0 / 16.0), 1e-9);  // 22.6 m
  s.ego.speed_mps = 30.0;
  const MonitorOutput broke = test::run(monitor_def1_3_halt, s, constant_accel_trace(s, 0.0));
  ASSERT_FALSE(broke.result.holds);
  EXPECT_EQ(broke.result.liable_id, Party::ego());
  EXPECT_NEAR(broke.result.min_margin, 300.0 - (252.4 + 900.0 / 16.0), 1e-9);  // -8.65 m
}

// Definition 1.3 asks the ego to halt only when no gap satisfies (1.1)/(1.2): on an empty road
// the same too-fast ego may go on toward the open lane.
TEST(Def1Monitor, HaltRuleDoesNotBindWhileSomeGapIsFeasible) {
  Scenario s = base_scenario();
  s.ego.x_m = 250.0;
  s.ego.speed_mps = 30.0;
  EXPECT_TRUE(test::run(monitor_def1_3_halt, s, constant_accel_trace(s, 0.0)).result.holds);
  s.vehicles = dense_platoon();
  EXPECT_FALSE(test::run(monitor_def1_3_halt, s, constant_accel_trace(s, 0.0)).result.holds);
}

// A trace of segments, each (duration, the accelerations of the ego and of every vehicle), the
// vehicles in the side lane and the main lane as constant_accel_trace starts them.
Trace piecewise_trace(Scenario s, const std::vector<std::pair<double, std::vector<double>>>& segments) {
  Trace t;
  double t0 = 0.0;
  for (const auto& [duration_s, accel] : segments) {
    const Trace part = constant_accel_trace(s, duration_s, accel);
    for (std::size_t i = t.steps.empty() ? 0 : 1; i < part.steps.size(); ++i) {
      TraceStep st = part.steps[i];
      st.time_s += t0;
      t.steps.push_back(st);
    }
    t.planner = part.planner;
    t0 += duration_s;
    s.ego.x_m = t.steps.back().ego.x_m;
    s.ego.speed_mps = t.steps.back().ego.vx_mps;
    for (std::size_t k = 0; k < s.vehicles.size(); ++k) {
      s.vehicles[k].x_m = t.steps.back().others[k].x_m;
      s.vehicles[k].speed_mps = t.steps.back().others[k].vx_mps;
    }
  }
  return t;
}

// The too-fast ego of HaltRuleMarginIsDistanceFromStopPointToSideLaneEnd (X = 250 m at 30 m/s,
// no longer able to halt before the side lane's end) goes on toward the gap ahead of vehicle 1,
// slow ahead of it (X = 255 m at 5 m/s): feasible, Definition 1.3 does not bind. From t = 0.5 s
// vehicle 1 accelerates at 12 m/s2, six times its a_accel^max: the gap is gone, and so is every
// other. The ego could not have foreseen the breach: vehicle 1 is liable. Declared able to
// accelerate at 12 m/s2, the same vehicle leaves no gap the ego could go on toward from the start,
// and the ego is liable. And an ego that then brakes until it can halt again, and speeds up once
// more with no gap, is liable for that, whatever the breach before.
TEST(Def1Monitor, HaltRuleBlamesTheVehicleWhoseBreachClosedTheGapTheEgoWentOnToward) {
  Scenario s = base_scenario();
  s.ego.x_m = 250.0;
  s.ego.speed_mps = 30.0;
  s.vehicles = {vehicle(1, 255.0, 5.0)};
  const std::vector<std::pair<double, std::vector<double>>> breach_at_half_a_second{{0.5, {0.0, 0.0}},
                                                                                     {2.0, {0.0, 12.0}}};
  const MonitorOutput breach = test::run(monitor_def1_3_halt, s, piecewise_trace(s, breach_at_half_a_second));
  ASSERT_FALSE(breach.result.holds);
  EXPECT_EQ(breach.result.liable_id, Party::vehicle(1));
  EXPECT_GT(*breach.result.first_violation_time_s, 0.5);
  // Vehicle 1 at 40 m/s2 from t = 0.1 s closes the gap by t = 0.5 s; the ego, braking at 25 m/s2
  // (harder than its b_max of 8), can halt again from t = 1 s, then speeds up at 25 m/s2 past
  // vehicle 1 and again can no longer halt, this time with no gap lost to a breach.
  const std::vector<std::pair<double, std::vector<double>>> then_halt_and_go_on{
      {0.1, {0.0, 0.0}}, {0.4, {0.0, 40.0}}, {1.0, {-25.0, 0.0}}, {1.0, {25.0, 0.0}}};
  const MonitorOutput later = test::run(monitor_def1_3_halt, s, piecewise_trace(s, then_halt_and_go_on));
  ASSERT_FALSE(later.result.holds);
  EXPECT_EQ(later.result.liable_id, Party::ego());
  EXPECT_GT(*later.result.first_violation_time_s, 1.5);
  EXPECT_LT(later.margin[25], 0.0);  // the breach's steps still count (t = 0.5 s)
  s.vehicles[0].limits.accel_max_mps2 = 12.0;
  const MonitorOutput declared = test::run(monitor_def1_3_halt, s, piecewise_trace(s, breach_at_half_a_second));
  ASSERT_FALSE(declared.result.holds);
  EXPECT_EQ(declared.result.liable_id, Party::ego());
}

// The ego of the previous test at 30 m/s, vehicle 1 5 m ahead of it at 5 m/s and beyond its
// declared a_accel^max (12 m/s2) from t = 0.5 s: the gap ahead of vehicle 1 is lost at t = 2 s.
// An ego still able to halt then, that loses its halt ability within the response time
// (T = 0.5 s) of the gap's last feasible step, could not have answered the loss: vehicle 1 is
// liable. One that goes on for longer without a gap is.
TEST(Def1Monitor, HaltRuleBlamesTheBreachThatClosedTheGapWithinTheResponseTimeOfTheHaltLost) {
  Scenario s = base_scenario();
  s.ego.speed_mps = 30.0;
  const std::vector<std::pair<double, std::vector<double>>> breach{{0.5, {0.0, 0.0}}, {3.5, {0.0, 12.0}}};
  // The front stops at x + 2.4 + 30^2/16: the halt is lost at t when x(0) = 300 - 58.65 - 30 t.
  const auto halt_lost_at = [&](double t_s) {
    s.ego.x_m = 241.35 - 30.0 * t_s;
    s.vehicles = {vehicle(1, s.ego.x_m + 5.0, 5.0)};
    return test::run(monitor_def1_3_halt, s, piecewise_trace(s, breach));
  };
  const MonitorOutput within = halt_lost_at(2.3);
  ASSERT_FALSE(within.result.holds);
  EXPECT_EQ(within.result.liable_id, Party::vehicle(1));
  EXPECT_NEAR(*within.result.first_violation_time_s, 2.3, 0.021);
  const MonitorOutput later = halt_lost_at(3.0);
  ASSERT_FALSE(later.result.holds);
  EXPECT_EQ(later.result.liable_id, Party::ego());
  EXPECT_NEAR(*later.result.first_violation_time_s, 3.0, 0.021);
}

TEST(Def1Monitor, HaltRuleDoesNotApplyWhileTheEgoHoldsTheRightOfWay) {
  // The ego of the previous test (too fast to halt before the side lane's end), with vehicle 1
  // 450 m behind: seen merging from t = 0, it holds the right of way by Definition 1 from then
  // (the gap behind nobody, ahead of vehicle 1, is feasible at 30 m/s) and the halt rule does not
  // apply (it would not bind either way while that gap is feasible:
  // HaltRuleDoesNotBindWhileSomeGapIsFeasible).
  Scenario s = base_scenario();
  s.ego.x_m = 250.0;
  s.ego.speed_mps = 30.0;
  s.vehicles = {vehicle(1, -200.0, 20.0)};
  const MonitorOutput out = test::run(monitor_def1_3_halt, s, merging_at_t0(constant_accel_trace(s, 0.5)));
  EXPECT_TRUE(out.result.holds);
  EXPECT_FALSE(std::isfinite(out.result.min_margin));
  EXPECT_FALSE(test::judge(s, merging_at_t0(constant_accel_trace(s, 0.5)))->row.ego_holds.empty());
}

}  // namespace
}  // namespace mg
