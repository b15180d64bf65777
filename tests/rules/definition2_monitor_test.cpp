#include "rules/definition2_monitor.h"

#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include "rules/definition1_monitor.h"

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::message_event;
using test::vehicle;

// The ego (X = 0, 20 m/s) and vehicle 1 (X = -25 m, 20 m/s); rho_c = 1 s, T = 0.5 s.
Scenario coop_scenario() {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -25.0, 20.0)};
  return s;
}

// Request at t = 0 (Def. 2.1, v_o* = 16 m/s), acceptance sent at t = 0.1 s.
Trace with_exchange(Trace t, CoopCase c, double target, double d_star = 30.0, double pc = 50.0) {
  t.events.push_back(message_event(0.0, MessageType::kRequest, 0, 1, c, pc, d_star, target));
  t.events.push_back(message_event(0.1, MessageType::kAccept, 1, 0, c, pc, d_star, target));
  return t;
}

TEST(Def2Monitor, RequestMarginIsTheSmallerOfPcAheadAndDstarOverContact) {
  // P_c 50 m ahead of the ego at X = 0; D*_lon = 30 m against contact (4.8 + 4.8)/2 = 4.8 m:
  // margin = min(50, 25.2) = 25.2 m. With D*_lon = 3 m: 3 - 4.8 = -1.8 m, the ego liable.
  const Scenario s = coop_scenario();
  const MonitorOutput ok = test::run(monitor_def2_1a_request, s, with_exchange(constant_accel_trace(s, 1.0), CoopCase::kEgoAhead, 16.0));
  EXPECT_NEAR(ok.result.min_margin, 25.2, 1e-9);
  const MonitorOutput bad =
      test::run(monitor_def2_1a_request, s, with_exchange(constant_accel_trace(s, 1.0), CoopCase::kEgoAhead, 16.0, 3.0));
  ASSERT_FALSE(bad.result.holds);
  EXPECT_EQ(bad.result.liable_id, Party::ego());
  EXPECT_NEAR(bad.result.min_margin, -1.8, 1e-9);
}

