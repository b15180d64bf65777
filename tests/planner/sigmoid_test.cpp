// Sigmoid planner (src/planner/sigmoid.cpp): shape of f_sig (RCPP §II-C), comfort bound, and the
// candidate search.
#include "planner/sigmoid.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg {
namespace {

Sigmoid gen_sigmoid() {
  return Sigmoid{*rc::gen::inRange(20, 60) / 10.0, *rc::gen::inRange(1, 1000) / 1000.0,
                 *rc::gen::inRange(-5000, 5000) / 10.0, *rc::gen::inRange(-100, 100) / 10.0};
}

RC_GTEST_PROP(Sigmoid, MonotoneAndWithinOffsetAndOffsetPlusWidth, ()) {
  const Sigmoid s = gen_sigmoid();
  double prev = s.offset_m;
  for (int i = -400; i <= 400; ++i) {
    const double y = s.y_at_m(s.pc_m + i * 0.05 / s.kappa_per_m);
    RC_ASSERT(y >= prev);
    RC_ASSERT(y >= s.offset_m);
    RC_ASSERT(y <= s.offset_m + s.width_m);
    prev = y;
  }
}

RC_GTEST_PROP(Sigmoid, MidpointIsHalfWayAndFractionsInvert, ()) {
  const Sigmoid s = gen_sigmoid();
  RC_ASSERT(std::abs(s.y_at_m(s.pc_m) - (s.offset_m + s.width_m / 2)) < 1e-9);
  const double f = *rc::gen::inRange(1, 99) / 100.0;
  RC_ASSERT(std::abs(s.y_at_m(s.x_at_fraction_m(f)) - (s.offset_m + f * s.width_m)) < 1e-9 * (1 + s.width_m));
}

TEST(Sigmoid, PeakLateralAccelerationMatchesNumericCurvature) {
  // Max |y''| of the logistic is W kappa^2 / (6 sqrt 3); at 20 m/s, W = 3.5, kappa = 0.1:
  // 400 * 3.5 * 0.01 / 10.392 = 1.347 m/s2.
  const Sigmoid s{3.5, 0.1, 0.0, -3.5};
  double max_ypp = 0;
  const double h = 1e-3;
  for (double x = -60; x <= 60; x += 0.01)
    max_ypp = std::max(max_ypp, std::abs(s.y_at_m(x + h) - 2 * s.y_at_m(x) + s.y_at_m(x - h)) / (h * h));
  EXPECT_NEAR(sigmoid_peak_lat_accel_mps2(20, 3.5, 0.1), 400 * max_ypp, 1e-3);
  EXPECT_NEAR(sigmoid_peak_lat_accel_mps2(20, 3.5, 0.1), 1.3472, 1e-4);
}

// peak_lat_accel_along_mps2 skips samples that cannot beat the peak so far (docs/performance.md):
// it must return exactly the maximum over all 41 samples, whatever the ramp (speeding up, slowing
// down, to a stop) and wherever it starts relative to the sigmoid.
RC_GTEST_PROP(Sigmoid, PeakLateralAccelerationIsTheMaximumOverEverySample, ()) {
  const Sigmoid sig = gen_sigmoid();
  const SpeedRamp ramp{*rc::gen::inRange(0, 400) / 10.0, *rc::gen::inRange(0, 400) / 10.0,
                       *rc::gen::inRange(1, 50) / 10.0, *rc::gen::inRange(1, 90) / 10.0};
  const double origin_x_m = sig.pc_m + *rc::gen::inRange(-3000, 1000) / 10.0;
  double full = 0.0;
  for (int i = 0; i <= 40; ++i) {  // the samples: u = kappa (x - P_c) from -4 to 4, every 0.2
    const double u = 4.0 * (2.0 * i / 40 - 1.0);
    const double sgm = 1.0 / (1.0 + std::exp(-u));
    const double x = sig.pc_m + u / sig.kappa_per_m;
    const double ypp = sig.width_m * sig.kappa_per_m * sig.kappa_per_m * sgm * (1.0 - sgm) * std::abs(1.0 - 2.0 * sgm);
    full = std::max(full, ramp.speed_squared_at_distance_m2ps2(std::max(0.0, x - origin_x_m)) * ypp);
  }
  RC_ASSERT(peak_lat_accel_along_mps2(sig, ramp, origin_x_m) == full);
  // The profile-free bound the comfort search uses to skip flat sigmoids is never below it.
  RC_ASSERT(peak_lat_accel_bound_mps2(sig, ramp) >= full);
}

RC_GTEST_PROP(Sigmoid, ComfortBoundIsTheLargestComfortableKappa, ()) {
  const double v = *rc::gen::inRange(1, 400) / 10.0;
  const double w = *rc::gen::inRange(20, 60) / 10.0;
  const double a = *rc::gen::inRange(1, 50) / 10.0;
  const double k = kappa_comfort_max_per_m(v, w, a);
  RC_ASSERT(std::abs(sigmoid_peak_lat_accel_mps2(v, w, k) - a) < 1e-9 * a);
  RC_ASSERT(sigmoid_peak_lat_accel_mps2(v, w, 1.01 * k) > a);
}

RC_GTEST_PROP(Sigmoid, ChosenCandidateLiesWithinBounds, ()) {
  const double pc_min = *rc::gen::inRange(0, 1000) / 10.0;
  const double pc_max = pc_min + *rc::gen::inRange(0, 1000) / 10.0;
  const double k_lo = *rc::gen::inRange(1, 100) / 1000.0;
  const double k_hi = k_lo + *rc::gen::inRange(0, 100) / 1000.0;
  const double pc_pref = *rc::gen::inRange(0, 2000) / 10.0;
  const auto choice = choose_sigmoid(
      even_grid(pc_min, pc_max, *rc::gen::inRange(1, 20)),
      [&](double) -> KappaRange { return std::make_pair(k_lo, k_hi); },
      *rc::gen::inRange(1, 10), [&](double pc, double kappa) { return std::abs(pc - pc_pref) + kappa; });
  RC_ASSERT(choice.has_value());
  RC_ASSERT(choice->param >= pc_min && choice->param <= pc_max);
  RC_ASSERT(choice->kappa_per_m >= k_lo && choice->kappa_per_m <= k_hi);
}

TEST(Sigmoid, NoAdmissibleKappaMeansNoChoice) {
  const auto choice = choose_sigmoid(
      even_grid(0, 10, 5), [](double) -> KappaRange { return std::nullopt; }, 5, [](double, double) { return 0.0; });
  EXPECT_FALSE(choice.has_value());
}

}  // namespace
}  // namespace mg
