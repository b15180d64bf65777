#include "planner/frenet.h"

#include <algorithm>
#include <cmath>

#include "core/demand.h"

namespace mg {

double QuinticPolynomial::at(double t) const { return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5])))); }
double QuinticPolynomial::d1(double t) const { return c[1] + t * (2 * c[2] + t * (3 * c[3] + t * (4 * c[4] + t * 5 * c[5]))); }
double QuinticPolynomial::d2(double t) const { return 2 * c[2] + t * (6 * c[3] + t * (12 * c[4] + t * 20 * c[5])); }
double QuinticPolynomial::d3(double t) const { return 6 * c[3] + t * (24 * c[4] + t * 60 * c[5]); }
double QuarticPolynomial::at(double t) const { return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * c[4]))); }
double QuarticPolynomial::d1(double t) const { return c[1] + t * (2 * c[2] + t * (3 * c[3] + t * 4 * c[4])); }
double QuarticPolynomial::d2(double t) const { return 2 * c[2] + t * (6 * c[3] + t * 12 * c[4]); }
double QuarticPolynomial::d3(double t) const { return 6 * c[3] + t * 24 * c[4]; }

QuinticPolynomial quintic_between(double x0, double v0, double a0, double x1, double v1, double a1, double T) {
  MG_DEMAND(T > 0.0);
  // Werling et al. 2010 §III-A: the jerk-optimal connection is the quintic whose first three
  // coefficients are the start state; the last three solve the end conditions at T.
  const double h = x1 - x0 - v0 * T - 0.5 * a0 * T * T;  // position still to go
  const double dv = v1 - v0 - a0 * T;                     // speed still to change
  const double da = a1 - a0;
  const double T2 = T * T, T3 = T2 * T;
  return QuinticPolynomial{{x0, v0, 0.5 * a0, (10.0 * h - 4.0 * dv * T + 0.5 * da * T2) / T3,
                  (-15.0 * h + 7.0 * dv * T - da * T2) / (T3 * T), (6.0 * h - 3.0 * dv * T + 0.5 * da * T2) / (T3 * T2)}};
}

QuarticPolynomial quartic_velocity_keeping(double x0, double v0, double a0, double v1, double a1, double T) {
  MG_DEMAND(T > 0.0);
  // Werling et al. 2010 §III-B, velocity keeping: the end position is free, so a quartic; its last
  // two coefficients solve the end speed and acceleration at T.
  const double dv = v1 - v0 - a0 * T;
  const double da = a1 - a0;
  return QuarticPolynomial{{x0, v0, 0.5 * a0, (3.0 * dv - da * T) / (3.0 * T * T), (-2.0 * dv + da * T) / (4.0 * T * T * T)}};
}

double FrenetTrajectory::s_at(double t) const {
  if (t <= duration_s) return longitudinal.at(t);
  return longitudinal.at(duration_s) + end_speed_mps * (t - duration_s);
}
double FrenetTrajectory::d_at(double t) const { return t <= duration_s ? lateral.at(t) : end_d_m; }
double FrenetTrajectory::s_dot_at(double t) const { return t <= duration_s ? longitudinal.d1(t) : end_speed_mps; }
double FrenetTrajectory::d_dot_at(double t) const { return t <= duration_s ? lateral.d1(t) : 0.0; }

FrenetTrajectory frenet_trajectory(const FrenetStart& a, double end_d_m, double end_speed_mps, double duration_s) {
  FrenetTrajectory t;
  t.lateral = quintic_between(a.d_m, a.d_dot_mps, a.d_ddot_mps2, end_d_m, 0.0, 0.0, duration_s);
  t.longitudinal = quartic_velocity_keeping(a.s_m, a.s_dot_mps, a.s_ddot_mps2, end_speed_mps, 0.0, duration_s);
  t.duration_s = duration_s;
  t.end_d_m = end_d_m;
  t.end_speed_mps = end_speed_mps;
  return t;
}

template <class Poly>
double jerk_integral(const Poly& q, double duration_s, double step_s) {
  MG_DEMAND(step_s > 0.0);
  const int n = std::max(1, static_cast<int>(std::ceil(duration_s / step_s - 1e-9)));
  const double h = duration_s / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double j = q.d3((i + 0.5) * h);
    sum += j * j * h;
  }
  return sum;
}
double squared_jerk_integral(const QuinticPolynomial& q, double duration_s, double step_s) { return jerk_integral(q, duration_s, step_s); }
double squared_jerk_integral(const QuarticPolynomial& q, double duration_s, double step_s) { return jerk_integral(q, duration_s, step_s); }

