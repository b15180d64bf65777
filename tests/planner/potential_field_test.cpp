// Potential field (src/planner/potential_field.cpp): RCPP eq. (3)-(5).
#include "planner/potential_field.h"

#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg {
namespace {

TEST(PotentialField, RoadMarkMatchesEquation3AndGuardsThePole) {
  // beta = 0.5, boundary at -5.25, ego width 1.9 at Y = -3.5: edge gap 1.75 - 0.95 = 0.8 m
  // -> 0.25 / 0.64 = 0.390625.
  EXPECT_DOUBLE_EQ(road_mark_potential(-3.5, -5.25, false, 1.9, 0.5), 0.25 / 0.64);
  const double at_pole = road_mark_potential(-5.25 + 0.95, -5.25, false, 1.9, 0.5);
  EXPECT_TRUE(std::isfinite(at_pole));
  EXPECT_DOUBLE_EQ(at_pole, 0.25 / (kRoadMarkMinDistanceM * kRoadMarkMinDistanceM));
}

TEST(PotentialField, ObstacleFallsToOneOverEAtTheRssDistances) {
  // sigma = 1/D^2: at (D_lon, 0) the exponential is e^-1; gamma 10, U 0.01 -> 10 |e^-1 - 0.01|.
  const ObstacleField o = obstacle_field_from_rss(100, 0, 2.0, 40.0);
  EXPECT_NEAR(obstacle_potential(140, 0, o, 10, 0.01), 10 * (std::exp(-1.0) - 0.01), 1e-12);
  EXPECT_NEAR(obstacle_potential(100, 2, o, 10, 0.01), 10 * (std::exp(-1.0) - 0.01), 1e-12);
  EXPECT_NEAR(obstacle_potential(100, 0, o, 10, 0.01), 10 * 0.99, 1e-12);
}

RC_GTEST_PROP(PotentialField, ObstacleDecreasesAwayFromItsCentreUntilU, ()) {
  const ObstacleField o = obstacle_field_from_rss(0, 0, *rc::gen::inRange(5, 50) / 10.0, *rc::gen::inRange(50, 800) / 10.0);
  const double dx = *rc::gen::inRange(0, 500) / 10.0;
  const double dy = *rc::gen::inRange(0, 50) / 10.0;
  const double u = 0.0;  // with U = 0 the field is a plain Gaussian
  RC_ASSERT(obstacle_potential(dx + 1, dy, o, 10, u) <= obstacle_potential(dx, dy, o, 10, u));
  RC_ASSERT(obstacle_potential(dx, dy + 0.1, o, 10, u) <= obstacle_potential(dx, dy, o, 10, u));
}

RC_GTEST_PROP(PotentialField, LaneCentreModesMeetAtTheSearchDistance, ()) {
  // Eq. (5): xi D*^2/2 (keeping) equals D* xi D* - xi D*^2/2 (merging) at d = D*; merging grows
  // linearly beyond, keeping quadratically.
  const double xi = *rc::gen::inRange(1, 100) / 10.0;
  const double d_star = *rc::gen::inRange(1, 500) / 10.0;
  const double keep = lane_centre_potential(d_star, xi, d_star, LaneCentreMode::kKeeping);
  const double merge = lane_centre_potential(d_star, xi, d_star, LaneCentreMode::kMerging);
  RC_ASSERT(std::abs(keep - merge) < 1e-9 * (1 + keep));
  const double d = d_star * 2;
  RC_ASSERT(lane_centre_potential(d, xi, d_star, LaneCentreMode::kMerging) <=
            lane_centre_potential(d, xi, d_star, LaneCentreMode::kKeeping));
}

TEST(PotentialField, TargetLaneIsLowerThanSideLaneWithoutObstacles) {
  Road road;
  FieldScene scene{&road, 1.9, {}, 0.0, LaneCentreMode::kMerging};
  RcppParams p;
  EXPECT_LT(field_potential(scene, p, 100, 0.0), field_potential(scene, p, 100, -3.5));
}

// The floor the RCPP search prunes with (field_potential_floor): never above the field anywhere,
// whatever the parameters (within their ranges), the obstacles and the mode.
RC_GTEST_PROP(PotentialField, TheFloorIsNeverAboveTheField, ()) {
  Road road;
  road.main_lanes = *rc::gen::inRange(1, 4);
  RcppParams p;
  p.pf_road_beta = *rc::gen::inRange(0, 1000) / 100.0;
  p.pf_obstacle_gamma = *rc::gen::inRange(0, 2000) / 100.0;
  p.pf_obstacle_u = *rc::gen::inRange(0, 100) / 100.0;
  p.pf_lane_xi = *rc::gen::inRange(0, 1000) / 1000.0;
  p.pf_search_distance_m = *rc::gen::inRange(1, 10000) / 100.0;
  const LaneCentreMode mode = *rc::gen::inRange(0, 2) == 0 ? LaneCentreMode::kMerging : LaneCentreMode::kKeeping;
  FieldScene scene{&road, 1.9, {}, 0.0, mode};
  const int n = *rc::gen::inRange(0, 5);
  for (int i = 0; i < n; ++i)
    scene.obstacles.push_back(obstacle_field_from_rss(*rc::gen::inRange(-500, 500) / 10.0, *rc::gen::inRange(-70, 70) / 10.0,
                                                      *rc::gen::inRange(5, 50) / 10.0, *rc::gen::inRange(50, 800) / 10.0));
  for (int k = 0; k < 20; ++k) {
    const double x = *rc::gen::inRange(-1000, 1000) / 10.0;
    const double y = *rc::gen::inRange(-100000, 100000) / 10000.0;
    RC_ASSERT(field_potential(scene, p, x, y) >= field_potential_floor(p, mode));
  }
}

}  // namespace
}  // namespace mg
