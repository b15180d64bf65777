#include "sim/path_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "planner/merge_path.h"
#include "planner/return_path.h"
#include "sim/single_track.h"
#include "test_egos.h"

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

// The campaign finding behind the return path (planner/return_path.h): a soft neutral-steer ego
// (2000 kg, C_f l_f = C_r l_r) aborts its merge at 25 m/s while still moving toward the main lane
// at 1.6 m/s (state from corpus/cases/rcpp__ego_never_liable__sideslip__ego-4.json at t = 1.6 s).
// Tracking the return from there keeps its sideslip well inside the rule's 0.05 rad; a level path
// on the side lane's centre (the snap-back the return replaced) does not.
TEST(PathTracker, ReturnAfterAnAbortKeepsTheSideslipOfASoftEgoInsideTheBound) {
  const EgoDynamics d = test::soft_neutral_steer_ego();
  const Limits lim;
  VehicleState abort;
  abort.x_m = 39.94;
  abort.y_m = -2.73;
  abort.vx_mps = 24.98;
  abort.vy_mps = -0.371;
  abort.yaw_rad = 0.079;
  abort.yaw_rate_radps = 0.05;
  abort.steer_rad = 0.002;
  const double v = abort.road_vx_mps();
  ReturnLimits limits;
  limits.comfort_curvature_per_m = 1.5 / (v * v);
  limits.cap_curvature_per_m = kPathSideslipMaxRad / std::abs(steady_sideslip_per_curvature_m(d, v));
  limits.y_max_m = -1.75 - 0.25;
  const ReturnPath back = plan_return_path(abort.x_m, abort.y_m, abort.road_vy_mps() / v, -3.5, limits);
  const auto peak_sideslip = [&](const std::vector<PathPoint>& path) {
    VehicleState s = abort;
    double peak = 0.0;
    for (int i = 0; i < 300; ++i) {
      s = step_single_track(s, {stanley_steering_rad(path, s, d), 0.0}, d, lim, 0.02);
      peak = std::max(peak, std::abs(sideslip_rad(s)));
    }
    return peak;
  };
  EXPECT_LT(peak_sideslip(sample_return_path(back, 0.0, 400.0, 1.0)), 0.04);
  EXPECT_GT(peak_sideslip({{0.0, -3.5}, {400.0, -3.5}}), 0.05);
}

// A crawl merge (planner/merge_path.h: at a crawl a path as sharp as half the steering ability,
// kappa 0.54/m over a 3.5 m lane change), from rest at the sigmoid's 2 % point up to 1.34 m/s.
// Within the sideslip envelope the tracker steers at most 0.06 rad, a third of what the path
// needs, and crosses the lane line almost 4 m past P_c (3 s at that speed); below the speed from
// which the rule judges the sideslip (2 m/s) it may steer as the path needs, and crosses it at
// P_c within a metre.
TEST(PathTracker, ACrawlMergeIsFollowedBelowTheSpeedTheSideslipIsJudgedFrom) {
  const EgoDynamics d;
  const Limits lim;
  const auto path = sigmoid_path(0.0, 0.54);
  const auto midpoint_x_m = [&](const SteeringEnvelope& envelope) {
    VehicleState s;
    s.x_m = -7.2;
    s.y_m = -3.5;
    for (int i = 0; i < 2000; ++i) {
      const double accel_mps2 = s.vx_mps < 1.34 ? lim.accel_max_mps2 : 0.0;
      s = step_single_track(s, {stanley_steering_rad(path, s, d, {}, envelope), accel_mps2}, d, lim, 0.02);
      if (s.y_m > -1.75) return s.x_m;
    }
    return std::numeric_limits<double>::infinity();
  };
  EXPECT_NEAR(midpoint_x_m({2.0, lim.accel_max_mps2, 0.02}), 0.0, 1.0);
  EXPECT_GT(midpoint_x_m({}), 3.0);
}

// Steering harder below the judged speed never breaks the envelope where the rule judges: an
// ego on a sharp path below 2 m/s, steered to its cap, then accelerating at its a_max through 2
// m/s, has at most the envelope's kinematic sideslip from there on (the steering rate takes the
// extra back before the speed gets there).
RC_GTEST_PROP(PathTracker, SteeringBelowTheJudgedSpeedIsBackInTheEnvelopeWhenTheRuleJudges, ()) {
  const EgoDynamics d;
  Limits lim;
  lim.accel_max_mps2 = *rc::gen::inRange(5, 60) / 10.0;
  const double kappa_per_m = *rc::gen::inRange(5, 60) / 100.0;
  const auto path = sigmoid_path(*rc::gen::inRange(0, 20) * 1.0, kappa_per_m);
  const SteeringEnvelope envelope{2.0, lim.accel_max_mps2, 0.02};
  VehicleState s;
  s.x_m = -5.0;
  s.y_m = -3.5;
  s.vx_mps = *rc::gen::inRange(1, 19) / 10.0;
  const int steady_steps = *rc::gen::inRange(0, 200);
  const double cap_rad = std::atan(std::tan(kPathTrackerSideslipRad) * d.wheelbase_m() / d.cg_to_rear_m);
  for (int i = 0; i < 600; ++i) {
    const double accel = i < steady_steps ? 0.0 : lim.accel_max_mps2;
    s = step_single_track(s, {stanley_steering_rad(path, s, d, {}, envelope), accel}, d, lim, 0.02);
    if (s.vx_mps >= envelope.sideslip_judged_from_mps) RC_ASSERT(std::abs(s.steer_rad) <= cap_rad + 1e-9);
  }
}

}  // namespace
}  // namespace mg
