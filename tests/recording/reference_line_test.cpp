// The reference line and its Frenet frame (src/recording/reference_line.h): exact on a straight
// road, and on a curved one projecting and mapping back are inverse; the road's deviation from
// straight is measured.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "recording/reference_line.h"

namespace mg {
namespace {

std::vector<Point2> arc(double radius_m, double angle_rad, int n) {
  std::vector<Point2> pts;
  for (int i = 0; i <= n; ++i) {
    const double a = angle_rad * i / n;
    pts.push_back({radius_m * std::sin(a), radius_m * (1 - std::cos(a))});  // starts at the origin heading +x, turns left
  }
  return pts;
}

TEST(ReferenceLine, StraightRoadIsExact) {
  const ReferenceLine ref({{0, 0}, {100, 0}});
  const FrenetPoint f = ref.project({40, 2.5});
  EXPECT_NEAR(f.s_m, 40, 1e-9);
  EXPECT_NEAR(f.d_m, 2.5, 1e-9);
  EXPECT_NEAR(ref.project({40, -3}).d_m, -3, 1e-9);
  EXPECT_NEAR(ref.project({-50, 1}).s_m, -50, 1e-9);  // the straight extension before the start
  EXPECT_NEAR(ref.shape().max_offset_from_chord_m, 0.0, 1e-9);
  EXPECT_NEAR(ref.shape().length_m, 100, 1e-9);
}

TEST(ReferenceLine, CurvedRoadHasArcLengthAlongItAndOffsetsAcrossIt) {
  const double r = 200, angle = 0.5;
  const ReferenceLine ref(arc(r, angle, 400));
  // A point 3 m outside the bend, a quarter of the way along.
  const double a = angle / 4;
  const FrenetPoint f = ref.project({(r + 3) * std::sin(a), r - (r + 3) * std::cos(a)});
  EXPECT_NEAR(f.s_m, r * a, 0.2);
  EXPECT_NEAR(f.d_m, -3, 0.05);  // right of the driving direction: outside a left bend
  EXPECT_NEAR(ref.shape().heading_change_rad, angle, 0.01);
  EXPECT_NEAR(ref.shape().max_offset_from_chord_m, r * (1 - std::cos(angle / 2)), 0.1);
  EXPECT_NEAR(ref.curvature_at(r * a), 1 / r, 1e-3);
}

RC_GTEST_PROP(ReferenceLine, ProjectionAndPointAtAreInverseNearTheLine, ()) {
  const double radius = *rc::gen::inRange(100, 2000);
  const ReferenceLine ref(arc(radius, 0.6, 300));
  const double s = *rc::gen::inRange(0, 100) * 0.01 * radius * 0.6;
  const double d = (*rc::gen::inRange(-800, 800)) * 0.01;
  const Point2 p = ref.point_at({s, d});
  const FrenetPoint back = ref.project(p);
  RC_ASSERT(std::abs(back.s_m - s) < 0.05);
  RC_ASSERT(std::abs(back.d_m - d) < 0.05);
}

TEST(ReferenceLine, ResamplingKeepsEndsAndSpacing) {
  const std::vector<Point2> pts = resample_polyline({{0, 0}, {10, 0}, {10, 10}}, 1.0);
  ASSERT_EQ(pts.size(), 21u);
  EXPECT_NEAR(pts.back().x_m, 10, 1e-9);
  EXPECT_NEAR(pts.back().y_m, 10, 1e-9);
  EXPECT_NEAR(pts[5].x_m, 5, 1e-9);
  EXPECT_NEAR(pts[15].y_m, 5, 1e-9);
}

TEST(ReferenceLine, SmoothingKeepsTheEndsAndAveragesInside) {
  const std::vector<Point2> s = smooth_polyline({{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}}, 1);
  EXPECT_DOUBLE_EQ(s.front().y_m, 0.0);
  EXPECT_DOUBLE_EQ(s.back().y_m, 0.0);
  EXPECT_NEAR(s[2].y_m, 2.0 / 3.0, 1e-12);
}

}  // namespace
}  // namespace mg