TEST(Def2Monitor, ResponderThatAcceptsAndDoesNotYieldIsLiable) {
  // Vehicle 1 keeps 20 m/s. From t_r + rho_c + T = 1.5 s it must be at most v_o* + 0.5 =
  // 16.5 m/s: margin 16.5 - 20 = -3.5 m/s at t = 1.5 s.
  const Scenario s = coop_scenario();
  const MonitorOutput out =
      test::run(monitor_def2_1b_responder, s, with_exchange(constant_accel_trace(s, 3.0), CoopCase::kEgoAhead, 16.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
  EXPECT_NEAR(*out.result.first_violation_time_s, 1.5, 1e-9);
  EXPECT_NEAR(out.result.min_margin, -3.5, 1e-9);
}

TEST(Def2Monitor, ResponderBrakingAtBminToTargetHolds) {
  // Vehicle 1 brakes at b_min = 4 from t = 0.1 s: v = 20 - 4 (t - 0.1) equals the rate floor, so
  // the margin is the 0.2 m/s tolerance until it reaches v_o* + 0.2 (t = 1.05 s); it then stays
  // at 16 m/s: yield margin 16.5 - 16 = 0.5 m/s.
  const Scenario s = coop_scenario();
  Trace t = constant_accel_trace(s, 3.0);
  for (auto& st : t.steps) {
    const double v = std::max(16.0, 20.0 - 4.0 * std::max(0.0, st.time_s - 0.1));
    st.others[0].vx_mps = v;
  }
  const MonitorOutput out = test::run(monitor_def2_1b_responder, s, with_exchange(t, CoopCase::kEgoAhead, 16.0));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 0.2, 1e-9);
}

TEST(Def2Monitor, EgoBrakingHarderThanBminAfterA22RequestIsLiable) {
  // The ego brakes at 5 > b_min 4 m/s2: at t = rho_c = 1 s, v = 15, floor = 16:
  // margin 15 - 16 + 0.2 = -0.8 m/s. At 4 m/s2 the margin stays at the 0.2 m/s tolerance.
  const Scenario s = coop_scenario();
  const MonitorOutput bad =
      test::run(monitor_def2_2a_ego_brake, s, with_exchange(constant_accel_trace(s, 2.0, {-5.0, 0.0}), CoopCase::kEgoBehind, 22.0));
  ASSERT_FALSE(bad.result.holds);
  EXPECT_EQ(bad.result.liable_id, Party::ego());
  EXPECT_NEAR(bad.result.min_margin, -0.8, 1e-9);
  const MonitorOutput ok =
      test::run(monitor_def2_2a_ego_brake, s, with_exchange(constant_accel_trace(s, 2.0, {-4.0, 0.0}), CoopCase::kEgoBehind, 22.0));
  EXPECT_TRUE(ok.result.holds);
  EXPECT_NEAR(ok.result.min_margin, 0.2, 1e-9);
}

// A refusal of the request of t = 0 delivered to the ego at `time_s`.
TraceEvent refusal_delivered(double time_s) {
  TraceEvent e = message_event(time_s, MessageType::kRefuse, 1, 0, CoopCase::kEgoBehind, 50, 30, 22);
  e.kind = EventKind::kMessageDelivered;
  return e;
}

TEST(Def2Monitor, EgoBrakingHarderThanBminAfterARefusalOfItsA22RequestHolds) {
  // Coasting until the refusal is delivered at t = 0.3 s, then braking at 7 > b_min 4 m/s2 (Def.
  // 2.3 sends the ego back to Definition 1, which may halt it). A window running to rho_c = 1 s
  // regardless would give v(1 s) = 20 - 7 * 0.7 = 15.1 < floor 16, margin -0.7 m/s. Judged up
  // to the refusal, the ego kept its speed: the smallest margin is the tolerance, at t = 0.
  const Scenario s = coop_scenario();
  Trace t = constant_accel_trace(s, 2.0);
  for (auto& st : t.steps) st.ego.vx_mps = 20.0 - 7.0 * std::max(0.0, st.time_s - 0.3);
  t.events.push_back(message_event(0.0, MessageType::kRequest, 0, 1, CoopCase::kEgoBehind, 50, 30, 22));
  const MonitorOutput old_window = test::run(monitor_def2_2a_ego_brake, s, t);
  ASSERT_FALSE(old_window.result.holds);  // no refusal: the window runs to rho_c
  EXPECT_NEAR(old_window.result.min_margin, -0.7, 1e-9);
  t.events.push_back(refusal_delivered(0.3));
  const MonitorOutput out = test::run(monitor_def2_2a_ego_brake, s, t);
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 0.2, 1e-9);
}

TEST(Def2Monitor, EgoBrakingHarderThanBminBeforeTheRefusalArrivesIsLiable) {
  // Braking at 6 m/s2 from t = 0, the refusal delivered at 0.5 s: at 0.5 s v = 17 < floor 18 -
  // 0.2, margin -0.8 m/s, before the window ends.
  const Scenario s = coop_scenario();
  Trace t = constant_accel_trace(s, 2.0, {-6.0, 0.0});
  t.events.push_back(message_event(0.0, MessageType::kRequest, 0, 1, CoopCase::kEgoBehind, 50, 30, 22));
  t.events.push_back(refusal_delivered(0.5));
  const MonitorOutput out = test::run(monitor_def2_2a_ego_brake, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -0.8, 1e-9);
}

TEST(Def2Monitor, EgoBrakingAsAnRssProperResponseAfterA22RequestHolds) {
  // Vehicle 1 is 20 m ahead of the ego in its lane, both at 20 m/s: a dangerous pair from t = 0
  // with the ego behind (D_lon is 45 m). The ego brakes at 6 m/s2, its RSS proper response
  // (at least b_min, at most b_max = 8): rss_longitudinal governs, not Def. 2.2A, which would
  // otherwise judge it (v = 14 against a floor of 16 at rho_c: margin -1.8 m/s).
  Scenario s = coop_scenario();
  s.vehicles[0].x_m = 20.0;
  Trace t = with_exchange(constant_accel_trace(s, 2.0, {-6.0, 0.0}), CoopCase::kEgoBehind, 22.0);
  for (auto& st : t.steps) st.others[0].y_m = st.ego.y_m;
  const MonitorOutput out = test::run(monitor_def2_2a_ego_brake, s, t);
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 0.2, 1e-9);  // only t = 0 is judged
  // The same braking with vehicle 1 in its own lane (no danger) is the ego's violation.
  Trace safe = with_exchange(constant_accel_trace(s, 2.0, {-6.0, 0.0}), CoopCase::kEgoBehind, 22.0);
  const MonitorOutput broke = test::run(monitor_def2_2a_ego_brake, s, safe);
  ASSERT_FALSE(broke.result.holds);
  EXPECT_EQ(broke.result.liable_id, Party::ego());
}

