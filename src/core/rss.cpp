#include "core/rss.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mg {
namespace {

void require_non_negative(double x, const char* name) {
  if (!(std::isfinite(x) && x >= 0.0))
    throw std::invalid_argument(std::string(name) + ": must be finite and >= 0, got " + std::to_string(x));
}

void require_positive(double x, const char* name) {
  if (!(std::isfinite(x) && x > 0.0))
    throw std::invalid_argument(std::string(name) + ": must be finite and > 0, got " + std::to_string(x));
}

void require_finite(double x, const char* name) {
  if (!std::isfinite(x)) throw std::invalid_argument(std::string(name) + ": must be finite");
}

}  // namespace

void reject_longitudinal_input(const LongitudinalInput& in) {
  require_non_negative(in.rear_speed_mps, "rear_speed_mps");
  require_non_negative(in.front_speed_mps, "front_speed_mps");
  require_non_negative(in.rear_length_m, "rear_length_m");
  require_non_negative(in.front_length_m, "front_length_m");
  require_non_negative(in.response_time_s, "response_time_s");
  require_non_negative(in.accel_max_mps2, "accel_max_mps2");
  require_positive(in.brake_min_mps2, "brake_min_mps2");
  require_positive(in.brake_max_mps2, "brake_max_mps2");
  throw std::invalid_argument("rss_longitudinal_m: inputs out of range");  // e.g. finite parts, infinite sum
}

void reject_lateral_input(const LateralInput& in) {
  require_finite(in.left_lat_speed_mps, "left_lat_speed_mps");
  require_finite(in.right_lat_speed_mps, "right_lat_speed_mps");
  require_non_negative(in.left_width_m, "left_width_m");
  require_non_negative(in.right_width_m, "right_width_m");
  require_non_negative(in.response_time_s, "response_time_s");
  require_non_negative(in.lat_accel_max_mps2, "lat_accel_max_mps2");
  require_positive(in.lat_brake_min_mps2, "lat_brake_min_mps2");
  require_non_negative(in.fluctuation_margin_m, "fluctuation_margin_m");
  throw std::invalid_argument("rss_lateral_m: inputs out of range");
}

}  // namespace mg