double frenet_cost(const FrenetTrajectory& t, double d_goal_m, double desired_speed_mps, const FrenetCostWeights& k,
                   double step_s) {
  const double dd = t.end_d_m - d_goal_m;
  const double dv = t.end_speed_mps - desired_speed_mps;
  // Werling et al. 2010 §III-A (lateral), §III-B (velocity keeping), §III-C (their sum).
  const double lateral = k.jerk * squared_jerk_integral(t.lateral, t.duration_s, step_s) + k.time * t.duration_s + k.deviation * dd * dd;
  const double longitudinal =
      k.jerk * squared_jerk_integral(t.longitudinal, t.duration_s, step_s) + k.time * t.duration_s + k.speed * dv * dv;
  return k.lateral * lateral + k.longitudinal * longitudinal;
}

std::string to_string(FrenetVerdict v) {
  switch (v) {
    case FrenetVerdict::kValid: return "valid";
    case FrenetVerdict::kReverses: return "reverses";
    case FrenetVerdict::kAccel: return "acceleration";
    case FrenetVerdict::kLatAccel: return "lateral acceleration";
    case FrenetVerdict::kCurvature: return "curvature";
    case FrenetVerdict::kCollision: return "collision";
    case FrenetVerdict::kSideLaneEnd: return "side lane end";
    case FrenetVerdict::kNotChecked: return "not checked";
  }
  return "?";
}

double frenet_curvature_per_m(const FrenetTrajectory& t, double time_s) {
  if (time_s > t.duration_s) return 0.0;  // held: straight
  const double sd = t.longitudinal.d1(time_s), sdd = t.longitudinal.d2(time_s);
  const double dd = t.lateral.d1(time_s), ddd = t.lateral.d2(time_s);
  const double speed = std::max(std::hypot(sd, dd), kCurvatureMinSpeedMps);
  return std::abs(sd * ddd - dd * sdd) / (speed * speed * speed);
}

bool boxes_meet(double ego_x_m, double ego_y_m, const PredictedObstacle& o, double t_s, double half_length_sum_m,
                double half_width_sum_m) {
  return std::abs(o.x_m + o.speed_mps * t_s - ego_x_m) < half_length_sum_m && std::abs(o.y_m - ego_y_m) < half_width_sum_m;
}

namespace {

FrenetVerdict check_limits(const FrenetTrajectory& t, const FrenetScene& sc, double time_s) {
  constexpr double kTolerance = 1e-9;
  if (t.longitudinal.d1(time_s) < -1e-6) return FrenetVerdict::kReverses;
  const double a = t.longitudinal.d2(time_s);
  if (a > sc.accel_max_mps2 + kTolerance || a < -sc.brake_max_mps2 - kTolerance) return FrenetVerdict::kAccel;
  if (std::abs(t.lateral.d2(time_s)) > sc.lat_accel_max_mps2 + kTolerance) return FrenetVerdict::kLatAccel;
  if (frenet_curvature_per_m(t, time_s) > sc.curvature_max_per_m + kTolerance) return FrenetVerdict::kCurvature;
  return FrenetVerdict::kValid;
}

FrenetVerdict check_surroundings(const FrenetTrajectory& t, const FrenetScene& sc, double time_s) {
  const double x = t.s_at(time_s), y = t.d_at(time_s);
  // Half a step of motion either side of the sample: the sampled check then covers the step.
  const double half_step = 0.5 * sc.step_s;
  const double ego_dx = std::abs(t.s_dot_at(time_s)) * half_step, ego_dy = std::abs(t.d_dot_at(time_s)) * half_step;
  if (y - 0.5 * sc.ego_width_m - ego_dy < -0.5 * sc.lane_width_m && x + 0.5 * sc.ego_length_m + ego_dx > sc.side_lane_end_x_m)
    return FrenetVerdict::kSideLaneEnd;
  for (const PredictedObstacle& o : sc.obstacles) {
    const double rel_dx = std::abs(t.s_dot_at(time_s) - o.speed_mps) * half_step;
    if (boxes_meet(x, y, o, time_s, 0.5 * (sc.ego_length_m + o.length_m) + sc.margin_m + rel_dx,
                   0.5 * (sc.ego_width_m + o.width_m) + sc.margin_m + ego_dy))
      return FrenetVerdict::kCollision;
  }
  return FrenetVerdict::kValid;
}

}  // namespace

FrenetVerdict check_trajectory(const FrenetTrajectory& t, const FrenetScene& sc) {
  MG_DEMAND(sc.step_s > 0.0);
  const int n = static_cast<int>(std::ceil(std::max(sc.horizon_s, t.duration_s) / sc.step_s - 1e-9));
  for (int i = 0; i <= n; ++i) {
    const double time_s = i * sc.step_s;
    if (time_s <= t.duration_s + 1e-12)
      if (const FrenetVerdict v = check_limits(t, sc, time_s); v != FrenetVerdict::kValid) return v;
    if (const FrenetVerdict v = check_surroundings(t, sc, time_s); v != FrenetVerdict::kValid) return v;
  }
  return FrenetVerdict::kValid;
}

}  // namespace mg
