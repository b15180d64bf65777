// RSS safe distances (RCPP eq. 1 and 2; Shalev-Shwartz et al., arXiv:1708.06374 Def. 1 and 4),
// with the two deviations of DESIGN §3: lengths/widths outside the clamp, and the lateral
// braking term of the right vehicle with the RSS sign. Pure, total functions: out-of-domain
// inputs (negative or non-finite) raise std::invalid_argument naming the argument.
#pragma once

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
double rss_longitudinal_m(const LongitudinalInput& in);

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

// RCPP eq. (2) corrected per RSS Def. 4 (DESIGN §3):
//   D = mu + (w_L + w_R)/2 + [d_L - d_R]_+
double rss_lateral_m(const LateralInput& in);

}  // namespace mg
