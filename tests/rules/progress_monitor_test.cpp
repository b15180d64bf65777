#include "rules/progress_monitor.h"
#include "rules/definition2_inequalities.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

TEST(ProgressMonitor, HaltingOnAnEmptyRoadIsNeedless) {
  // No main-lane traffic: any v_e* is feasible. The ego stands at X = 100 for 5 s: the
  // needless halt exceeds the 3 s grace at t = 3.02 s; worst margin 3 - 5 = -2 s.
  Scenario s = base_scenario();
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 0.0;
  const MonitorOutput out = test::run(monitor_progress, s, constant_accel_trace(s, 5.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(*out.result.first_violation_time_s, 3.02, 1e-9);
  EXPECT_NEAR(out.result.min_margin, -2.0, 1e-9);
}

TEST(ProgressMonitor, AnApproachTheTraceEndsBeforeItsStartIsNotJudged) {
  // An empty road, the ego at 20 m/s (rho_b = rho_m = 4 s): it waits 2.5 s, then moves toward the
  // main lane at 0.05 m/s, below lat_speed_hysteresis_mps, so no start is observed before the
  // trace ends at 6 s. The approach may lead into a start the trace does not show: its last
  // rho_b (all of it here) pauses the clock, and the 2.5 s waited are within the grace. Without
  // the approach the ego waits 6 s and fails.
  Scenario s = base_scenario();
  const Trace straight = constant_accel_trace(s, 6.0);
  EXPECT_TRUE(test::run(monitor_progress, s, test::with_lateral_move(straight, 2.5, 0.05)).result.holds);
  const MonitorOutput out = test::run(monitor_progress, s, straight);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
}

TEST(ProgressMonitor, AnApproachFromBelowTheSideLaneCentreIsNotJudgedWhileItIsFasterThanDrift) {
  // As above, but the ego starts 0.5 m below its side lane's centre (beyond the main lane's
  // side) and moves toward the main lane from t = 2.5 s: at 0.12 m/s it is still below the
  // centre when the trace ends at 6 s, moving faster than lat_speed_hysteresis_mps, and its
  // approach pauses the clock. At 0.05 m/s (an ego settling on its centre moves so) the approach
  // does not, and the 6 s waited fail.
  Scenario s = base_scenario();
  const auto from_below = [&](double vy_mps) {
    Trace t = test::with_lateral_move(constant_accel_trace(s, 6.0), 2.5, vy_mps);
    for (TraceStep& st : t.steps) st.ego.y_m -= 0.5;
    return t;
  };
  EXPECT_LT(from_below(0.12).steps.back().ego.y_m, -3.5);
  EXPECT_TRUE(test::run(monitor_progress, s, from_below(0.12)).result.holds);
  const MonitorOutput out = test::run(monitor_progress, s, from_below(0.05));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
}

TEST(ProgressMonitor, AnApproachUnderWayWhenAVehicleBreaksItsLimitsIsNotJudgedUpToThatStep) {
  // An empty target lane at 20 m/s (every gap open from t = 0); vehicle 1 drives in the lane
  // beyond, 300 m ahead. The ego moves toward the main lane at 0.05 m/s (no start an observer
  // sees) from 0.5 s to 4.5 s, then back. At 4.4 s vehicle 1 is seen braking at 9 m/s2, beyond
  // its declared 8: the approach up to then pauses the clock (the ego dropping a merge that
  // rested on the declared limits is responding to the breach), and the 0.5 s before it and the
  // 1.6 s after it stay within the grace. Without the breach the approach leads into no start and
  // the clock runs from t = 0: it fails at 3.02 s.
  Scenario s = base_scenario();
  MainVehicle beyond = vehicle(1, 300.0, 20.0);
  beyond.lane = 1;
  s.road.main_lanes = 2;
  s.vehicles = {beyond};
  const Trace steady = test::with_aborted_move(constant_accel_trace(s, 6.0), 0.5, 0.05, 4.0);
  const MonitorOutput waited = test::run(monitor_progress, s, steady);
  ASSERT_FALSE(waited.result.holds);
  EXPECT_NEAR(*waited.result.first_violation_time_s, 3.02, 1e-9);
  Trace breach = steady;
  for (TraceStep& st : breach.steps)
    if (std::abs(st.time_s - 4.4) < 1e-9) st.others[0].accel_mps2 = -9.0;
  EXPECT_TRUE(test::run(monitor_progress, s, breach).result.holds);
}

TEST(ProgressMonitor, AnApproachDroppedOnceNoMergeIsOfferedIsNotJudged) {
  // The ego stands at X = 100 with vehicle 1 driving away ahead at 20 m/s (merging behind it is
  // offered from t = 0) and moves toward the main lane at 0.05 m/s (no start an observer sees)
  // from 0.5 s to 4.5 s, then back. Vehicle 1 holding its speed, the approach is dropped while the
  // merge is still offered, and the clock runs over it: it fails at 3.02 s. Vehicle 1 braking at
  // 1 m/s2 from 4.4 s (harder than Def. 1.2 assumes) has withdrawn the offer by the drop: the
  // approach was a merge dropped for that reason and pauses the clock; the 0.5 s before it are
  // within the grace, and nothing is offered after it.
  Scenario s = base_scenario();
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 0.0;
  s.vehicles = {vehicle(1, 160.0, 20.0)};
  const Trace steady = test::with_aborted_move(constant_accel_trace(s, 6.0), 0.5, 0.05, 4.0);
  const MonitorOutput kept = test::run(monitor_progress, s, steady);
  ASSERT_FALSE(kept.result.holds);
  EXPECT_EQ(kept.result.liable_id, Party::ego());
  EXPECT_NEAR(*kept.result.first_violation_time_s, 3.02, 1e-9);
  Trace braking = steady;
  for (TraceStep& st : braking.steps) {
    const double dt = st.time_s - 4.4;
    if (dt < -1e-9) continue;
    st.others[0].x_m -= 0.5 * dt * dt;
    st.others[0].vx_mps -= dt;
    st.others[0].accel_mps2 = -1.0;
  }
  const MonitorOutput dropped = test::run(monitor_progress, s, braking);
  EXPECT_TRUE(dropped.result.holds) << dropped.result.detail;
}

TEST(ProgressMonitor, OnlyTheLastRhoBOfAnApproachThatNeverStartsPausesTheClock) {
  // The same road; the ego drifts toward the main lane at 0.05 m/s from the start of an 8 s
  // trace and never starts a merge: only the last rho_b (4 s) of its approach pauses the clock,
  // and it waited the 4 s before, 1 s beyond the grace. A drift that never merges is no merge
  // under way.
  Scenario s = base_scenario();
  const MonitorOutput out =
      test::run(monitor_progress, s, test::with_lateral_move(constant_accel_trace(s, 8.0), 0.0, 0.05));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(*out.result.first_violation_time_s, 3.02, 1e-9);
}

TEST(ProgressMonitor, HaltingBesideADensePlatoonIsNotNeedless) {
  // Vehicles every 45.5 m at 20 m/s (just RSS-safe for them, far too tight for the ego, which
  // needs about 90 m) pass the halted ego: no gap is feasible, the halt is justified and the
  // margin stays at the 3 s grace.
  Scenario s = base_scenario();
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 0.0;
  for (int i = 0; i < 8; ++i) s.vehicles.push_back(vehicle(i + 1, 200.0 - 45.5 * i, 20.0));
  const MonitorOutput out = test::run(monitor_progress, s, constant_accel_trace(s, 4.0));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 3.0, 1e-12);
}

TEST(ProgressMonitor, HaltingWhileAVehicleDrivesAwayAheadIsNeedless) {
  // The ego stands at X = 100; vehicle 1 drives away at 20 m/s from X = 160: merging behind it
  // is feasible (a drivable sigmoid, clear of it), so the halt is needless after the 3 s grace.
  Scenario s = base_scenario();
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 0.0;
  s.vehicles = {vehicle(1, 160.0, 20.0)};
  const MonitorOutput out = test::run(monitor_progress, s, constant_accel_trace(s, 5.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_NE(out.result.detail.find("leader 1"), std::string::npos) << out.result.detail;
}

TEST(ProgressMonitor, ABrakingLeaderOffersNoGap) {
  // The same, but vehicle 1 brakes at 1 m/s^2 (> progress_leader_braking_mps2): Def. 1.2 assumes
  // it holds its speed, so the gap behind it does not count and the halt is justified.
  Scenario s = base_scenario();
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 0.0;
  s.vehicles = {vehicle(1, 160.0, 20.0)};
  const MonitorOutput out = test::run(monitor_progress, s, constant_accel_trace(s, 5.0, {0.0, -1.0}));
  EXPECT_TRUE(out.result.holds);
}

TEST(ProgressMonitor, AMovingEgoThatNeverMergesIsJudgedToo) {
  // At 20 m/s on an empty road, every gap is open from t = 0: keeping the side lane lets the
  // right of way pass, at any speed; the grace ends at t = 3.02 s.
  const Scenario s = base_scenario();
  const MonitorOutput out = test::run(monitor_progress, s, constant_accel_trace(s, 4.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(*out.result.first_violation_time_s, 3.02, 1e-9);
  EXPECT_NE(out.result.detail.find("let the right of way pass"), std::string::npos) << out.result.detail;
}

TEST(ProgressMonitor, AnEgoMergingWithinTheGraceIsNotJudged) {
  // The same, but the ego moves toward the main lane at 1 m/s from t = 1 s: its body reaches into
  // the main lane at t ~ 1.8 s, its merge resets the clock.
  const Scenario s = base_scenario();
  const MonitorOutput out = test::run(monitor_progress, s, test::with_lateral_move(constant_accel_trace(s, 6.0), 1.0, 1.0));
  EXPECT_TRUE(out.result.holds) << out.result.detail;
}

TEST(ProgressMonitor, WaitingForAGapTheEgoThenMergesIntoIsNotLettingItPass) {
  // The ego stands at X = 100 while the gap behind vehicle 1 (driving away at 20 m/s from X = 160)
  // is feasible from t = 0, and merges into it from t = 5 s: it took the gap after a 5 s wait,
  // longer than the grace. The wait is reported, not judged.
  Scenario s = base_scenario();
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 0.0;
  s.vehicles = {vehicle(1, 160.0, 20.0)};
  const MonitorOutput out = test::run(monitor_progress, s, test::with_lateral_move(constant_accel_trace(s, 12.0), 5.0, 1.0));
  EXPECT_TRUE(out.result.holds) << out.result.detail;
  double waited_s = 0.0;
  for (const auto& [name, value] : out.result.measures)
    if (name == "longest_wait_for_taken_s") waited_s = value;
  EXPECT_GT(waited_s, 4.5);
}

TEST(ProgressMonitor, AMergeIntoTheGapThatIsAbortedDidNotTakeIt) {
  // The same wait, but the merge's body enters the main lane (its centre 2 m out of 3.5) and it
  // turns back: the gap was let pass, and the wait before the attempt fails the rule at the end
  // of the grace.
  Scenario s = base_scenario();
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 0.0;
  s.vehicles = {vehicle(1, 160.0, 20.0)};
  const MonitorOutput out = test::run(monitor_progress, s, test::with_aborted_move(constant_accel_trace(s, 12.0), 5.0, 1.0, 1.5));
  ASSERT_FALSE(out.result.holds) << out.result.detail;
  EXPECT_NEAR(*out.result.first_violation_time_s, 3.02, 1e-9);
}

TEST(ProgressMonitor, AnEgoTooCloseToTheEndToTurnInIsNotJudged) {
  // At rest 10 m before the side lane's end: a path within the sideslip bound needs more than
  // that to reach the lane line, so no gap is offered however empty the road.
  Scenario s = base_scenario();
  s.ego.x_m = s.road.side_lane_end_x_m - 10.0 - 2.4;
  s.ego.speed_mps = 0.0;
  const MonitorOutput out = test::run(monitor_progress, s, constant_accel_trace(s, 5.0));
  EXPECT_TRUE(out.result.holds) << out.result.detail;
}


TEST(ProgressMonitor, AMergeThatWouldLeaveTheRoadPastTheSideLaneEndIsNotOffered) {
  // At rest, its front 30 m before the side lane's end, on an empty road: a merge (at
  // a_accel^max) reaches its midpoint past the turn-in (18.7 m) with the front 11 m short of the
  // end, but the rear of the body is still in the side lane when the front comes within
  // progress_gap_margin_m of the end, where the road's edge is the lane line (on_road). No merge
  // gets the whole body across in time, so none is offered (without this condition one would be,
  // from about 24 m); 4 m farther back one is.
  Scenario s = base_scenario();
  s.ego.x_m = s.road.side_lane_end_x_m - 30.0 - 2.4;
  s.ego.speed_mps = 0.0;
  EXPECT_TRUE(test::run(monitor_progress, s, constant_accel_trace(s, 5.0)).result.holds);
  s.ego.x_m -= 4.0;
  const MonitorOutput out = test::run(monitor_progress, s, constant_accel_trace(s, 5.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
}

TEST(ProgressMonitor, AVehicleOfTheLaneBeyondIsKeptBehindWhereItsLegalBrakingWouldPutIt) {
  // Two main lanes; the ego at 20 m/s with a weak lateral brake (0.4 m/s2: D_lat reaches across a
  // lane while it merges), a target-lane vehicle 70 m behind it at 20 m/s (the ego must merge at
  // about its own speed, ahead of it), and a vehicle of the lane beyond 90 m ahead at 20 m/s. At
  // its observed speed that vehicle stays 90 m ahead, clear of D_lon (40.4 m) plus the margin; but
  // braking at its b_max (8 m/s2) from now it stops 25 m on, and the ego, near it laterally in
  // mid-merge, would be inside its D_lon and owe an RSS response: no merge is offered. 400 m
  // ahead it leaves the merge clear, and waiting fails the rule.
  Scenario s = base_scenario();
  s.road.main_lanes = 2;
  s.ego.x_m = 100.0;
  s.ego.limits.lat_brake_min_mps2 = 0.4;
  MainVehicle beyond = vehicle(2, 190.0, 20.0);
  beyond.lane = 1;
  s.vehicles = {vehicle(1, 30.0, 20.0), beyond};
  EXPECT_TRUE(test::run(monitor_progress, s, constant_accel_trace(s, 5.0)).result.holds);
  s.vehicles[1].x_m = 500.0;
  const MonitorOutput out = test::run(monitor_progress, s, constant_accel_trace(s, 5.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_NE(out.result.detail.find("follower 1, leader open"), std::string::npos) << out.result.detail;
}

// A cooperative merge on offer: the ego at 15 m/s in the side lane beside a platoon at 20 m/s
// with vehicles every 45.5 m (no Definition 1 gap: HaltingBesideADensePlatoonIsNotNeedless),
// 22.5 m ahead of vehicle 4 and 23 m behind vehicle 3. At t = 0 it asks vehicle 4 to drop to
// 12 m/s (Def. 2.1, the ego ahead); the acceptance arrives at 0.1 s and is in force until
// t_r + rho_c + rho_m = 5 s. Vehicle 3, ahead of the partner, leaves room: the ego falls back
// from it. The ego never moves toward the main lane.
Scenario coop_offer_scenario() {
  Scenario s = base_scenario();
  s.ego.x_m = 86.0;
  s.ego.speed_mps = 15.0;
  for (int i = 0; i < 8; ++i) s.vehicles.push_back(vehicle(i + 1, 200.0 - 45.5 * i, 20.0));
  return s;
}

// The trace of coop_offer_scenario over 6 s, with vehicle `id` (index id) driven by `speed_at`
// (its speed at time t) instead of at constant speed.
Trace coop_offer_trace(const Scenario& s, int id, const std::function<double(double)>& speed_at) {
  Trace t = constant_accel_trace(s, 6.0);
  const std::size_t k = static_cast<std::size_t>(id - 1);
  for (std::size_t i = 1; i < t.steps.size(); ++i) {
    const double dt = t.steps[i].time_s - t.steps[i - 1].time_s;
    VehicleState& v = t.steps[i].others[k];
    const VehicleState& before = t.steps[i - 1].others[k];
    v.vx_mps = speed_at(t.steps[i].time_s);
    v.x_m = before.x_m + 0.5 * (before.vx_mps + v.vx_mps) * dt;
    v.accel_mps2 = (v.vx_mps - before.vx_mps) / dt;
  }
  t.events.push_back(test::message_event(0.0, MessageType::kRequest, 0, 4, CoopCase::kEgoAhead, 150.0, 30.0, 12.0));
  const TraceEvent accept = test::message_event(0.05, MessageType::kAccept, 4, 0, CoopCase::kEgoAhead, 150.0, 30.0, 12.0);
  t.events.push_back(accept);
  t.events.push_back(test::delivered_event(accept, 0.1));
  return t;
}

// Braking from 20 m/s at `rate_mps2` from `from_s` down to `to_mps`, then holding it.
std::function<double(double)> slows(double from_s, double to_mps, double rate_mps2) {
  return [=](double t) { return std::max(to_mps, 20.0 - rate_mps2 * std::max(0.0, t - from_s)); };
}

TEST(ProgressMonitor, AKeptAcceptanceLeftUnusedIsLettingTheRightOfWayPass) {
  // Vehicle 4 yields to 12 m/s as it accepted (at its b_max, within 1 s); the ego ignores it: the acceptance was in force
  // from 0.1 s, the grace runs out at 3.1 s.
  const Scenario s = coop_offer_scenario();
  const MonitorOutput out = test::run(monitor_progress, s, coop_offer_trace(s, 4, slows(0.1, 12.0, 8.0)));
  ASSERT_FALSE(out.result.holds) << out.result.detail;
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NE(out.result.detail.find("vehicle 4's acceptance in force"), std::string::npos) << out.result.detail;
  const auto gaps = std::find_if(out.result.measures.begin(), out.result.measures.end(),
                                 [](const auto& m) { return m.first == "feasible_gaps_let_pass"; });
  ASSERT_NE(gaps, out.result.measures.end());
  EXPECT_EQ(gaps->second, 0.0) << out.result.detail;  // no Definition 1 gap: the acceptance alone
  EXPECT_NEAR(*out.result.first_violation_time_s, 3.12, 0.021);
}

TEST(ProgressMonitor, AnAcceptanceItsSenderDoesNotKeepOffersNothing) {
  // Vehicle 4 accepts and drives on at 20 m/s: past its accepted profile (def2_positions), the
  // merge it promised never existed, and the ego that waits is not letting anything pass.
  const Scenario s = coop_offer_scenario();
  const Trace t = coop_offer_trace(s, 4, [](double) { return 20.0; });
  const MonitorOutput broken = test::run(monitor_def2_positions, s, t);
  ASSERT_FALSE(broken.result.holds);
  EXPECT_EQ(broken.result.liable_id, Party::from_vehicle_id(4));
  const MonitorOutput out = test::run(monitor_progress, s, t);
  EXPECT_TRUE(out.result.holds) << out.result.detail;
}

TEST(ProgressMonitor, AnAcceptanceWhoseOtherVehicleLeftNoRoomOffersNothing) {
  // Vehicle 4 yields as promised, but vehicle 3, ahead of it, brakes at 8 m/s2 from 20 to 11 m/s
  // by 1.23 s and then holds that speed: it brakes no more, yet a merge begun now at 15 m/s ends
  // within D_lon of it (ineq. (1.2) toward it fails), so the acceptance no longer offers a merge.
  // (Judged by its braking alone, the offer resumed at 1.23 s and ran out at 4.25 s.)
  const Scenario s = coop_offer_scenario();
  Trace t = coop_offer_trace(s, 4, slows(0.1, 12.0, 8.0));
  const Trace braking = coop_offer_trace(s, 3, slows(0.1, 11.0, 8.0));
  for (std::size_t i = 0; i < t.steps.size(); ++i) t.steps[i].others[2] = braking.steps[i].others[2];
  const MonitorOutput out = test::run(monitor_progress, s, t);
  EXPECT_TRUE(out.result.holds) << out.result.detail;
}

TEST(ProgressMonitor, AnAcceptanceWhoseOtherVehicleMustSlowForTheOneAheadOfItOffersNothing) {
  // Vehicle 4 yields as promised and vehicle 3, ahead of it, holds 20 m/s, but vehicle 2, 45.5 m
  // ahead of vehicle 3, drives at 12 m/s: holding its speed over rho vehicle 3 would come within
  // vehicle 2's D_lon, so it must slow down and the gap the request counted on shrinks, as for a
  // Definition 1 gap's leader. The acceptance offers no merge (judged by vehicle 3's braking and
  // ineq. (1.2) alone it offered one for 4.98 s); with vehicle 2 at 20 m/s it does
  // (AKeptAcceptanceLeftUnusedIsLettingTheRightOfWayPass).
  Scenario s = coop_offer_scenario();
  s.vehicles[1].speed_mps = 12.0;
  const MonitorOutput out = test::run(monitor_progress, s, coop_offer_trace(s, 4, slows(0.1, 12.0, 8.0)));
  EXPECT_TRUE(out.result.holds) << out.result.detail;
}

TEST(ProgressMonitor, AnAcceptanceWhoseSenderTheEgoLetCloseInOffersNoMore) {
  // Vehicle 4 yields to 12 m/s as it accepted, but the ego brakes from 15 m/s at 2 m/s2 from 0.1 s
  // to 9 m/s (Def. 2.1 has it hold its speed): vehicle 4 closes in, and from about 1.8 s a merge
  // begun at the ego's speed would reach its midpoint inside vehicle 4's RSS distance
  // (sigmoid_pc_bounds, the ego's). The acceptance offered a merge for less than the grace.
  const Scenario s = coop_offer_scenario();
  Trace t = coop_offer_trace(s, 4, slows(0.1, 12.0, 8.0));
  for (std::size_t i = 1; i < t.steps.size(); ++i) {
    const double dt = t.steps[i].time_s - t.steps[i - 1].time_s;
    VehicleState& e = t.steps[i].ego;
    const VehicleState& before = t.steps[i - 1].ego;
    e.vx_mps = std::max(9.0, 15.0 - 2.0 * std::max(0.0, t.steps[i].time_s - 0.1));
    e.x_m = before.x_m + 0.5 * (before.vx_mps + e.vx_mps) * dt;
    e.accel_mps2 = (e.vx_mps - before.vx_mps) / dt;
  }
  const MonitorOutput out = test::run(monitor_progress, s, t);
  EXPECT_TRUE(out.result.holds) << out.result.detail;
  const auto unused = std::find_if(out.result.measures.begin(), out.result.measures.end(),
                                   [](const auto& m) { return m.first == "longest_unused_s"; });
  ASSERT_NE(unused, out.result.measures.end());
  EXPECT_GT(unused->second, 0.5);
  EXPECT_LT(unused->second, 3.0);
}

}  // namespace
}  // namespace mg