TEST(Def2Monitor, ResponderThatDoesNotSpeedUpForA22RequestIsLiable) {
  // v_o* = 24 m/s; vehicle 1 stays at 20: from 1.5 s the margin is 20 - (24 - 0.5) = -3.5 m/s.
  const Scenario s = coop_scenario();
  const MonitorOutput out =
      test::run(monitor_def2_2b_responder, s, with_exchange(constant_accel_trace(s, 3.0), CoopCase::kEgoBehind, 24.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
  EXPECT_NEAR(out.result.min_margin, -3.5, 1e-9);
}

// The ego seen moving toward the main lane from merge_time_s at 1.75 m/s (its start observed 0.06 s
// later). Vehicle 1 is moved 45 m behind, and with a speed limit of 22 m/s leaves no Definition 1
// gap: ahead of it ineq. (1.1) needs 64.925 m (definition1_monitor_test.cpp), behind it ineq. (1.2)
// at v_e* = 0 over rho/2 = 2 s fails by -45 + 20*2 - 4.8 = -9.8 m. Only an acceptance grants the merge.
Trace with_coop_merge(Trace t, double merge_time_s) { return test::with_lateral_move(std::move(t), merge_time_s, 1.75); }
Scenario coop_merge_scenario() {
  Scenario s = coop_scenario();
  s.vehicles[0].x_m = -45.0;
  s.road.speed_limit_mps = 22.0;
  return s;
}

TEST(Def2Monitor, CooperativeMergeNeedsAnAcceptanceWithinRhoC) {
  // P_c = 30 m: where the ego's centre crosses the lane line in the merge from 0.5 s (1.5 s at
  // 20 m/s); one it did not keep to would grant nothing (def2_request_truthful).
  const Scenario s = coop_merge_scenario();
  const TraceEvent request = message_event(0.0, MessageType::kRequest, 0, 1, CoopCase::kEgoAhead, 30, 30, 16);
  const TraceEvent accept = message_event(0.1, MessageType::kAccept, 1, 0, CoopCase::kEgoAhead, 30, 30, 16);
  // Request at 0, acceptance delivered at 0.3 s, merge from 0.5 s: margin 0 + 1 - 0.3 = 0.7 s.
  Trace ok = with_coop_merge(constant_accel_trace(s, 2.0), 0.5);
  ok.events = {request, accept, test::delivered_event(accept, 0.3)};
  const MonitorOutput held = test::run(monitor_def2_3_fallback, s, ok);
  EXPECT_TRUE(held.result.holds);
  EXPECT_NEAR(held.result.min_margin, 0.7, 1e-9);
  // The acceptance delivered at 1.4 s, after rho_c, and the merge from 1.5 s: margin 1 - 1.4 =
  // -0.4 s, the ego liable.
  Trace late = with_coop_merge(constant_accel_trace(s, 2.0), 1.5);
  late.events = {request, accept, test::delivered_event(accept, 1.4)};
  const MonitorOutput broke = test::run(monitor_def2_3_fallback, s, late);
  ASSERT_FALSE(broke.result.holds);
  EXPECT_EQ(broke.result.liable_id, Party::ego());
  EXPECT_NEAR(broke.result.min_margin, -0.4, 1e-9);
}

// Def. 2.3 judges an attempt that took room in the main lane: one aborted in the side lane after
// a late acceptance (out at 1 m/s for 0.5 s, never past the lane line) took nobody's, as for the
// Definition 1 gap rules.
TEST(Def2Monitor, AnAttemptAbortedInTheSideLaneOnALateAcceptanceIsNotDef23s) {
  const Scenario s = coop_merge_scenario();
  const TraceEvent request = message_event(0.0, MessageType::kRequest, 0, 1, CoopCase::kEgoAhead, 30, 30, 16);
  const TraceEvent accept = message_event(0.1, MessageType::kAccept, 1, 0, CoopCase::kEgoAhead, 30, 30, 16);
  Trace t = test::with_aborted_move(constant_accel_trace(s, 4.0), 1.5, 1.0, 0.5);
  t.events = {request, accept, test::delivered_event(accept, 1.4)};
  const auto j = test::judge(s, t);
  ASSERT_EQ(j->attempts.attempts.size(), 1u);
  ASSERT_TRUE(j->attempts.attempts[0].exchange.has_value());  // made on the late acceptance ...
  EXPECT_FALSE(j->attempts.attempts[0].entry_step.has_value());  // ... and never in the main lane
  const MonitorOutput out = test::run(monitor_def2_3_fallback, s, t);
  EXPECT_TRUE(out.result.holds);
  EXPECT_FALSE(std::isfinite(out.result.min_margin));
}

TEST(Def2Monitor, AMergeWithoutAnyAcceptanceIsDefinition1s) {
  // No acceptance at all: not a cooperative merge, so def2_3 does not apply; the ego merged
  // without the right of way and a def1 gap rule holds it liable: it entered the gap ahead of
  // vehicle 1, 45 m behind it at 20 m/s, where ineq. (1.1) fails at every v_e* up to the 22 m/s
  // speed limit.
  const Scenario s = coop_merge_scenario();
  Trace t = with_coop_merge(constant_accel_trace(s, 2.0), 0.5);
  t.events.push_back(message_event(0.0, MessageType::kRequest, 0, 1, CoopCase::kEgoAhead, 50, 30, 16));
  const MonitorOutput fallback = test::run(monitor_def2_3_fallback, s, t);
  EXPECT_TRUE(fallback.result.holds);
  EXPECT_FALSE(std::isfinite(fallback.result.min_margin));
  const MonitorOutput gap = test::run(monitor_def1_1_gap, s, t);
  ASSERT_FALSE(gap.result.holds);
  EXPECT_EQ(gap.result.liable_id, Party::ego());
  EXPECT_LT(gap.result.min_margin, -10.0);
}

TEST(Def2Monitor, AnAcceptanceDeliveredAtTheDeadlineItselfIsInTime) {
  // Run 60204 of the seed-1 campaign: the request at step 455 (t = 9.1 s), rho_c = 1.2 s, the
  // acceptance delivered at step 515 (t = 10.3 s). As trace times they differ from t_r + rho_c by
  // rounding, and the margin was -1.8e-15 s (the ego liable); the window is closed, so a tie
  // holds with margin 0. One step later (10.32 s) is late: margin -0.02 s. The ego is seen to
  // start merging right after the acceptance arrives.
  Scenario s = coop_merge_scenario();
  s.params.rules.comm_threshold_s = 1.2;
  const auto traced = [&](double accept_time_s) {
    Trace t = with_coop_merge(constant_accel_trace(s, 11.0), accept_time_s);
    const double t_r = t.steps[455].time_s;
    t.events.push_back(message_event(t_r, MessageType::kRequest, 0, 1, CoopCase::kEgoAhead, 50, 30, 16));
    TraceEvent delivered = message_event(accept_time_s, MessageType::kAccept, 1, 0, CoopCase::kEgoAhead, 50, 30, 16);
    delivered.kind = EventKind::kMessageDelivered;
    t.events.push_back(delivered);
    return t;
  };
  const Trace on_time = traced(constant_accel_trace(s, 11.0).steps[515].time_s);
  ASSERT_LT(on_time.steps[455].time_s + 1.2 - on_time.steps[515].time_s, 0.0);  // the rounding of the finding
  const MonitorOutput held = test::run(monitor_def2_3_fallback, s, on_time);
  EXPECT_TRUE(held.result.holds);
  EXPECT_EQ(held.result.min_margin, 0.0);
  const MonitorOutput late = test::run(monitor_def2_3_fallback, s, traced(constant_accel_trace(s, 11.0).steps[516].time_s));
  ASSERT_FALSE(late.result.holds);
  EXPECT_EQ(late.result.liable_id, Party::ego());
  EXPECT_NEAR(late.result.min_margin, -0.02, 1e-9);
}

}  // namespace
}  // namespace mg
