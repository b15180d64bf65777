// Ego vehicle dynamics (spec §7): dynamic single-track (bicycle) model with linear tyres,
// blended into the kinematic bicycle model at low speed so that the ego can halt and start
// again. States X, Y, psi, v_x, v_y, r live in VehicleState (body-frame v_x, v_y).
#pragma once

#include "core/scenario.h"
#include "core/vehicle_state.h"

namespace mg {

// Below kKinematicBelowMps the kinematic model alone is used, above kDynamicAboveMps the
// dynamic one alone; in between the two one-step results are blended linearly in speed.
inline constexpr double kKinematicBelowMps = 3.0;
inline constexpr double kDynamicAboveMps = 5.0;

struct EgoCommand {
  double steer_rad = 0.0;    // requested steering angle (rate- and angle-limited by the model)
  double accel_mps2 = 0.0;   // requested longitudinal acceleration (clamped to [-b_max, a_acc])
};

// Steering after one step of the actuator: moves toward the request at most
// steer_rate_max * dt and stays within +-steer_max.
double limit_steering(double current_rad, double request_rad, const EgoDynamics& d, double dt_s);

// Longitudinal acceleration inside the ego's physical envelope [-brake_max, accel_max].
double limit_accel(double request_mps2, const Limits& limits);

// Advances the ego by dt_s. The returned state carries the applied steering and acceleration.
// The ego never reverses: its longitudinal speed stays >= 0.
VehicleState step_single_track(const VehicleState& s, const EgoCommand& cmd, const EgoDynamics& d,
                               const Limits& limits, double dt_s);

// Sideslip angle at the centre of gravity, beta = atan2(v_y, v_x) (0 at standstill).
double sideslip_rad(const VehicleState& s);

// Understeer gradient K of the linear single-track model, K = m/L (l_r/C_f - l_f/C_r)
// (rad per m/s^2); steady-state yaw-rate gain r/delta = v / (L + K v^2).
double understeer_gradient(const EgoDynamics& d);
double steady_state_yaw_rate_gain(const EgoDynamics& d, double speed_mps);

}  // namespace mg
