#include "sim/path_tracker.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "sim/single_track.h"

namespace mg {
namespace {

std::vector<PathPoint> sigmoid_path(double pc_m, double kappa_per_m) {
  std::vector<PathPoint> p;
  for (double x = -50.0; x <= 600.0; x += 1.0) p.push_back({x, 3.5 / (1.0 + std::exp(-kappa_per_m * (x - pc_m))) - 3.5});
  return p;
}

TEST(PathTracker, CrossTrackErrorIsPositiveLeftOfThePath) {
  const std::vector<PathPoint> path{{0.0, 0.0}, {10.0, 0.0}, {20.0, 0.0}};
  EXPECT_DOUBLE_EQ(project_on_path(path, 5.0, 1.5).cross_track_m, 1.5);
  EXPECT_DOUBLE_EQ(project_on_path(path, 15.0, -0.5).cross_track_m, -0.5);
  EXPECT_DOUBLE_EQ(project_on_path(path, 30.0, 2.0).cross_track_m, 2.0) << "the end segment extends straight";
}

TEST(PathTracker, ConvergesOntoAnOffsetStraightLine) {
  const EgoDynamics d;
  const Limits lim;
  const std::vector<PathPoint> path{{-10.0, 0.0}, {1000.0, 0.0}};
  VehicleState s;
  s.vx_mps = 20.0;
  s.y_m = -1.0;
  for (int i = 0; i < 500; ++i) s = step_single_track(s, {stanley_steering_rad(path, s, d), 0.0}, d, lim, 0.02);
  EXPECT_NEAR(s.y_m, 0.0, 0.02);
  EXPECT_NEAR(s.yaw_rad, 0.0, 0.005);
}

TEST(PathTracker, FollowsASigmoidLaneChangeWithoutOvershoot) {
  const EgoDynamics d;
  const Limits lim;
  const auto path = sigmoid_path(150.0, 0.15);
  VehicleState s;
  s.vx_mps = 20.0;
  s.y_m = -3.5;
  double worst = 0.0, highest = -10.0;
  for (int i = 0; i < 1000; ++i) {
    s = step_single_track(s, {stanley_steering_rad(path, s, d), 0.0}, d, lim, 0.02);
    worst = std::max(worst, std::abs(project_on_path(path, s.x_m, s.y_m).cross_track_m));
    highest = std::max(highest, s.y_m);
  }
  EXPECT_LT(worst, 0.15);
  EXPECT_LT(highest, 0.05);
  EXPECT_NEAR(s.y_m, 0.0, 0.02);
}

}  // namespace
}  // namespace mg
