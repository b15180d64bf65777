// A planner that decides an acceleration (the car-following models, a trajectory's s''(t)) and
// must speak PlanOutput's speed command: a target speed and the |acceleration| the speed
// controller may use toward it.
#pragma once

namespace mg {

struct SpeedCommand {
  double target_speed_mps = 0.0;
  double accel_limit_mps2 = 0.0;
};

// The target a second of `accel_mps2` away, inside [0, speed_limit_mps], with |accel_mps2| as the
// limit: a speed controller of gain >= 1/s then applies accel_mps2 itself until the target is
// reached, whatever its gain. The limit is at least kMinAccelLimitMps2 (PlanOutput asks for a
// positive one), so an acceleration of zero holds the speed.
inline constexpr double kMinAccelLimitMps2 = 0.05;
SpeedCommand speed_command_for_accel(double speed_mps, double accel_mps2, double speed_limit_mps);

}  // namespace mg
