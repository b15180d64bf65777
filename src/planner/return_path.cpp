#include "planner/return_path.h"

#include <algorithm>
#include <cmath>

#include "core/demand.h"

namespace mg {

double Quintic::y_at_m(double x_m) const {
  const double d = std::min(x_m - x0_m, length_m);
  return coeff[0] + d * (coeff[1] + d * (coeff[2] + d * (coeff[3] + d * (coeff[4] + d * coeff[5]))));
}

double Quintic::curvature_at_per_m(double x_m) const {
  const double d = x_m - x0_m;
  if (d > length_m) return 0.0;
  return 2.0 * coeff[2] + d * (6.0 * coeff[3] + d * (12.0 * coeff[4] + d * 20.0 * coeff[5]));
}

// Boundary-value quintic (Takahashi et al. 1989; Werling et al. 2010, eq. 4) with the end state
// (y_end, 0, 0).
Quintic quintic_to_level(double x0_m, double y0_m, double slope0, double curvature0_per_m, double y_end_m,
                         double length_m) {
  MG_DEMAND(length_m > 0.0);
  const double L = length_m, rise = y_end_m - y0_m, c0 = curvature0_per_m;
  return Quintic{x0_m, L,
                 {y0_m, slope0, 0.5 * c0, (20.0 * rise - 12.0 * slope0 * L - 3.0 * c0 * L * L) / (2.0 * L * L * L),
                  (-30.0 * rise + 16.0 * slope0 * L + 3.0 * c0 * L * L) / (2.0 * L * L * L * L),
                  (12.0 * rise - 6.0 * slope0 * L - c0 * L * L) / (2.0 * L * L * L * L * L)}};
}

double peak_curvature_per_m(const Quintic& q) {
  double peak = std::max(std::abs(q.curvature_at_per_m(q.x0_m)), std::abs(q.curvature_at_per_m(q.x0_m + q.length_m)));
  const double a = 60.0 * q.coeff[5], b = 24.0 * q.coeff[4], c = 6.0 * q.coeff[3];  // y''' = a d^2 + b d + c
  const auto visit = [&](double d) {
    if (d > 0.0 && d < q.length_m) peak = std::max(peak, std::abs(q.curvature_at_per_m(q.x0_m + d)));
  };
  if (a == 0.0) {
    if (b != 0.0) visit(-c / b);
  } else if (const double disc = b * b - 4.0 * a * c; disc >= 0.0) {
    visit((-b + std::sqrt(disc)) / (2.0 * a));
    visit((-b - std::sqrt(disc)) / (2.0 * a));
  }
  return peak;
}

double ReturnPath::y_at_m(double x_m) const {
  const double d = x_m - x0_m;
  if (d < 0.0) return y0_m + slope0 * d;
  if (d < stop_length_m) return y0_m + d * (slope0 - 0.5 * stop_curvature_per_m * d);
  return back.y_at_m(x_m);
}

namespace {

// The shortest quintic from (x, y, slope 0 or s, curvature c) to level at y_end whose |y''| stays
// within bound_per_m (the header's "shortest within a bound").
Quintic shortest_to_level(double x_m, double y_m, double slope, double curvature_per_m, double y_end_m,
                          double bound_per_m) {
  const auto quintic_of = [&](double length_m) {
    return quintic_to_level(x_m, y_m, slope, curvature_per_m, y_end_m, length_m);
  };
  double too_short_m = 0.0, long_enough_m = kReturnMinLengthM;
  const auto fits = [&](double length_m) { return peak_curvature_per_m(quintic_of(length_m)) <= bound_per_m; };
  for (int k = 0; k < 40 && !fits(long_enough_m); ++k) {  // fits long before 2^40 m (header)
    too_short_m = long_enough_m;
    long_enough_m *= 2.0;
  }
  while (long_enough_m - too_short_m > kReturnLengthTolerance * long_enough_m) {
    const double mid_m = 0.5 * (too_short_m + long_enough_m);
    (fits(mid_m) ? long_enough_m : too_short_m) = mid_m;
  }
  return quintic_of(long_enough_m);
}

// Step 1 of the header: the stop of the lateral motion toward the main lane, when there is one.
// Returns the path so far and sets where the next part starts.
ReturnPath lateral_stop(double x0_m, double y0_m, double slope0, const ReturnLimits& limits, double& start_x_m,
                        double& start_y_m, double& start_slope, double& start_curvature_per_m) {
  const double bound_per_m = std::min(limits.comfort_curvature_per_m, limits.cap_curvature_per_m);
  ReturnPath p{x0_m, y0_m, slope0, 0.0, 0.0, {}};
  start_x_m = x0_m, start_y_m = y0_m, start_slope = slope0, start_curvature_per_m = 0.0;
  if (slope0 > 0.0) {
    // A stop at the bound rises slope0^2 / (2 c); sharpen it to peak at y_max if that is higher.
    const double room_m = limits.y_max_m - y0_m;
    const double needed_per_m = room_m > 0.0 ? slope0 * slope0 / (2.0 * room_m) : limits.cap_curvature_per_m;
    p.stop_curvature_per_m = std::max(bound_per_m, std::min(needed_per_m, limits.cap_curvature_per_m));
    p.stop_length_m = slope0 / p.stop_curvature_per_m;
    start_x_m += p.stop_length_m;
    start_y_m += 0.5 * slope0 * p.stop_length_m;
    start_slope = 0.0;
    start_curvature_per_m = -std::min(p.stop_curvature_per_m, bound_per_m);
  }
  return p;
}

}  // namespace

ReturnPath plan_return_path(double x0_m, double y0_m, double slope0, double y_end_m, const ReturnLimits& limits) {
  MG_DEMAND(y_end_m < y0_m && std::isfinite(slope0));
  MG_DEMAND(limits.cap_curvature_per_m > 0.0 && limits.comfort_curvature_per_m > 0.0);
  double x_m = 0.0, y_m = 0.0, slope = 0.0, curvature_per_m = 0.0;
  ReturnPath p = lateral_stop(x0_m, y0_m, slope0, limits, x_m, y_m, slope, curvature_per_m);
  p.back = shortest_to_level(x_m, y_m, slope, curvature_per_m, y_end_m,
                             std::min(limits.comfort_curvature_per_m, limits.cap_curvature_per_m));
  return p;
}

ReturnPath plan_lateral_hold(double x0_m, double y0_m, double slope0, const ReturnLimits& limits) {
  MG_DEMAND(slope0 > 0.0 && limits.cap_curvature_per_m > 0.0 && limits.comfort_curvature_per_m > 0.0);
  // The quintic from slope0 (curvature 0) to level that rises half of slope0 * length: its slope,
  // slope0 (1 - u)^2 (1 + 2u) at u = d / length, never changes sign, and its |y''| peaks at
  // 1.5 slope0 / length (mid-way). So length = 1.5 slope0 / c and the rise 0.75 slope0^2 / c for
  // the curvature bound c, sharpened (up to the cap) where the rise would reach y_max.
  const double bound_per_m = std::min(limits.comfort_curvature_per_m, limits.cap_curvature_per_m);
  const double room_m = limits.y_max_m - y0_m;
  const double needed_per_m = room_m > 0.0 ? 0.75 * slope0 * slope0 / room_m : limits.cap_curvature_per_m;
  const double c_per_m = std::max(bound_per_m, std::min(needed_per_m, limits.cap_curvature_per_m));
  const double length_m = 1.5 * slope0 / c_per_m;
  ReturnPath p{x0_m, y0_m, slope0, 0.0, 0.0, {}};
  p.back = quintic_to_level(x0_m, y0_m, slope0, 0.0, y0_m + 0.5 * slope0 * length_m, length_m);
  return p;
}

std::vector<PathPoint> sample_return_path(const ReturnPath& p, double x_from_m, double x_to_m, double step_m) {
  return sample_path(x_from_m, x_to_m, step_m, [&](double x) { return p.y_at_m(x); });
}

}  // namespace mg
