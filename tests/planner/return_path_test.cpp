// The return path to the side lane's centre (src/planner/return_path.cpp): the quintic's boundary
// values and exact peak curvature, and the return's shape from the ego's state.
#include "planner/return_path.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg {
namespace {

// Central first difference of y(X) at x: the path's slope.
template <class Path>
double slope_of(const Path& p, double x, double h = 1e-4) {
  return (p.y_at_m(x + h) - p.y_at_m(x - h)) / (2.0 * h);
}

RC_GTEST_PROP(ReturnPath, QuinticMeetsItsBoundaryValues, ()) {
  const double y0 = *rc::gen::inRange(-400, 0) / 100.0, y_end = *rc::gen::inRange(-400, 0) / 100.0;
  const double slope0 = *rc::gen::inRange(-100, 100) / 1000.0, c0 = *rc::gen::inRange(-100, 100) / 10000.0;
  const double length = *rc::gen::inRange(5, 300) * 1.0;
  const Quintic q = quintic_to_level(10.0, y0, slope0, c0, y_end, length);
  RC_ASSERT(std::abs(q.y_at_m(10.0) - y0) < 1e-12);
  RC_ASSERT(std::abs(q.curvature_at_per_m(10.0) - c0) < 1e-12);
  RC_ASSERT(std::abs((q.y_at_m(10.0 + 1e-4) - y0) / 1e-4 - slope0) < 1e-4);
  RC_ASSERT(std::abs(q.y_at_m(10.0 + length) - y_end) < 1e-9);
  RC_ASSERT(std::abs(q.curvature_at_per_m(10.0 + length)) < 1e-9);
  RC_ASSERT(std::abs((y_end - q.y_at_m(10.0 + length - 1e-4)) / 1e-4) < 1e-4);
  RC_ASSERT(q.y_at_m(10.0 + 2.0 * length) == q.y_at_m(10.0 + length));  // level beyond its end
}

RC_GTEST_PROP(ReturnPath, PeakCurvatureIsTheMaximumOverTheSpan, ()) {
  const Quintic q = quintic_to_level(0.0, *rc::gen::inRange(-400, 0) / 100.0, *rc::gen::inRange(-100, 100) / 1000.0,
                                     *rc::gen::inRange(-100, 100) / 10000.0, -3.5, *rc::gen::inRange(5, 300) * 1.0);
  double sampled = 0.0;
  for (int i = 0; i <= 10000; ++i) sampled = std::max(sampled, std::abs(q.curvature_at_per_m(q.length_m * i / 10000)));
  const double peak = peak_curvature_per_m(q);
  RC_ASSERT(peak >= sampled - 1e-15);
  RC_ASSERT(peak <= sampled * (1.0 + 1e-6) + 1e-15);  // attained: no sample far below it
}

struct ReturnCase {
  double y0, slope0;
  ReturnLimits limits;
};
ReturnCase gen_return_case() {
  ReturnCase c;
  c.y0 = -3.5 + *rc::gen::inRange(5, 250) / 100.0;
  c.slope0 = *rc::gen::inRange(-80, 150) / 1000.0;
  c.limits.comfort_curvature_per_m = *rc::gen::inRange(10, 5000) / 1e5;
  c.limits.cap_curvature_per_m = *rc::gen::inRange(10, 5000) / 1e5;
  c.limits.y_max_m = *rc::gen::inRange(-300, -150) / 100.0;
  return c;
}

// The return starts at the ego along its direction of travel, its curvature stays within the
// cap (within comfort unless the stop was sharpened), and it ends level on the centre.
RC_GTEST_PROP(ReturnPath, StartsAlongTheEgoAndEndsLevelOnTheCentreWithinItsBounds, ()) {
  const ReturnCase c = gen_return_case();
  const ReturnPath p = plan_return_path(50.0, c.y0, c.slope0, -3.5, c.limits);
  RC_ASSERT(std::abs(p.y_at_m(50.0) - c.y0) < 1e-12);
  RC_ASSERT(std::abs(slope_of(p, 50.0 - 1e-3) - c.slope0) < 1e-9);  // behind: the tangent
  RC_ASSERT(std::abs((p.y_at_m(50.0 + 1e-5) - c.y0) / 1e-5 - c.slope0) < 1e-4);
  const double bound = std::min(c.limits.comfort_curvature_per_m, c.limits.cap_curvature_per_m);
  RC_ASSERT(p.stop_curvature_per_m <= std::max(bound, c.limits.cap_curvature_per_m) * (1 + 1e-12));
  RC_ASSERT(peak_curvature_per_m(p.back) <= bound * (1 + 1e-12));
  RC_ASSERT(std::abs(p.y_at_m(p.end_x_m()) + 3.5) < 1e-9);
  RC_ASSERT(std::abs(p.y_at_m(p.end_x_m() + 100.0) + 3.5) < 1e-9);
  // C1 everywhere: no kink at the stop's end or anywhere along the path.
  RC_ASSERT(p.end_x_m() < 50.0 + 1e5);
  for (int i = 1; i < 500; ++i) {
    const double x = 50.0 + (p.end_x_m() - 50.0) * i / 500.0;
    const double h = 1e-4;
    const double left = (p.y_at_m(x) - p.y_at_m(x - h)) / h, right = (p.y_at_m(x + h) - p.y_at_m(x)) / h;
    RC_ASSERT(std::abs(left - right) < 2e-4 * std::max(1.0, std::max(bound, p.stop_curvature_per_m) * 1e3));
  }
}

//        y_max ......................................
//             peak  _--_
//  ego -> y0  ___--'    '--__
//                            '--___   centre
// An ego moving toward the main lane first stops that motion: at the comfort bound when that stays
// below y_max, sharper (up to the cap) when not; the rest never rises again.
RC_GTEST_PROP(ReturnPath, StopsTheMotionTowardTheLaneBelowTheLimitWhenTheCapAllows, ()) {
  ReturnCase c = gen_return_case();
  c.slope0 = *rc::gen::inRange(1, 150) / 1000.0;
  const ReturnPath p = plan_return_path(0.0, c.y0, c.slope0, -3.5, c.limits);
  const double bound = std::min(c.limits.comfort_curvature_per_m, c.limits.cap_curvature_per_m);
  const double peak = c.y0 + c.slope0 * c.slope0 / (2.0 * p.stop_curvature_per_m);
  RC_ASSERT(std::abs(p.y_at_m(p.stop_length_m) - peak) < 1e-9);
  const double comfortable_peak = c.y0 + c.slope0 * c.slope0 / (2.0 * bound);
  const double sharpest_peak = c.y0 + c.slope0 * c.slope0 / (2.0 * c.limits.cap_curvature_per_m);
  if (comfortable_peak <= c.limits.y_max_m) {
    RC_ASSERT(p.stop_curvature_per_m == bound);
  } else if (sharpest_peak <= c.limits.y_max_m) {
    RC_ASSERT(peak <= c.limits.y_max_m + 1e-9);
  } else {
    RC_ASSERT(p.stop_curvature_per_m == c.limits.cap_curvature_per_m);
  }
  double highest = -1e9;
  for (int i = 0; i <= 1000; ++i) highest = std::max(highest, p.y_at_m(p.stop_length_m + (p.end_x_m() - p.stop_length_m) * i / 1000.0));
  RC_ASSERT(highest <= peak + 1e-9);
}

//             y_max ..............................
//   hold level   ___________________________
//  ego -> y0  _-'
// A hold (after a shallow abort) starts along the ego, never moves back (the lateral speed keeps
// its sign: no reversal for the smoothness rule to count), ends level, keeps |y''| within the
// comfort bound unless it had to sharpen to stay below y_max, and stays below y_max when the cap
// allows it.
RC_GTEST_PROP(ReturnPath, AHoldStopsTheMotionTowardTheLaneWithoutMovingBack, ()) {
  ReturnCase c = gen_return_case();
  c.slope0 = *rc::gen::inRange(1, 150) / 1000.0;
  const ReturnPath p = plan_lateral_hold(0.0, c.y0, c.slope0, c.limits);
  RC_ASSERT(std::abs(p.y_at_m(0.0) - c.y0) < 1e-12);
  RC_ASSERT(std::abs((p.y_at_m(1e-5) - c.y0) / 1e-5 - c.slope0) < 1e-4);
  const double level = p.y_at_m(p.end_x_m());
  RC_ASSERT(std::abs(p.y_at_m(p.end_x_m() + 50.0) - level) < 1e-12);
  double previous = c.y0;
  for (int i = 1; i <= 1000; ++i) {
    const double y = p.y_at_m(p.end_x_m() * i / 1000.0);
    RC_ASSERT(y >= previous - 1e-12);
    previous = y;
  }
  const double bound = std::min(c.limits.comfort_curvature_per_m, c.limits.cap_curvature_per_m);
  RC_ASSERT(peak_curvature_per_m(p.back) <= std::max(bound, c.limits.cap_curvature_per_m) * (1 + 1e-9));
  const double comfortable_rise_m = 0.75 * c.slope0 * c.slope0 / bound;
  if (c.y0 + comfortable_rise_m <= c.limits.y_max_m) RC_ASSERT(peak_curvature_per_m(p.back) <= bound * (1 + 1e-9));
  const double sharpest_rise_m = 0.75 * c.slope0 * c.slope0 / c.limits.cap_curvature_per_m;
  if (c.y0 + sharpest_rise_m <= c.limits.y_max_m) RC_ASSERT(level <= c.limits.y_max_m + 1e-9);
}

TEST(ReturnPath, LevelStartIsTheQuinticAtTheComfortBound) {
  // From rest 1 m above the centre at 25 m/s with 1.5 m/s2: max |y''| of the rest-to-rest
  // quintic is 10 sqrt(3)/3 |dy| / L^2, so L = sqrt(5.7735 / (1.5 / 625)) = 49.0 m.
  const ReturnLimits limits{1.5 / 625.0, 1.0, -1.0};
  const ReturnPath p = plan_return_path(0.0, -2.5, 0.0, -3.5, limits);
  EXPECT_EQ(p.stop_length_m, 0.0);
  EXPECT_NEAR(p.back.length_m, std::sqrt(10.0 * std::sqrt(3.0) / 3.0 / limits.comfort_curvature_per_m),
              kReturnLengthTolerance * p.back.length_m);
  EXPECT_LE(peak_curvature_per_m(p.back), limits.comfort_curvature_per_m);
}

}  // namespace
}  // namespace mg
