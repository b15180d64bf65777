#include "rules/progress_monitor.h"

#include <cmath>
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

TEST(ProgressMonitor, AGapIsJudgedAlongTheWholeMergeNotOnlyAtItsMidpointAndEnd) {
  // Vehicle 1 overtakes the ego (12 m/s) at 20 m/s from alongside it on 3 m lanes. Ineq. (1.2)
  // holds at rho/2 and rho for a v_e* the ego brakes to, and holds there whatever the lateral
  // slack; but a merge leaving the side lane while the leader is still beside the ego comes within
  // D_lat plus the slack of it without D_lon behind it. With the largest slack (1.5 m) the ego is
  // that near it from the first instant, and the gap is not offered; with none it is.
  Scenario s = base_scenario();
  s.road.lane_width_m = 3.0;
  s.ego.y_m = -3.0;
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 12.0;
  s.vehicles = {vehicle(1, 100.0, 20.0)};
  const auto j = test::judge(s, constant_accel_trace(s, 1.0));
  j->params.progress_lateral_margin_m = 1.5;
  EXPECT_TRUE(def1_gaps_feasible(j->trace, j->params, 0).empty());
  j->params.progress_lateral_margin_m = 0.0;
  EXPECT_FALSE(def1_gaps_feasible(j->trace, j->params, 0).empty());
}

TEST(ProgressMonitor, ADeclaredMergeDurationBelowTheShortestComfortableOneIsRaisedToIt) {
  // rho_m = 2 s: a lane change of 3.5 m in 2 s needs 4.4 m/s^2 of lateral acceleration on the
  // flattest witness (c = 2 ln 49, cut at 2 %): with the default bound (1.5 m/s^2) the empty
  // road is offered at the shortest comfortable duration, 1.05 * 2 ln 49 / sqrt(6 sqrt 3 * 1.5 /
  // 3.5) = 3.87 s; with a bound of 5 m/s^2 at 2.12 s; at rho_m = 5 s (above both) at rho_m.
  const Scenario s = base_scenario();
  const auto j = test::judge(s, constant_accel_trace(s, 1.0));
  j->params.merge_duration_s = 2.0;
  const auto offered = [&] {
    const std::vector<FeasibleMerge> gaps = def1_gaps_feasible(j->trace, j->params, 0);
    EXPECT_EQ(gaps.size(), 1u);
    return gaps.empty() ? 0.0 : gaps.front().merge_duration_s;
  };
  EXPECT_NEAR(offered(), 3.8726, 1e-4);
  j->params.progress_lat_accel_max_mps2 = 5.0;
  EXPECT_NEAR(offered(), 1.05 * 2.0 * std::log(49.0) / std::sqrt(6.0 * std::sqrt(3.0) * 5.0 / 3.5), 1e-9);
  j->params.merge_duration_s = 5.0;
  EXPECT_NEAR(offered(), 5.0, 1e-12);
}

TEST(ProgressMonitor, TheTurnInIsTheSteepestSigmoidWithinTheSideslipBound) {
  // c = tan(0.05) / 2.4 (half the 4.8 m length); from the side-lane centre (Y = -3.5, A = 3.5) the
  // steepest logistic has kappa = sqrt(6 sqrt 3 c / 3.5) = 0.2489/m and reaches the line (its
  // middle) ln 49 / kappa = 15.64 m after its 2 % point; from Y = -2.5 (A = 2.5, the line at
  // f = 0.3) the same with logit(0.3); at the line itself, nothing.
  const Scenario s = base_scenario();
  const auto j = test::judge(s, constant_accel_trace(s, 0.1));
  const double c = std::tan(0.05) / 2.4;
  const double k35 = std::sqrt(6.0 * std::sqrt(3.0) * c / 3.5), k25 = std::sqrt(6.0 * std::sqrt(3.0) * c / 2.5);
  EXPECT_NEAR(shortest_turn_in_m(j->trace, j->params, -3.5), std::log(49.0) / k35, 1e-9);
  EXPECT_NEAR(shortest_turn_in_m(j->trace, j->params, -3.5), 15.64, 0.01);
  EXPECT_NEAR(shortest_turn_in_m(j->trace, j->params, -2.5), (std::log(0.3 / 0.7) + std::log(49.0)) / k25, 1e-9);
  EXPECT_NEAR(shortest_turn_in_m(j->trace, j->params, -1.75), 0.0, 1e-12);
}

}  // namespace
}  // namespace mg
