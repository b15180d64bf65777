#include "rules/rss_distance_monitor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

// Vehicle 1 follows vehicle 2 in the main lane, both at 20 m/s; the ego is far away.
// D_lon = (4.8 + 4.8)/2 + [20*0.5 + 2*0.5^2/2 + (20 + 2*0.5)^2/(2*4) - 20^2/(2*8)]
//       = 4.8 + [10 + 0.25 + 55.125 - 25] = 45.175 m.
Scenario two_in_lane(double gap_m) {
  Scenario s = base_scenario();
  s.ego.x_m = -500.0;
  s.vehicles = {vehicle(1, 0.0, 20.0), vehicle(2, gap_m, 20.0)};
  return s;
}

TEST(RssLongitudinalMonitor, SafeFollowingHoldsWithGapMinusDlonMargin) {
  const Scenario s = two_in_lane(50.0);
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, constant_accel_trace(s, 2.0));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 50.0 - 45.175, 1e-9);  // 4.825 m
}

TEST(RssLongitudinalMonitor, RearThatDoesNotBrakeOnceUnsafeIsLiable) {
  // Gap 40 m < 45.175 m from t = 0 (t_b = 0); vehicle 1 keeps its speed: after T = 0.5 s it
  // breaks its obligation to brake at least b_min. Margin = 40 - 45.175 = -5.175 m.
  const Scenario s = two_in_lane(40.0);
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, constant_accel_trace(s, 2.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, 1);
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.5, 1e-9);
  EXPECT_NEAR(out.result.min_margin, -5.175, 1e-9);
}

TEST(RssLongitudinalMonitor, RearBrakingAtBminIsAProperResponse) {
  // Same unsafe start, but vehicle 1 brakes at b_min = 4 m/s2 from t = 0: margin clamps to 0.
  const Scenario s = two_in_lane(40.0);
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, constant_accel_trace(s, 2.0, {0.0, -4.0, 0.0}));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 0.0, 1e-12);
}

TEST(RssLongitudinalMonitor, RearAcceleratingBeyondItsAmaxInsideTheResponseTimeIsLiable) {
  // Unsafe from t = 0 (40 m < 45.175 m); vehicle 1 accelerates at 3 > a_max 2 m/s2 at once.
  // Within T it owes no braking yet, but D_lon assumed at most a_max: liable at t = 0, not 0.5 s.
  const Scenario s = two_in_lane(40.0);
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, constant_accel_trace(s, 0.4, {0.0, 3.0, 0.0}));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, 1);
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.0, 1e-9);
}

TEST(RssLongitudinalMonitor, FrontBrakingBeyondBmaxIsLiable) {
  // Vehicle 2 brakes at 9 > b_max 8 m/s2 from t = 0 with a safe 50 m gap; as the gap shrinks
  // below D_lon the front is liable even though the rear brakes at b_min after T.
  const Scenario s = two_in_lane(50.0);
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, constant_accel_trace(s, 3.0, {0.0, 0.0, -9.0}));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, 2);
}

// Vehicle 1 (lane centre, Y = 0) drives 5 m behind the ego at its speed: longitudinally unsafe
// (D_lon 45.175 m). The ego, off-centre at Y = -2.03, is laterally unsafe at rest (D_lat 2.0625 m)
// but safe while it moves away at 0.5 m/s (D_lat = 0.1 + 1.9 + [0.03125 - 0.225]_+ = 2.0 m).
// At t = 0.3 s its lateral speed becomes `then_mps`: 0 (it stops moving away) or +0.1 (toward).
Trace stop_moving_away_trace(const Scenario& s, double then_mps) {
  Trace t = constant_accel_trace(s, 2.0);
  for (auto& st : t.steps) st.ego.vy_mps = st.time_s < 0.3 - 1e-9 ? -0.5 : then_mps;
  return t;
}

Scenario off_centre_beside_rear_vehicle() {
  Scenario s = base_scenario();
  s.ego.y_m = -2.03;
  s.vehicles = {vehicle(1, -5.0, 20.0)};
  return s;
}

TEST(RssLongitudinalMonitor, AnEgoThatStopsMovingAwayHasNotCutIn) {
  // Dangerous from t_b = 0.3 s without a cut-in: the rear vehicle 1 owes b_min from 0.8 s.
  const Scenario s = off_centre_beside_rear_vehicle();
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, stop_moving_away_trace(s, 0.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, 1);
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.8, 1e-9);
}

TEST(RssLongitudinalMonitor, AnEgoMovingTowardALongitudinallyUnsafeVehicleCutsIn) {
  const Scenario s = off_centre_beside_rear_vehicle();
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, stop_moving_away_trace(s, 0.1));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, kEgoId);
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.3, 1e-9);
}

TEST(RssLongitudinalMonitor, AnEgoThatAbortedWithinTheResponseTimeHasNotCutIn) {
  // As above (moving toward from t = 0.3 s), but the ego held a Def. 1 right of way until it
  // aborted at t = 0.1 s: at t_b = 0.3 s it is within T = 0.5 s of holding it, so its lateral
  // motion is no cut-in; vehicle 1, the rear vehicle, owes b_min from 0.8 s.
  const Scenario s = off_centre_beside_rear_vehicle();
  Trace t = stop_moving_away_trace(s, 0.1);
  Decision merge;
  merge.mode = DecisionMode::kDef1Merge;
  merge.gap = Gap{1, -1};
  Decision abort = merge;
  abort.time_s = 0.1;
  abort.mode = DecisionMode::kDef1Halt;
  abort.gap.reset();
  t.decisions = {merge, abort};
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, 1);
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.8, 1e-9);
}

