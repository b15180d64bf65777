// The path back to the side lane's centre, after an aborted merge or from a start off-centre
// toward the main lane (docs/planner.md, "Return to the side lane").
#pragma once

#include <array>
#include <vector>

#include "planner/planner.h"

namespace mg {

// A quintic y(X) = sum c_i d^i, d = X - x0_m, over [0, length_m] from a lateral offset, slope
// dy/dX and curvature y'' at x0_m to y_end level (slope and curvature 0), straight on y_end after
// it: the Frenet-frame quintic of Werling et al. (ICRA 2010), in X rather than time.
struct Quintic {
  double x0_m = 0.0;
  double length_m = 0.0;
  std::array<double, 6> coeff{};
  double y_at_m(double x_m) const;               // x_m >= x0_m
  double curvature_at_per_m(double x_m) const;  // y''; 0 beyond the end
};
Quintic quintic_to_level(double x0_m, double y0_m, double slope0, double curvature0_per_m, double y_end_m,
                         double length_m);
// max |y''| over the span: y'' is a cubic, so its extremes are at the ends or at the roots of y'''
// (a quadratic); exact up to rounding.
double peak_curvature_per_m(const Quintic& q);

// The return, from the ego at (x0, y0) with slope0 (its direction of travel) to y_end below y0:
// 1. while slope0 > 0 (the ego still moves toward the main lane), a stop of that lateral motion at
//    constant curvature -stop_curvature: y = y0 + slope0 d - stop_curvature d^2 / 2 up to its
//    peak at d = slope0 / stop_curvature;
// 2. from there (or from the ego, with its slope, when slope0 <= 0) the shortest quintic to y_end
//    whose |y''| stays within the bound in use, starting with the stop's curvature.
// The path starts where and in the direction the ego is going. That matters at merge speeds: a
// path that starts level while the ego still moves toward the main lane makes the tracker reverse
// its steering at its cap, and the dynamic sideslip of that transient overshot the sideslip rule's
// bound (corpus cases rcpp__ego_never_liable__sideslip__ego-3 and -4). Behind x0 it extends along the
// start tangent.
struct ReturnPath {
  double x0_m = 0.0;
  double y0_m = 0.0;
  double slope0 = 0.0;
  double stop_curvature_per_m = 0.0;  // > 0 when there is a stop
  double stop_length_m = 0.0;
  Quintic back;
  double end_x_m() const { return back.x0_m + back.length_m; }
  double y_at_m(double x_m) const;
};

// What a return may do. Its |y''| stays within comfort_curvature_per_m (the comfort bound at the
// ego's speed) and cap_curvature_per_m (trackability and steady-state sideslip); the stop sharpens
// beyond comfort, up to the cap, where a comfortable one would carry the ego above y_max_m, toward
// the main lane's line: an ego that aborted its merge should not cross into the lane on its way
// back (one with sluggish lateral dynamics still can: it lags the planned stop).
struct ReturnLimits {
  double comfort_curvature_per_m = 0.0;
  double cap_curvature_per_m = 0.0;
  double y_max_m = 0.0;
};
// "Shortest within a bound": the first of kReturnMinLengthM * 2^k that fits, bisected against the
// one before it to within kReturnLengthTolerance (the shortest fitting length when fitting is
// monotone in the length). A long enough quintic always fits: its start curvature is within the
// bound and its own term never exceeds it; the offset's and the slope's fall as 1/length^2 and
// 1/length.
inline constexpr double kReturnMinLengthM = 1.0;
inline constexpr double kReturnLengthTolerance = 0.01;
ReturnPath plan_return_path(double x0_m, double y0_m, double slope0, double y_end_m, const ReturnLimits& limits);
// A stop of the lateral motion toward the main lane alone, level where it ends, never moving
// back (slope0 > 0; within the same limits as a return): an ego that aborted a merge it had
// barely begun holds its lateral position instead of swinging back (side_lane_path.cpp).
ReturnPath plan_lateral_hold(double x0_m, double y0_m, double slope0, const ReturnLimits& limits);
// Samples from x_from to x_to (inclusive, step_m apart, strictly increasing in X).
std::vector<PathPoint> sample_return_path(const ReturnPath& p, double x_from_m, double x_to_m, double step_m);

}  // namespace mg
