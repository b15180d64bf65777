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
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
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
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.0, 1e-9);
}

TEST(RssLongitudinalMonitor, FrontBrakingBeyondBmaxIsLiable) {
  // Vehicle 2 brakes at 9 > b_max 8 m/s2 from t = 0 with a safe 50 m gap; as the gap shrinks
  // below D_lon the front is liable even though the rear brakes at b_min after T.
  const Scenario s = two_in_lane(50.0);
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, constant_accel_trace(s, 3.0, {0.0, 0.0, -9.0}));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(2));
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
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.8, 1e-9);
}

TEST(RssLongitudinalMonitor, AnEgoMovingTowardALongitudinallyUnsafeVehicleCutsIn) {
  const Scenario s = off_centre_beside_rear_vehicle();
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, stop_moving_away_trace(s, 0.1));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.3, 1e-9);
}

// Vehicle 1 drives 42 m behind the ego (both 20 m/s): longitudinally unsafe throughout (D_lon
// 45.175 m). With a speed limit of 22 m/s Definition 1 never holds: ahead of it ineq. (1.1) needs
// 64.925 m, behind it (1.2) at v_e* = 0 fails by -42 + 40 - 4.8 = -6.8 m. The ego requests a Def. 2 merge at t = 0 and vehicle
// 1's acceptance reaches it at 0.1 s: its first attempt (out at 0.5 m/s for 0.4 s, to Y = -3.3,
// laterally safe; back at 0.5 m/s) holds the right of way from 0.1 s until it is seen aborted
// back on the side-lane centre (Y < -3.45, t = 0.92 s). From `resume_s` it moves toward the main
// lane at 1.2 m/s: D_lat = 0.1 + 1.9 + (1.2 + 1.3)/2 * 0.5 + 1.3^2/1.6 = 3.68 m > 3.5 m, dangerous
// from t_b = resume_s: a new attempt, on the acceptance while it binds vehicle 1 (until 0 + rho_c +
// rho_m = 5 s), after that without the right of way.
Scenario abort_scenario() {
  Scenario s = base_scenario();
  s.road.speed_limit_mps = 22.0;
  s.vehicles = {vehicle(1, -42.0, 20.0)};
  return s;
}

Trace abort_then_resume(const Scenario& s, double resume_s) {
  Trace t = constant_accel_trace(s, std::max(2.5, resume_s + 0.9));
  double y = s.ego.y_m;
  for (auto& st : t.steps) {
    const double tt = st.time_s + 1e-9;
    st.ego.vy_mps = tt < 0.2 ? 0.0 : tt < 0.6 ? 0.5 : tt < 1.0 ? -0.5 : tt < resume_s ? 0.0 : 1.2;
    st.ego.y_m = std::min(y, 0.0);
    y = std::max(y + st.ego.vy_mps * 0.02, tt < resume_s ? -3.5 : -10.0);
  }
  const TraceEvent accept = test::message_event(0.05, MessageType::kAccept, 1, 0, CoopCase::kEgoAhead, 40, 30, 18);
  t.events = {test::message_event(0.0, MessageType::kRequest, 0, 1, CoopCase::kEgoAhead, 40, 30, 18), accept,
              test::delivered_event(accept, 0.1)};
  return t;
}

TEST(RssLongitudinalMonitor, AnEgoThatAbortedWithinTheResponseTimeHasNotCutIn) {
  // Resuming at t_b = 1.2 s: the ego held the right of way until 0.92 s, within T = 0.5 s of t_b,
  // so its lateral motion is no cut-in; vehicle 1, the rear vehicle, owes b_min from t_b + T.
  const Scenario s = abort_scenario();
  const Trace t = abort_then_resume(s, 1.2);
  const auto judged = test::judge(s, t);
  ASSERT_EQ(judged->phases.count(MergePhaseKind::kAbort), 1);
  ASSERT_EQ(judged->attempts.attempts.front().basis, RowBasis::kDef2);
  const MonitorOutput out = test::run(monitor_rss_longitudinal, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
  EXPECT_NEAR(*out.result.first_violation_time_s, 1.7, 0.021);
  // Resuming at 1.6 s, more than T after the abort, on the acceptance still in force: no cut-in.
  const MonitorOutput again = test::run(monitor_rss_longitudinal, s, abort_then_resume(s, 1.6));
  ASSERT_FALSE(again.result.holds);
  EXPECT_EQ(again.result.liable_id, Party::vehicle(1));
  // Resuming at 5.6 s, once the acceptance no longer binds vehicle 1: a cut-in, the ego liable
  // from the step at which it is again past its lane centre by the start offset (0.1 s later).
  const MonitorOutput late = test::run(monitor_rss_longitudinal, s, abort_then_resume(s, 5.6));
  ASSERT_FALSE(late.result.holds);
  EXPECT_EQ(late.result.liable_id, Party::ego());
  EXPECT_NEAR(*late.result.first_violation_time_s, 5.7, 0.021);
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
  EXPECT_EQ(late.result.liable_id, Party::ego());
  EXPECT_NEAR(*late.result.first_violation_time_s, 0.8, 0.021);
}

// The ego moves left at 1 m/s beside vehicle 1 (same X: longitudinally unsafe). With the ego
// as the right vehicle: v_R = 1, v_R,rho = 1 + 0.5*0.2 = 1.1, d_R = -(1 + 1.1)/2*0.5 - 1.1^2/1.6
// = -1.28125; v_L = 0, v_L,rho = -0.1, d_L = 0.025 + 0.1^2/1.6 = 0.03125;
// D_lat = 0.1 + 1.9 + 1.3125 = 3.3125 m. dy = 3.5 - t: dangerous from t_b = 0.2 s.
// The ego is seen merging but has no right of way: vehicle 2, 41 m behind in the lane, leaves no
// Definition 1 gap (behind vehicle 1 ineq. (1.1) toward vehicle 2 needs v_e* >= 27 m/s, at which
// (1.2) toward vehicle 1 fails; ahead of vehicle 1 (1.1) fails at every v_e* up to the 33.34 m/s
// limit; behind vehicle 2 (1.2) fails at v_e* = 0 by -41 + 40 - 4.8 m), and no acceptance.
Scenario side_by_side() {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, 0.0, 20.0), vehicle(2, -41.0, 20.0)};
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
  EXPECT_EQ(out.result.liable_id, Party::ego());
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

