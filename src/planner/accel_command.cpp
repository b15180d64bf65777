#include "planner/accel_command.h"

#include <algorithm>
#include <cmath>

namespace mg {

SpeedCommand speed_command_for_accel(double speed_mps, double accel_mps2, double speed_limit_mps) {
  constexpr double kLookaheadS = 1.0;  // >= 1 / gain of any speed controller worth the name
  return {std::clamp(speed_mps + accel_mps2 * kLookaheadS, 0.0, speed_limit_mps),
          std::max(std::abs(accel_mps2), kMinAccelLimitMps2)};
}

}  // namespace mg
