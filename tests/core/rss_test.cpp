// RSS safe distances: hand-computed vectors and RapidCheck properties (RCPP eq. 1, 2; spec §3).
#include "core/rss.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg {
namespace {

LongitudinalInput standard_longitudinal() {
  // Both at 50 km/h = 13.8889 m/s, T = 2 s, a_acc = 2, b_min = 4, b_max = 8, zero lengths.
  return {13.888889, 13.888889, 0.0, 0.0, 2.0, 2.0, 4.0, 8.0};
}

LateralInput standard_lateral() {
  // Both at rest laterally, T = 2 s, a_lat = 0.2, b_lat,min = 0.8, mu = 0.1, zero widths.
  return {0.0, 0.0, 0.0, 0.0, 2.0, 0.2, 0.8, 0.1};
}

// The RSS Def. 1 bracket as printed: v_r T + a T^2/2 + (v_r + a T)^2/(2 b_min) - v_f^2/(2 b_max).
double final_stop_closing_m(const LongitudinalInput& in) {
  const double t = in.response_time_s, u = in.rear_speed_mps + in.accel_max_mps2 * t;
  return in.rear_speed_mps * t + 0.5 * in.accel_max_mps2 * t * t + u * u / (2.0 * in.brake_min_mps2) -
         in.front_speed_mps * in.front_speed_mps / (2.0 * in.brake_max_mps2);
}

// Largest closing of the worst-case motion (rear: a for T, then b_min to a stop; front: b_max to a
// stop), by brute force: exact motion sampled every millisecond (the grid meets T exactly), the
// independent oracle for the closed form's choice of candidate instants.
void advance(double& x_m, double& v_mps, double a_mps2, double dt_s) {
  if (v_mps + a_mps2 * dt_s >= 0.0) {
    x_m += v_mps * dt_s + 0.5 * a_mps2 * dt_s * dt_s;
    v_mps += a_mps2 * dt_s;
  } else {
    x_m += v_mps * v_mps / (-2.0 * a_mps2);
    v_mps = 0.0;
  }
}
double scanned_max_closing_m(const LongitudinalInput& in) {
  double x_r = 0.0, v_r = in.rear_speed_mps, x_f = 0.0, v_f = in.front_speed_mps, best = 0.0;
  constexpr double dt = 1e-3;
  const int response_steps = static_cast<int>(std::ceil(in.response_time_s / dt));
  for (int k = 0; k < response_steps; ++k) {
    advance(x_r, v_r, in.accel_max_mps2, in.response_time_s / response_steps);
    advance(x_f, v_f, -in.brake_max_mps2, in.response_time_s / response_steps);
    best = std::max(best, x_r - x_f);
  }
  while (v_r > 0.0) {
    advance(x_r, v_r, -in.brake_min_mps2, dt);
    advance(x_f, v_f, -in.brake_max_mps2, dt);
    best = std::max(best, x_r - x_f);
  }
  return best;
}

TEST(RssLongitudinal, MatchesStandardRssVector) {
  // v T = 27.7778; a T^2/2 = 4; (v + a T)^2/(2 b_min) = 17.8889^2/8 = 40.0017;
  // v_f^2/(2 b_max) = 192.901/16 = 12.0563  ->  27.7778 + 4 + 40.0017 - 12.0563 = 59.7232 m.
  EXPECT_NEAR(rss_longitudinal_m(standard_longitudinal()), 59.72, 0.01);
}

TEST(RssLongitudinal, WeakFrontBrakesNeedTheGapAtEqualSpeeds) {
  // Both at 20 m/s, T = 0.5 s, a = 2, rear b_min = 4, front b_max = 2, zero lengths. The printed
  // RSS term is negative (final stops 100 m apart in the front's favour), yet the rear closes
  //   during T: (a + b_max) T^2 / 2 = 0.5 m, closing speed (a + b_max) T = 2 m/s;
  //   then the closing speed falls at b_min - b_max = 2 m/s^2 for 1 s: + 2 * 1 / 2 = 1 m.
  const LongitudinalInput in{20.0, 20.0, 0.0, 0.0, 0.5, 2.0, 4.0, 2.0};
  EXPECT_LT(final_stop_closing_m(in), 0.0);
  EXPECT_NEAR(rss_longitudinal_m(in), 1.5, 1e-9);
}

TEST(RssLongitudinal, LengthsAddOutsideTheClamp) {
  // Rear at rest, front at 30 m/s: the bracket is negative (0 - 900/16 < 0) and clamps to 0, so
  // the distance is exactly the bumper-contact distance (4 + 5)/2 = 4.5 m (spec §3 deviation).
  LongitudinalInput in{0.0, 30.0, 4.0, 5.0, 0.0, 0.0, 4.0, 8.0};
  EXPECT_DOUBLE_EQ(rss_longitudinal_m(in), 4.5);
}

TEST(RssLongitudinal, ZeroResponseTimeIsPureBrakingDifference) {
  // v_r = 20, v_f = 10, T = 0: 400/8 - 100/16 = 50 - 6.25 = 43.75 m.
  LongitudinalInput in{20.0, 10.0, 0.0, 0.0, 0.0, 2.0, 4.0, 8.0};
  EXPECT_DOUBLE_EQ(rss_longitudinal_m(in), 43.75);
}

TEST(RssLongitudinal, RejectsOutOfDomainInputs) {
  auto in = standard_longitudinal();
  in.rear_speed_mps = -1.0;
  EXPECT_THROW(rss_longitudinal_m(in), std::invalid_argument);
  in = standard_longitudinal();
  in.front_speed_mps = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(rss_longitudinal_m(in), std::invalid_argument);
  in = standard_longitudinal();
  in.brake_min_mps2 = 0.0;
  EXPECT_THROW(rss_longitudinal_m(in), std::invalid_argument);
  in = standard_longitudinal();
  in.response_time_s = std::numeric_limits<double>::infinity();
  EXPECT_THROW(rss_longitudinal_m(in), std::invalid_argument);
  in = standard_longitudinal();
  in.rear_length_m = -0.1;
  EXPECT_THROW(rss_longitudinal_m(in), std::invalid_argument);
}

TEST(RssLateral, MatchesStandardRssVector) {
  // v_L,rho = -0.4, v_R,rho = +0.4 (each drifts toward the other during T).
  // d_L = -(0 - 0.4)/2 * 2 + 0.4^2/1.6 = 0.4 + 0.1 = 0.5; d_R = -(0 + 0.4)/2 * 2 - 0.1 = -0.5
  // D = 0.1 + 0 + [0.5 - (-0.5)]_+ = 1.1 m.
  EXPECT_NEAR(rss_lateral_m(standard_lateral()), 1.1, 1e-12);
}

TEST(RssLateral, SeparatingVehiclesNeedOnlyMarginAndWidths) {
  // L moves left at 2 m/s, R moves right at 2 m/s, T = 0: d_L = 0, d_R = 0 (no braking toward
  // each other), so D = mu + (w_L + w_R)/2 = 0.2 + (1.8 + 2.0)/2 = 2.1 m.
  LateralInput in{2.0, -2.0, 1.8, 2.0, 0.0, 0.2, 0.8, 0.2};
  EXPECT_DOUBLE_EQ(rss_lateral_m(in), 2.1);
}

TEST(RssLateral, RejectsOutOfDomainInputs) {
  auto in = standard_lateral();
  in.left_lat_speed_mps = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(rss_lateral_m(in), std::invalid_argument);
  in = standard_lateral();
  in.lat_brake_min_mps2 = -1.0;
  EXPECT_THROW(rss_lateral_m(in), std::invalid_argument);
  in = standard_lateral();
  in.left_width_m = -1.0;
  EXPECT_THROW(rss_lateral_m(in), std::invalid_argument);
}

// Generators over the realistic domain of the formulas; b_max of the front vehicle may lie below
// b_min of the rear one (a truck with weak brakes ahead of a car).
rc::Gen<LongitudinalInput> longitudinal_inputs() {
  return rc::gen::apply(
      [](int vr, int vf, int lr, int lf, int t, int a, int bmin, int bmax) {
        return LongitudinalInput{vr / 10.0, vf / 10.0, lr / 10.0, lf / 10.0, t / 100.0, a / 10.0,
                                 bmin / 10.0, bmax / 10.0};
      },
      rc::gen::inRange(0, 500), rc::gen::inRange(0, 500), rc::gen::inRange(0, 200), rc::gen::inRange(0, 200),
      rc::gen::inRange(0, 300), rc::gen::inRange(0, 100), rc::gen::inRange(1, 100), rc::gen::inRange(1, 150));
}

rc::Gen<LateralInput> lateral_inputs() {
  return rc::gen::apply(
      [](int vl, int vr, int wl, int wr, int t, int a, int b, int mu) {
        return LateralInput{vl / 10.0, vr / 10.0, wl / 10.0, wr / 10.0, t / 100.0, a / 10.0, b / 10.0, mu / 100.0};
      },
      rc::gen::inRange(-50, 50), rc::gen::inRange(-50, 50), rc::gen::inRange(0, 30), rc::gen::inRange(0, 30),
      rc::gen::inRange(0, 300), rc::gen::inRange(0, 30), rc::gen::inRange(1, 30), rc::gen::inRange(0, 100));
}

RC_GTEST_PROP(RssLongitudinal, EqualsThePrintedRssTermWhenTheFrontBrakesAtLeastAsHard, ()) {
  auto in = *longitudinal_inputs();
  in.brake_max_mps2 = std::max(in.brake_max_mps2, in.brake_min_mps2);
  const double expected = 0.5 * (in.rear_length_m + in.front_length_m) + std::max(0.0, final_stop_closing_m(in));
  RC_ASSERT(std::abs(rss_longitudinal_m(in) - expected) <= 1e-9 * (1.0 + expected));
}

RC_GTEST_PROP(RssLongitudinal, EqualsTheLargestClosingOfTheWorstCaseMotion, ()) {
  const auto in = *longitudinal_inputs();
  const double closing_m = rss_longitudinal_m(in) - 0.5 * (in.rear_length_m + in.front_length_m);
  // The 1 ms scan can only miss a little of the true maximum, never exceed it.
  const double scanned_m = scanned_max_closing_m(in);
  RC_ASSERT(closing_m >= scanned_m - 1e-6);
  RC_ASSERT(closing_m <= scanned_m + 0.01);
}

RC_GTEST_PROP(RssLongitudinal, NeverBelowBumperContact, ()) {
  const auto in = *longitudinal_inputs();
  RC_ASSERT(rss_longitudinal_m(in) >= 0.5 * (in.rear_length_m + in.front_length_m));
}

RC_GTEST_PROP(RssLongitudinal, SafeDistanceGrowsWithRearSpeed, ()) {
  const auto in = *longitudinal_inputs();
  auto faster = in;
  faster.rear_speed_mps += *rc::gen::inRange(1, 100) / 10.0;
  RC_ASSERT(rss_longitudinal_m(faster) >= rss_longitudinal_m(in));
}

RC_GTEST_PROP(RssLongitudinal, SafeDistanceGrowsWithResponseTime, ()) {
  const auto in = *longitudinal_inputs();
  auto slower_response = in;
  slower_response.response_time_s += *rc::gen::inRange(1, 100) / 100.0;
  RC_ASSERT(rss_longitudinal_m(slower_response) >= rss_longitudinal_m(in));
}

RC_GTEST_PROP(RssLongitudinal, SafeDistanceShrinksWithFrontSpeed, ()) {
  const auto in = *longitudinal_inputs();
  auto faster_front = in;
  faster_front.front_speed_mps += *rc::gen::inRange(1, 100) / 10.0;
  RC_ASSERT(rss_longitudinal_m(faster_front) <= rss_longitudinal_m(in));
}

RC_GTEST_PROP(RssLateral, NeverBelowMarginPlusHalfWidths, ()) {
  const auto in = *lateral_inputs();
  RC_ASSERT(rss_lateral_m(in) >= in.fluctuation_margin_m + 0.5 * (in.left_width_m + in.right_width_m));
}

RC_GTEST_PROP(RssLateral, MirrorSymmetric, ()) {
  // Mirroring the road (Y -> -Y) swaps left and right and negates both lateral speeds.
  const auto in = *lateral_inputs();
  LateralInput mirrored = in;
  mirrored.left_lat_speed_mps = -in.right_lat_speed_mps;
  mirrored.right_lat_speed_mps = -in.left_lat_speed_mps;
  mirrored.left_width_m = in.right_width_m;
  mirrored.right_width_m = in.left_width_m;
  RC_ASSERT(std::abs(rss_lateral_m(mirrored) - rss_lateral_m(in)) <= 1e-9);
}

}  // namespace
}  // namespace mg
