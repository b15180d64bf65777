// Kinematic state of one vehicle in the road frame (spec §2).
#pragma once

#include <cmath>

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

  // Road-frame velocity components. Heading exactly along X (every main-lane vehicle, the ego on a
  // straight stretch) needs no trigonometry: cos(+-0) = 1 and sin(+-0) = +-0, so the same value.
  double road_vx_mps() const {
    if (yaw_rad == 0.0) return vx_mps - vy_mps * yaw_rad;
    return vx_mps * std::cos(yaw_rad) - vy_mps * std::sin(yaw_rad);
  }
  double road_vy_mps() const {
    if (yaw_rad == 0.0) return vx_mps * yaw_rad + vy_mps;
    return vx_mps * std::sin(yaw_rad) + vy_mps * std::cos(yaw_rad);
  }
};

}  // namespace mg