// The ego at X = 0 in the side lane with a weak lateral brake (0.1 m/s2); vehicle 1 beside it in
// the next lane over (lane 1, Y = 3.5), two main lanes.
Scenario merge_beside_next_lane() {
  Scenario s = base_scenario();
  s.road.main_lanes = 2;
  s.ego.limits.lat_brake_min_mps2 = 0.1;
  s.vehicles = {vehicle(1, 0.0, 20.0)};
  s.vehicles[0].lane = 1;
  return s;
}

// The right of way waives the lateral duty for the merge's own motion only. The ego merges into
// an empty rightmost lane (it holds the right of way by Definition 1) at 1 m/s laterally with a
// weak lateral brake (0.1 m/s2), beside vehicle 1 in the next lane over (Y = 3.5): D_lat exceeds
// their distance from the start. Up to the lane's centre (Y = 0, t = 3.5 s) that is the merge;
// the ego that keeps moving left beyond it owes vehicle 1 its lateral response: from 3.5 s, with
// T = 0.5 s to start braking (judged here with a speed tolerance of 0.05 m/s, so that not braking
// shows at 4.5 s, before the ego's centre reaches vehicle 1's lane at 5.25 s).
TEST(RssLateralMonitor, TheRightOfWayWaivesTheLateralDutyOnlyUpToTheTargetLanesCentre) {
  Scenario s = merge_beside_next_lane();
  const auto moving_left_for = [&](double duration_s) {
    Trace t = constant_accel_trace(s, duration_s);
    for (auto& st : t.steps) {
      st.ego.y_m = s.ego.y_m + 1.0 * st.time_s;
      st.ego.vy_mps = 1.0;
    }
    return t;
  };
  const auto merge = test::judge(s, moving_left_for(3.4));
  EXPECT_TRUE(merge->row.ego_holds_at(1.0));
  EXPECT_TRUE(monitor_rss_lateral(merge->context()).result.holds);
  s.params.rules.speed_tolerance_mps = 0.05;
  const auto beyond = test::judge(s, moving_left_for(5.0));
  const MonitorOutput out = monitor_rss_lateral(beyond->context());
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_GE(*out.result.first_violation_time_s, 4.5 - 1e-9);
}

// The same merge, the ego crossing the lane's centre at 3.5 s at 1 m/s: its lateral duty toward
// vehicle 1 begins there, so it has the response time T = 0.5 s from then, and braking laterally
// at its b_lat_min (0.1 m/s2) from 4 s on answers it, although the lateral danger began at t = 0
// (a campaign finding: counted from t = 0, the ego was "1 s late" the moment its merge ended).
TEST(RssLateralMonitor, ADutyThatBeginsAtTheLanesCentreHasItsResponseTimeFromThere) {
  Scenario s = merge_beside_next_lane();
  Trace t = constant_accel_trace(s, 6.0);
  for (auto& st : t.steps) {
    const double braking_s = std::max(0.0, st.time_s - 4.0);
    st.ego.vy_mps = 1.0 - 0.1 * braking_s;
    st.ego.y_m = s.ego.y_m + std::min(st.time_s, 4.0) + braking_s - 0.05 * braking_s * braking_s;
  }
  const auto j = test::judge(s, t);
  ASSERT_TRUE(j->row.ego_holds_at(1.0));
  const MonitorOutput out = monitor_rss_lateral(j->context());
  EXPECT_TRUE(out.result.holds) << out.result.detail;
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
