#include "rules/progress_monitor.h"

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

}  // namespace
}  // namespace mg