// Vehicle 1 (30 m/s) passes the ego (20 m/s, Y = -2.0: laterally unsafe at rest) from 3 m behind:
// dangerous from t = 0, vehicle 1 is the rear vehicle until it draws level at t = 0.3 s, then the
// ego is. The ego's obligation to brake starts T = 0.5 s after it became the rear vehicle, at
// t = 0.8 s, not at t_b + T = 0.5 s.
Scenario overtaken_beside() {
  Scenario s = base_scenario();
  s.ego.y_m = -2.0;
  s.vehicles = {vehicle(1, -3.0, 30.0)};
  return s;
}

Trace ego_brakes_from(const Scenario& s, double from_s) {
  Trace t = constant_accel_trace(s, 1.5);
  for (auto& st : t.steps) {
    const double b = std::max(0.0, st.time_s - from_s);
    st.ego.accel_mps2 = st.time_s >= from_s - 1e-9 ? -4.0 : 0.0;
    st.ego.vx_mps = 20.0 - 4.0 * b;
    st.ego.x_m = 20.0 * st.time_s - 2.0 * b * b;
  }
  return t;
}

TEST(RssLongitudinalMonitor, AVehicleThatBecomesTheRearMidEpisodeHasItsOwnResponseTime) {
  const Scenario s = overtaken_beside();
  EXPECT_TRUE(test::run(monitor_rss_longitudinal, s, ego_brakes_from(s, 0.6)).result.holds);
  const MonitorOutput late = test::run(monitor_rss_longitudinal, s, ego_brakes_from(s, 1.0));
  ASSERT_FALSE(late.result.holds);
  EXPECT_EQ(late.result.liable_id, kEgoId);
  EXPECT_NEAR(*late.result.first_violation_time_s, 0.8, 0.021);
}

// The ego moves left at 1 m/s beside vehicle 1 (same X: longitudinally unsafe). With the ego
// as the right vehicle: v_R = 1, v_R,rho = 1 + 0.5*0.2 = 1.1, d_R = -(1 + 1.1)/2*0.5 - 1.1^2/1.6
// = -1.28125; v_L = 0, v_L,rho = -0.1, d_L = 0.025 + 0.1^2/1.6 = 0.03125;
// D_lat = 0.1 + 1.9 + 1.3125 = 3.3125 m. dy = 3.5 - t: dangerous from t_b = 0.2 s.
Scenario side_by_side() {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, 0.0, 20.0)};
  return s;
}

Trace lateral_trace(const Scenario& s, bool respond) {
  Trace t = constant_accel_trace(s, 2.0);
  double vy = 1.0, y = s.ego.y_m;
  for (auto& st : t.steps) {
    st.ego.y_m = y;
    st.ego.vy_mps = vy;
    if (respond && st.time_s >= 0.7 - 1e-9) vy = std::max(0.0, vy - 1.0 * 0.02);  // 1 m/s2 >= b_lat,min
    y += vy * 0.02;
  }
  return t;
}

TEST(RssLateralMonitor, EgoWithoutRightOfWayThatKeepsMovingTowardIsLiable) {
  // After t_b + T = 0.7 s the allowed lateral speed is 1 - 0.8 (t - 0.7) + 0.2 (tolerance):
  // below 1 m/s from t = 0.96 s on, so the breach is at t = 0.96 s with dy = 3.5 - 0.96 =
  // 2.54 m: margin 2.54 - 3.3125 = -0.7725 m.
  const Scenario s = side_by_side();
  const MonitorOutput out = test::run(monitor_rss_lateral, s, lateral_trace(s, false));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, kEgoId);
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.96, 0.021);
  EXPECT_NEAR(out.margin[48], -0.7725, 1e-6);  // step 48: t = 0.96 s
  // The worst moment is the last step with the ego still outside vehicle 1's lane (|dy| >= W/2 =
  // 1.75 m), t = 1.74 s: dy = 1.76 m, margin 1.76 - 3.3125 = -1.5525 m.
  EXPECT_NEAR(out.result.min_margin, -1.5525, 1e-6);
}

TEST(RssLateralMonitor, AnEgoCentringItselfInTheLaneOfAVehicleBehindIsJudgedLongitudinally) {
  // The ego's centre is in lane 0 (Y = -0.3), still moving toward its centre at 0.1 m/s, with
  // vehicle 1 approaching from 5 m behind (longitudinally unsafe) and no right of way: not a
  // lateral approach (rss_longitudinal judges the pair).
  Scenario s = base_scenario();
  s.ego.y_m = -0.3;
  s.vehicles = {vehicle(1, -5.0, 25.0)};
  Trace t = constant_accel_trace(s, 2.0);
  for (auto& st : t.steps) st.ego.vy_mps = 0.1;
  const MonitorOutput out = test::run(monitor_rss_lateral, s, t);
  EXPECT_TRUE(out.result.holds);
  for (const double m : out.margin) EXPECT_TRUE(std::isnan(m));  // not applicable at any step
}

TEST(RssLateralMonitor, LateralBrakingAfterResponseTimeHolds) {
  const Scenario s = side_by_side();
  const MonitorOutput out = test::run(monitor_rss_lateral, s, lateral_trace(s, true));
  EXPECT_TRUE(out.result.holds);
  // Before t_b the margin is dy - D_lat = 3.5 - 3.3125 = 0.1875 m at t = 0; afterwards 0.
  EXPECT_NEAR(out.result.min_margin, 0.0, 1e-12);
}

}  // namespace
}  // namespace mg
