#include "rules/road_monitor.h"

#include <gtest/gtest.h>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;

TEST(RoadMonitor, EgoOnTheSideLaneCentreIsOnTheRoad) {
  // y = -3.5, width 1.9: lowest corner -4.45 against the edge -5.25: 0.8 m; top corner -2.55
  // against the left edge 1.75: 4.3 m. Margin 0.8 m + 0.05 m edge tolerance = 0.85 m.
  const Scenario s = base_scenario();
  const MonitorOutput out = test::run(monitor_on_road, s, constant_accel_trace(s, 0.5));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 0.85, 1e-9);
}

TEST(RoadMonitor, EgoOverTheRightEdgeIsOffRoad) {
  // y = -5.0: lowest corner -5.95, 0.7 m beyond the edge: margin -0.7 + 0.05 = -0.65 m.
  Scenario s = base_scenario();
  s.ego.y_m = -5.0;
  const MonitorOutput out = test::run(monitor_on_road, s, constant_accel_trace(s, 0.5));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -0.65, 1e-9);
}

TEST(RoadMonitor, PassingTheSideLaneEndWhileInItIsAViolation) {
  // Ego at X = 290 m at 20 m/s in the side lane ending at 300 m: its front (X + 2.4) reaches
  // the end at t = 7.6 / 20 = 0.38 s; at t = 1 s the margin is 300 - 312.4 = -12.4 m.
  Scenario s = base_scenario();
  s.ego.x_m = 290.0;
  const MonitorOutput out = test::run(monitor_side_lane_end, s, constant_accel_trace(s, 1.0));
  ASSERT_FALSE(out.result.holds);
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.40, 1e-9);  // first step past 0.38 s
  EXPECT_NEAR(out.result.min_margin, -12.4, 1e-6);
}

TEST(RoadMonitor, SideLaneEndHoldsWhenTheEgoStopsBeforeIt) {
  // From X = 250 at 20 m/s braking at 5 m/s2: stops after 20^2 / 10 = 40 m, front at
  // 290 + 2.4 = 292.4 m: margin 300 - 292.4 = 7.6 m.
  Scenario s = base_scenario();
  s.ego.x_m = 250.0;
  const MonitorOutput out = test::run(monitor_side_lane_end, s, constant_accel_trace(s, 5.0, {-5.0}));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 7.6, 1e-6);
}

}  // namespace
}  // namespace mg
