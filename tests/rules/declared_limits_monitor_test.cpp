// The declared-limits rule (rules/declared_limits_monitor.h): every vehicle, at every step.
#include "rules/declared_limits_monitor.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

// Default limits: a_accel^max 2, a_brake^max 8 m/s2, tolerance 0.05 m/s2.
TEST(DeclaredLimitsMonitor, DrivingAtTheLimitsHolds) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, 50.0, 20.0), vehicle(2, 100.0, 20.0)};
  const MonitorOutput out = test::run(monitor_declared_limits, s, constant_accel_trace(s, 2.0, {2.0, -8.0, 2.05}));
  EXPECT_TRUE(out.result.holds) << out.result.detail;
  EXPECT_NEAR(out.result.min_margin, 0.0, 1e-9);
}

TEST(DeclaredLimitsMonitor, AVehicleBrakingBeyondItsBmaxOutsideAnyDangerIsLiable) {
  // Vehicle 2, alone ahead and in no danger, brakes at 9 m/s2 (declared 8).
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -80.0, 20.0), vehicle(2, 200.0, 20.0)};
  const MonitorOutput out = test::run(monitor_declared_limits, s, constant_accel_trace(s, 1.0, {0.0, 0.0, -9.0}));
  EXPECT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(2));
  EXPECT_NEAR(out.result.min_margin, -0.95, 1e-9);
  EXPECT_EQ(*out.result.first_violation_time_s, 0.0);
}

TEST(DeclaredLimitsMonitor, TheEgoBeyondItsAccelerationLimitIsLiable) {
  Scenario s = base_scenario();
  s.ego.limits.accel_max_mps2 = 1.5;
  const MonitorOutput out = test::run(monitor_declared_limits, s, constant_accel_trace(s, 1.0, {1.6}));
  EXPECT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
}

// Whatever the accelerations, the rule holds exactly when every one is within its limits.
RC_GTEST_PROP(DeclaredLimitsMonitor, HoldsExactlyWhenEveryVehicleKeepsItsLimits, ()) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -80.0, 20.0), vehicle(2, 200.0, 20.0)};
  std::vector<double> accel;
  bool within = true;
  for (int k = 0; k < 3; ++k) {
    accel.push_back(*rc::gen::inRange(-1000, 300) / 100.0);
    within = within && accel.back() <= 2.05 + 1e-12 && accel.back() >= -8.05 - 1e-12;
  }
  const MonitorOutput out = test::run(monitor_declared_limits, s, constant_accel_trace(s, 0.2, accel));
  RC_ASSERT(out.result.holds == within);
}

}  // namespace
}  // namespace mg
