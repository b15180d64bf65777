// RSS safe distances (RCPP eq. 1 and 2; Shalev-Shwartz et al., arXiv:1708.06374 Def. 1 and 4),
// with the two deviations of spec §3: lengths/widths outside the clamp, and the lateral
// braking term of the right vehicle with the RSS sign. Pure, total functions: out-of-domain
// inputs (negative or non-finite) raise std::invalid_argument naming the argument. Defined inline
// (below): the planner's searches and the monitors evaluate them millions of times a second.
#pragma once

#include <algorithm>
#include <cmath>

namespace mg {

struct LongitudinalInput {
  double rear_speed_mps;      // v_r >= 0
  double front_speed_mps;     // v_f >= 0
  double rear_length_m;       // l_r >= 0
  double front_length_m;      // l_f >= 0
  double response_time_s;     // T >= 0
  double accel_max_mps2;      // a_accel^max of the rear vehicle, >= 0
  double brake_min_mps2;      // a_brake^min of the rear vehicle, > 0
  double brake_max_mps2;      // a_brake^max of the front vehicle, > 0
};

// RCPP eq. (1), centre-to-centre; either role order (the ego may be rear or front).
//   D = (l_r + l_f)/2 + [v_r T + a T^2/2 + (v_r + a T)^2/(2 b_min) - v_f^2/(2 b_max)]_+
inline double rss_longitudinal_m(const LongitudinalInput& in);

struct LateralInput {
  double left_lat_speed_mps;   // v_L, road frame (+Y left); any finite value
  double right_lat_speed_mps;  // v_R, road frame
  double left_width_m;         // >= 0
  double right_width_m;        // >= 0
  double response_time_s;      // T >= 0
  double lat_accel_max_mps2;   // a_lat^max >= 0
  double lat_brake_min_mps2;   // a_lat,brake^min > 0
  double fluctuation_margin_m; // mu >= 0
};

// RCPP eq. (2) corrected per RSS Def. 4 (spec §3):
//   D = mu + (w_L + w_R)/2 + [d_L - d_R]_+
inline double rss_lateral_m(const LateralInput& in);

// Throw std::invalid_argument naming the first out-of-range field of `in` (rss.cpp).
[[noreturn]] void reject_longitudinal_input(const LongitudinalInput& in);
[[noreturn]] void reject_lateral_input(const LateralInput& in);

// ---- inline definitions ----
namespace rss_detail {

// Braking distance toward the other vehicle: s(v) = v^2 / (2 b) if v > 0 else 0 (RSS Def. 4).
inline double lateral_braking_distance_m(double speed_toward_mps, double brake_mps2) {
  return speed_toward_mps > 0.0 ? speed_toward_mps * speed_toward_mps / (2.0 * brake_mps2) : 0.0;
}

// Worst-case motion of RSS Def. 1 from the current instant: the rear vehicle accelerates at a for
// T and then brakes at b_min until it stops; the front vehicle brakes at b_max until it stops.
struct WorstCase {
  const LongitudinalInput& in;
  double rear_speed_after_t_mps() const { return in.rear_speed_mps + in.accel_max_mps2 * in.response_time_s; }
  double rear_stop_s() const { return in.response_time_s + rear_speed_after_t_mps() / in.brake_min_mps2; }
  double front_stop_s() const { return in.front_speed_mps / in.brake_max_mps2; }
  double rear_x_m(double t) const {
    const double tr = std::min(t, in.response_time_s);
    const double tb = std::clamp(t - in.response_time_s, 0.0, rear_stop_s() - in.response_time_s);
    return in.rear_speed_mps * tr + 0.5 * in.accel_max_mps2 * tr * tr + rear_speed_after_t_mps() * tb -
           0.5 * in.brake_min_mps2 * tb * tb;
  }
  double front_x_m(double t) const {
    const double tf = std::min(t, front_stop_s());
    return in.front_speed_mps * tf - 0.5 * in.brake_max_mps2 * tf * tf;
  }
  // How far the rear vehicle gets ahead of where it started relative to the front vehicle.
  double closing_m(double t) const { return rear_x_m(t) - front_x_m(t); }
};

}  // namespace rss_detail

// RCPP eq. (1); RSS arXiv:1708.06374 Def. 1. Deviations (spec §3, docs/rss.md): half-lengths
// outside [.]_+; and the bracket is the largest closing of the worst-case motion over time, not
// only at the final stop. The two agree whenever b_max,f >= b_min,r (then the closing is
// monotone after T and the RSS term v_r T + a T^2/2 + (v_r + a T)^2/(2 b_min) - v_f^2/(2 b_max)
// is its maximum); with a front vehicle that brakes more weakly than the rear one, the final
// positions can be far apart while the rear vehicle hits the front one on the way, so the
// maximum is taken at the instant their speeds are equal as well.
inline double rss_longitudinal_m(const LongitudinalInput& in) {
  // One branch on the hot path (planner and monitors call this millions of times); the named
  // checks run only to report what is wrong.
  const bool ok = in.rear_speed_mps >= 0.0 && in.front_speed_mps >= 0.0 && in.rear_length_m >= 0.0 &&
                  in.front_length_m >= 0.0 && in.response_time_s >= 0.0 && in.accel_max_mps2 >= 0.0 &&
                  in.brake_min_mps2 > 0.0 && in.brake_max_mps2 > 0.0 &&
                  std::isfinite(in.rear_speed_mps + in.front_speed_mps + in.rear_length_m + in.front_length_m +
                                in.response_time_s + in.accel_max_mps2 + in.brake_min_mps2 + in.brake_max_mps2);
  if (!ok) [[unlikely]] reject_longitudinal_input(in);
  const rss_detail::WorstCase m{in};
  const double t = in.response_time_s;
  const double v_rear_after_t = m.rear_speed_after_t_mps();
  const double final_closing = in.rear_speed_mps * t + 0.5 * in.accel_max_mps2 * t * t +
                               v_rear_after_t * v_rear_after_t / (2.0 * in.brake_min_mps2) -
                               in.front_speed_mps * in.front_speed_mps / (2.0 * in.brake_max_mps2);
  double closing = std::max(0.0, final_closing);
  if (in.brake_max_mps2 < in.brake_min_mps2) {
    // Up to T the closing speed only grows; after T it falls at b_min - b_max while both move, is
    // the rear speed once the front has stopped, minus the front speed once the rear has stopped.
    // So the maximum lies at T, where the speeds become equal while both move, or the rear stop.
    closing = std::max({closing, m.closing_m(t), m.closing_m(m.rear_stop_s())});
    const double t_equal = (in.front_speed_mps - v_rear_after_t - in.brake_min_mps2 * t) /
                           (in.brake_max_mps2 - in.brake_min_mps2);
    if (t_equal > t && t_equal < std::min(m.rear_stop_s(), m.front_stop_s())) closing = std::max(closing, m.closing_m(t_equal));
  }
  return 0.5 * (in.rear_length_m + in.front_length_m) + closing;
}

// RCPP eq. (2) corrected per RSS arXiv:1708.06374 Def. 4 (spec §3): the right vehicle's
// braking term enters with the RSS sign; widths outside [.]_+.
inline double rss_lateral_m(const LateralInput& in) {
  const bool ok = in.left_width_m >= 0.0 && in.right_width_m >= 0.0 && in.response_time_s >= 0.0 &&
                  in.lat_accel_max_mps2 >= 0.0 && in.lat_brake_min_mps2 > 0.0 && in.fluctuation_margin_m >= 0.0 &&
                  std::isfinite(in.left_lat_speed_mps + in.right_lat_speed_mps + in.left_width_m + in.right_width_m +
                                in.response_time_s + in.lat_accel_max_mps2 + in.lat_brake_min_mps2 +
                                in.fluctuation_margin_m);
  if (!ok) [[unlikely]] reject_lateral_input(in);
  const double t = in.response_time_s;
  // During T each accelerates toward the other (+Y is left: L moves down, R moves up).
  const double v_left_rho = in.left_lat_speed_mps - t * in.lat_accel_max_mps2;
  const double v_right_rho = in.right_lat_speed_mps + t * in.lat_accel_max_mps2;
  // Downward (toward R) travel of L and upward travel of R, both until they stop.
  const double d_left = -(in.left_lat_speed_mps + v_left_rho) / 2.0 * t +
                        rss_detail::lateral_braking_distance_m(-v_left_rho, in.lat_brake_min_mps2);
  const double d_right = -(in.right_lat_speed_mps + v_right_rho) / 2.0 * t -
                         rss_detail::lateral_braking_distance_m(v_right_rho, in.lat_brake_min_mps2);
  return in.fluctuation_margin_m + 0.5 * (in.left_width_m + in.right_width_m) +
         std::max(0.0, d_left - d_right);
}

}  // namespace mg
