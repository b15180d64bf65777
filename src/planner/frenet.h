// The formulas and checks of the `frenet` baseline (planner/frenet_planner.h), after M. Werling,
// J. Ziegler, S. Kammel, S. Thrun, "Optimal Trajectory Generation for Dynamic Street Scenarios in
// a Frenet Frame", ICRA 2010. The road is straight, so its Frenet frame is the road frame: s = X
// along the main lane's centre line, d = Y.
//
// - lateral movement (their §III-A, high speeds): the quintic d(t) from the start state
//   (d0, d0', d0'') to (d1, 0, 0) at T, the jerk-optimal connection of two states (their eq. (1)
//   ff.: the minimiser of the integral of the squared jerk is a quintic);
// - longitudinal movement, velocity keeping (their §III-B): the quartic s(t) from (s0, s0', s0'')
//   to (s1', 0) at T, the position at T left free;
// - cost of a pair: C = k_lat C_d + k_lon C_s with C_d = k_j J_d + k_t T + k_d (d1 - d_goal)^2 and
//   C_s = k_j J_s + k_t T + k_s (s1' - v_desired)^2, J the integral of the squared jerk (their
//   cost functionals of §III-A and §III-B and the combination of §III-C);
// - validity (their §III-C): every sample within the acceleration and curvature limits, and no
//   collision with the obstacles predicted at constant velocity (their "static and dynamic
//   collision check"); here the side lane's end is the static obstacle.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace mg {

// c0 + c1 t + ... + c5 t^5.
struct QuinticPolynomial {
  std::array<double, 6> c{};
  double at(double t_s) const;
  double d1(double t_s) const;  // first derivative
  double d2(double t_s) const;
  double d3(double t_s) const;
};
// c0 + c1 t + ... + c4 t^4.
struct QuarticPolynomial {
  std::array<double, 5> c{};
  double at(double t_s) const;
  double d1(double t_s) const;
  double d2(double t_s) const;
  double d3(double t_s) const;
};

// The quintic with value, slope and curvature (x0, v0, a0) at 0 and (x1, v1, a1) at duration_s.
QuinticPolynomial quintic_between(double x0, double v0, double a0, double x1, double v1, double a1, double duration_s);
// The quartic with (x0, v0, a0) at 0 and slope and curvature (v1, a1) at duration_s.
QuarticPolynomial quartic_velocity_keeping(double x0, double v0, double a0, double v1, double a1, double duration_s);

// The Frenet state the candidates start from.
struct FrenetStart {
  double s_m = 0.0, s_dot_mps = 0.0, s_ddot_mps2 = 0.0;
  double d_m = 0.0, d_dot_mps = 0.0, d_ddot_mps2 = 0.0;
};

// One sampled trajectory: lateral quintic and longitudinal quartic over duration_s, then held (d
// at its end, speed at its end) to any later time.
struct FrenetTrajectory {
  QuinticPolynomial lateral;
  QuarticPolynomial longitudinal;
  double duration_s = 0.0;
  double end_d_m = 0.0;        // d1
  double end_speed_mps = 0.0;  // s1'
  double cost = 0.0;           // C, set by frenet_cost
  double s_at(double t_s) const;
  double d_at(double t_s) const;
  double s_dot_at(double t_s) const;
  double d_dot_at(double t_s) const;
};
FrenetTrajectory frenet_trajectory(const FrenetStart& start, double end_d_m, double end_speed_mps, double duration_s);

struct FrenetCostWeights {
  double jerk = 0.1;          // k_j
  double time = 0.1;          // k_t
  double deviation = 1.0;     // k_d
  double speed = 1.0;         // k_s
  double lateral = 1.0;       // k_lat
  double longitudinal = 1.0;  // k_lon
};
// The integral of the squared third derivative over [0, duration_s], by the midpoint rule at step_s.
double squared_jerk_integral(const QuinticPolynomial& q, double duration_s, double step_s);
double squared_jerk_integral(const QuarticPolynomial& q, double duration_s, double step_s);
// C = k_lat C_d + k_lon C_s (above), d_goal the lateral offset the planner wants to reach.
double frenet_cost(const FrenetTrajectory& t, double d_goal_m, double desired_speed_mps, const FrenetCostWeights& k,
                   double step_s);

// An obstacle predicted at constant velocity: centre (x_m + speed_mps t, y_m).
struct PredictedObstacle {
  int id = 0;
  double x_m = 0.0, y_m = 0.0, speed_mps = 0.0;
  double length_m = 0.0, width_m = 0.0;
};

// What a candidate is checked against.
struct FrenetScene {
  double ego_length_m = 0.0, ego_width_m = 0.0;
  double accel_max_mps2 = 0.0;     // longitudinal, forward
  double brake_max_mps2 = 0.0;     // longitudinal, magnitude
  double lat_accel_max_mps2 = 0.0;
  double curvature_max_per_m = 0.0;
  double lane_width_m = 3.5;
  double side_lane_end_x_m = 0.0;  // where the side lane (Y below -W/2) physically ends
  double margin_m = 0.0;           // added to every obstacle's extent
  double horizon_s = 0.0;          // collisions are checked to here (past the trajectory's end: held)
  double step_s = 0.1;             // sampling of the checks
  std::vector<PredictedObstacle> obstacles;
};

enum class FrenetVerdict { kValid, kReverses, kAccel, kLatAccel, kCurvature, kCollision, kSideLaneEnd, kNotChecked };
std::string to_string(FrenetVerdict v);

// The curvature of the path (s(t), d(t)): |s' d'' - d' s''| / |v|^3, with |v| no lower than
// kCurvatureMinSpeedMps (a trajectory that moves sideways at rest is judged at that speed).
inline constexpr double kCurvatureMinSpeedMps = 1.0;
double frenet_curvature_per_m(const FrenetTrajectory& t, double t_s);

// Whether the ego's box centred at (ego_x_m, ego_y_m) and the obstacle's at time t_s overlap:
// their centres closer than half_length_sum_m along X and half_width_sum_m across (the sums of
// the two half extents, grown by whatever margin the caller adds).
bool boxes_meet(double ego_x_m, double ego_y_m, const PredictedObstacle& o, double t_s, double half_length_sum_m,
                double half_width_sum_m);

// Limits over [0, duration_s], collisions and the side lane's end over [0, horizon_s]. A sample
// stands for the half step either side: the boxes are grown by the relative motion of half a step.
FrenetVerdict check_trajectory(const FrenetTrajectory& t, const FrenetScene& scene);

}  // namespace mg
