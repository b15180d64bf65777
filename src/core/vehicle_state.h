// Kinematic state of one vehicle in the road frame (DESIGN §2).
#pragma once

namespace mg {

struct VehicleState {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;          // from +X, counter-clockwise
  double vx_mps = 0.0;           // body-frame longitudinal speed
  double vy_mps = 0.0;           // body-frame lateral speed (ego single-track; 0 for others)
  double yaw_rate_radps = 0.0;
  double accel_mps2 = 0.0;       // applied longitudinal acceleration during the last step
  double steer_rad = 0.0;        // ego only
  bool operator==(const VehicleState&) const = default;

  // Road-frame velocity components.
  double road_vx_mps() const;
  double road_vy_mps() const;
};

}  // namespace mg
