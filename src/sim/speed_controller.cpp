#include "sim/speed_controller.h"

#include <algorithm>

namespace mg {

double speed_command_mps2(const PlanOutput& plan, double speed_mps, const Limits& limits) {
  const double band = std::max(plan.accel_limit_mps2, 0.0);
  double a = std::clamp(kSpeedGainPerS * (plan.target_speed_mps - speed_mps), -band, band);
  if (plan.proper_response) a = std::min(a, -limits.brake_min_mps2);
  return std::clamp(a, -limits.brake_max_mps2, limits.accel_max_mps2);
}

}  // namespace mg
