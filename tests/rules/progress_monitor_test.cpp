#include "rules/progress_monitor.h"

#include <string>

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

TEST(ProgressMonitor, MovingEgoIsNotJudged) {
  const Scenario s = base_scenario();
  const MonitorOutput out = test::run(monitor_progress, s, constant_accel_trace(s, 4.0));
  EXPECT_TRUE(out.result.holds);
  EXPECT_FALSE(std::isfinite(out.result.min_margin));
}

}  // namespace
}  // namespace mg
