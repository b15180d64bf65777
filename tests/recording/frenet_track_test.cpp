// Speeds and accelerations of recorded vehicles (src/recording/frenet_track.h): the smoothing
// slope is exact on straight lines and averages noise away; recorded speeds are used as given.
#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "recording/frenet_track.h"

namespace mg {
namespace {

RC_GTEST_PROP(LocalSlope, IsExactOnAStraightLine, ()) {
  const double a = *rc::gen::inRange(-1000, 1000);
  const double b = *rc::gen::inRange(-300, 300) * 0.1;
  const int n = *rc::gen::inRange(2, 60);
  const int h = *rc::gen::inRange(1, 8);
  std::vector<double> y;
  for (int i = 0; i < n; ++i) y.push_back(a + b * 0.1 * i);
  const std::size_t i = static_cast<std::size_t>(*rc::gen::inRange(0, n));
  RC_ASSERT(std::abs(local_slope(y, 0.1, i, h) - b) < 1e-6);
}

TEST(LocalSlope, AveragesAlternatingNoiseAway) {
  std::vector<double> y;
  for (int i = 0; i < 40; ++i) y.push_back(2.0 * 0.1 * i + (i % 2 ? 0.05 : -0.05));
  // A central difference would read 2 +- 1 m/s here; the +-3 step fit is within 0.1.
  EXPECT_NEAR(local_slope(y, 0.1, 20, 3), 2.0, 0.1);
  EXPECT_DOUBLE_EQ(local_slope({5.0}, 0.1, 0, 3), 0.0);
}

RecordedVehicle straight_vehicle(bool with_speed) {
  RecordedVehicle v;
  v.id = 4;
  v.type = "car";
  for (int i = 0; i < 30; ++i) {
    RecordedState s;
    s.time_step = 10 + i;
    s.x_m = 5 + 15.0 * 0.1 * i + 0.5 * 1.0 * (0.1 * i) * (0.1 * i);  // 15 m/s, 1 m/s2
    s.y_m = 1.0;
    if (with_speed) s.speed_mps = 15.0 + 0.1 * i, s.orientation_rad = 0.0;
    v.states.push_back(s);
  }
  return v;
}

TEST(FrenetTrack, DerivesSpeedsAndAccelerationsFromPositionsAndSaysSo) {
  const ReferenceLine ref({{0, 0}, {200, 0}});
  const FrenetTrack t = project_track(straight_vehicle(false), ref, 0.1, 3);
  EXPECT_TRUE(t.speed_from_positions);
  EXPECT_TRUE(t.accel_from_speeds);
  EXPECT_TRUE(t.yaw_from_motion);
  EXPECT_NEAR(t.states[15].vs_mps, 16.5, 1e-6);
  EXPECT_NEAR(t.states[15].accel_mps2, 1.0, 1e-6);
  EXPECT_NEAR(t.states[15].d_m, 1.0, 1e-9);
  EXPECT_EQ(t.at_step(25), &t.states[15]);
  EXPECT_EQ(t.at_step(9), nullptr);
}

TEST(FrenetTrack, UsesRecordedSpeedAndHeading) {
  const ReferenceLine ref({{0, 0}, {200, 0}});
  const FrenetTrack t = project_track(straight_vehicle(true), ref, 0.1, 3);
  EXPECT_FALSE(t.speed_from_positions);
  EXPECT_FALSE(t.yaw_from_motion);
  EXPECT_TRUE(t.accel_from_speeds);
  EXPECT_DOUBLE_EQ(t.states[15].vs_mps, 16.5);
}

}  // namespace
}  // namespace mg
