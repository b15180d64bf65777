#include "sim/single_track.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/demand.h"

namespace mg {
namespace {

// Dynamic-model state X, Y, psi, v_x, v_y, r.
using DynState = std::array<double, 6>;

// Linear single-track model: lateral tyre forces F = C * alpha; the longitudinal command is
// the body-frame acceleration itself (v_x' = a), so the speed controller's command is exactly
// what the longitudinal dynamics deliver.
DynState dynamic_derivative(const DynState& s, double steer_rad, double cos_steer, double accel_mps2,
                            const EgoDynamics& d) {
  const double psi = s[2], vx = std::max(s[3], 0.1), vy = s[4], r = s[5];
  // Driving straight along X (every lateral quantity exactly zero): no tyre force, and the
  // general expression below evaluates to exactly this, without its four trigonometric calls.
  if (psi == 0.0 && vy == 0.0 && r == 0.0 && steer_rad == 0.0) return {s[3], 0.0, 0.0, accel_mps2, 0.0, 0.0};
  const double alpha_f = steer_rad - std::atan2(vy + d.cg_to_front_m * r, vx);
  const double alpha_r = -std::atan2(vy - d.cg_to_rear_m * r, vx);
  const double fyf = d.cornering_front_npr * alpha_f;
  const double fyr = d.cornering_rear_npr * alpha_r;
  return {s[3] * std::cos(psi) - vy * std::sin(psi),
          s[3] * std::sin(psi) + vy * std::cos(psi),
          r,
          accel_mps2,
          (fyf * cos_steer + fyr) / d.mass_kg - r * vx,
          (d.cg_to_front_m * fyf * cos_steer - d.cg_to_rear_m * fyr) / d.yaw_inertia_kgm2};
}

DynState axpy(const DynState& s, double h, const DynState& k) {
  DynState out;
  for (std::size_t i = 0; i < s.size(); ++i) out[i] = s[i] + h * k[i];
  return out;
}

// Number of RK4 sub-steps so that h * (largest lateral/yaw eigenvalue estimate) <= 0.5: the
// linear tyre model stiffens as 1/v_x.
int dynamic_substeps(const EgoDynamics& d, double vx_mps, double dt_s) {
  const double vx = std::max(vx_mps, kKinematicBelowMps);
  const double lf = d.cg_to_front_m, lr = d.cg_to_rear_m;
  const double lambda = (d.cornering_front_npr + d.cornering_rear_npr) / (d.mass_kg * vx) +
                        (lf * lf * d.cornering_front_npr + lr * lr * d.cornering_rear_npr) / (d.yaw_inertia_kgm2 * vx);
  return static_cast<int>(std::clamp(std::ceil(lambda * dt_s / 0.5), 1.0, 2000.0));
}

DynState step_dynamic(const VehicleState& v, double steer_rad, double accel_mps2, const EgoDynamics& d, double dt_s) {
  DynState s{v.x_m, v.y_m, v.yaw_rad, v.vx_mps, v.vy_mps, v.yaw_rate_radps};
  const int n = dynamic_substeps(d, v.vx_mps, dt_s);
  const double h = dt_s / n;
  const double cos_steer = std::cos(steer_rad);  // the steering angle holds over the step
  for (int i = 0; i < n; ++i) {
    const DynState k1 = dynamic_derivative(s, steer_rad, cos_steer, accel_mps2, d);
    const DynState k2 = dynamic_derivative(axpy(s, h / 2, k1), steer_rad, cos_steer, accel_mps2, d);
    const DynState k3 = dynamic_derivative(axpy(s, h / 2, k2), steer_rad, cos_steer, accel_mps2, d);
    const DynState k4 = dynamic_derivative(axpy(s, h, k3), steer_rad, cos_steer, accel_mps2, d);
    for (std::size_t j = 0; j < s.size(); ++j) s[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    s[3] = std::max(s[3], 0.0);
  }
  return s;
}

// Kinematic bicycle model about the centre of gravity: slip angle beta = atan(l_r tan(delta)/L),
// speed v along the velocity vector, which never reverses (braking stops at v = 0).
DynState step_kinematic(const VehicleState& v, double steer_rad, double accel_mps2, const EgoDynamics& d, double dt_s) {
  const double speed = std::hypot(v.vx_mps, v.vy_mps);
  double speed_new = speed + accel_mps2 * dt_s;
  double mean_speed = 0.5 * (speed + speed_new);
  if (speed_new < 0.0) {  // stops within the step
    speed_new = 0.0;
    mean_speed = speed * speed / (2.0 * -accel_mps2) / dt_s;
  }
  const double length = d.wheelbase_m();
  const double beta = std::atan(d.cg_to_rear_m * std::tan(steer_rad) / length);
  const double yaw_rate_per_speed = std::cos(beta) * std::tan(steer_rad) / length;
  const double yaw_mid = v.yaw_rad + 0.5 * mean_speed * yaw_rate_per_speed * dt_s;
  return {v.x_m + mean_speed * std::cos(yaw_mid + beta) * dt_s,
          v.y_m + mean_speed * std::sin(yaw_mid + beta) * dt_s,
          v.yaw_rad + mean_speed * yaw_rate_per_speed * dt_s,
          speed_new * std::cos(beta),
          speed_new * std::sin(beta),
          speed_new * yaw_rate_per_speed};
}

}  // namespace

double limit_steering(double current_rad, double request_rad, const EgoDynamics& d, double dt_s) {
  const double max_change = d.steer_rate_max_radps * dt_s;
  const double moved = current_rad + std::clamp(request_rad - current_rad, -max_change, max_change);
  return std::clamp(moved, -d.steer_max_rad, d.steer_max_rad);
}

double limit_accel(double request_mps2, const Limits& limits) {
  return std::clamp(request_mps2, -limits.brake_max_mps2, limits.accel_max_mps2);
}

VehicleState step_single_track(const VehicleState& s, const EgoCommand& cmd, const EgoDynamics& d,
                               const Limits& limits, double dt_s) {
  MG_DEMAND(dt_s > 0.0);
  const double steer = limit_steering(s.steer_rad, cmd.steer_rad, d, dt_s);
  const double accel = limit_accel(cmd.accel_mps2, limits);
  const double speed = std::hypot(s.vx_mps, s.vy_mps);
  const double w_dyn = std::clamp((speed - kKinematicBelowMps) / (kDynamicAboveMps - kKinematicBelowMps), 0.0, 1.0);

  DynState next{};
  if (w_dyn >= 1.0) {
    next = step_dynamic(s, steer, accel, d, dt_s);
  } else if (w_dyn <= 0.0) {
    next = step_kinematic(s, steer, accel, d, dt_s);
  } else {
    const DynState dyn = step_dynamic(s, steer, accel, d, dt_s);
    const DynState kin = step_kinematic(s, steer, accel, d, dt_s);
    for (std::size_t i = 0; i < next.size(); ++i) next[i] = w_dyn * dyn[i] + (1.0 - w_dyn) * kin[i];
  }

  VehicleState out = s;
  out.x_m = next[0];
  out.y_m = next[1];
  out.yaw_rad = next[2];
  out.vx_mps = std::max(next[3], 0.0);
  out.vy_mps = next[4];
  out.yaw_rate_radps = next[5];
  out.steer_rad = steer;
  // The acceleration actually applied: at standstill a braking request applies nothing.
  out.accel_mps2 = (speed <= 0.0 && accel < 0.0) ? 0.0 : accel;
  if (out.vx_mps == 0.0 && out.accel_mps2 < 0.0) out.accel_mps2 = -speed / dt_s;
  return out;
}

double sideslip_rad(const VehicleState& s) {
  if (s.vx_mps == 0.0 && s.vy_mps == 0.0) return 0.0;
  return std::atan2(s.vy_mps, s.vx_mps);
}

double understeer_gradient(const EgoDynamics& d) {
  return d.mass_kg / d.wheelbase_m() *
         (d.cg_to_rear_m / d.cornering_front_npr - d.cg_to_front_m / d.cornering_rear_npr);
}

double steady_state_yaw_rate_gain(const EgoDynamics& d, double speed_mps) {
  return speed_mps / (d.wheelbase_m() + understeer_gradient(d) * speed_mps * speed_mps);
}

}  // namespace mg
