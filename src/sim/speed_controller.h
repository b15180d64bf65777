// Longitudinal control of the ego (spec §7): a saturated proportional speed controller that
// tracks PlanOutput::target_speed_mps, and the RSS proper response override.
#pragma once

#include "core/scenario.h"
#include "planner/planner.h"

namespace mg {

inline constexpr double kSpeedGainPerS = 5.0;  // proportional gain on the speed error

// Acceleration request: k (v_target - v), |a| <= accel_limit_mps2, then inside
// [-brake_max, accel_max]. Under a proper response (RSS override, paper Fig. 1) the ego brakes
// at least brake_min (and at most brake_max) whatever the target says.
double speed_command_mps2(const PlanOutput& plan, double speed_mps, const Limits& limits);

}  // namespace mg
