#include "planner/definition1.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/demand.h"
#include "core/rss.h"

namespace mg {

SpeedRamp Def1Context::ramp_to(double ve_star_mps) const {
  return SpeedRamp{ego_speed_mps, ve_star_mps, ego_limits.accel_max_mps2, ego_limits.brake_min_mps2};
}

namespace {

// Ineq. (1.1) at rho/2 with the ego at position x_m and speed v_m.
double ineq11_at(const Def1Context& c, const MainLaneVehicle& follower, double x_m, double v_mps) {
  const double half_s = 0.5 * c.merge_duration_s;
  const double a_f = follower.limits.accel_max_mps2;
  const double follower_x_m = follower.x_m + follower.speed_mps * half_s + a_f * c.merge_duration_s * c.merge_duration_s / 8.0;
  const double d_lon_m = rss_longitudinal_m({follower.speed_mps + a_f * half_s, v_mps, follower.length_m, c.ego_length_m,
                                             c.response_time_s, a_f, follower.limits.brake_min_mps2,
                                             c.ego_limits.brake_max_mps2});
  return (x_m - d_lon_m) - follower_x_m;
}

// Ineq. (1.2) at time t_s with the ego at position x_m and speed v_m.
double ineq12_at(const Def1Context& c, const MainLaneVehicle& leader, double t_s, double x_m, double v_mps) {
  const double d_lon_m = rss_longitudinal_m({v_mps, leader.speed_mps, c.ego_length_m, leader.length_m,
                                             c.response_time_s, c.ego_limits.accel_max_mps2,
                                             c.ego_limits.brake_min_mps2, leader.limits.brake_max_mps2});
  return (leader.x_m + leader.speed_mps * t_s - d_lon_m) - x_m;
}

}  // namespace

// RCPP ineq. (1.1); Def. 1.1 (spec §4): the paper's literal form (ego at v_e* from T_dec) and the
// bounded-rate fix (the ego ramps to v_e*) must both hold.
double def1_1_margin_m(const Def1Context& c, const MainLaneVehicle& follower, double ve_star_mps) {
  const double half_s = 0.5 * c.merge_duration_s;
  const SpeedRamp ramp = c.ramp_to(ve_star_mps);
  return std::min(ineq11_at(c, follower, c.ego_x_m + ve_star_mps * half_s, ve_star_mps),
                  ineq11_at(c, follower, c.ego_x_m + ramp.distance_at_m(half_s), ramp.speed_at_mps(half_s)));
}

// RCPP ineq. (1.2); Def. 1.2 (spec §4): over the interval [T_dec, T_dec + rho], checked at rho/2
// and rho, in the paper's literal form and with the bounded-rate fix.
double def1_2_margin_m(const Def1Context& c, const MainLaneVehicle& leader, double ve_star_mps) {
  const SpeedRamp ramp = c.ramp_to(ve_star_mps);
  double margin = std::numeric_limits<double>::infinity();
  for (const double t : {0.5 * c.merge_duration_s, c.merge_duration_s}) {
    margin = std::min(margin, ineq12_at(c, leader, t, c.ego_x_m + ve_star_mps * t, ve_star_mps));
    margin = std::min(margin, ineq12_at(c, leader, t, c.ego_x_m + ramp.distance_at_m(t), ramp.speed_at_mps(t)));
  }
  return margin;
}

std::vector<LaneGap> enumerate_gaps(std::vector<MainLaneVehicle> lane_vehicles) {
  std::sort(lane_vehicles.begin(), lane_vehicles.end(), lane_order_before);
  std::vector<LaneGap> gaps;
  std::optional<MainLaneVehicle> follower;
  for (const MainLaneVehicle& v : lane_vehicles) {
    gaps.push_back(LaneGap{follower, v});
    follower = v;
  }
  gaps.push_back(LaneGap{follower, std::nullopt});
  return gaps;
}

SpeedInterval solve_def1_interval(const Def1Context& c, const LaneGap& gap) {
  MG_DEMAND(c.speed_limit_mps > 0.0 && c.merge_duration_s > 0.0);
  double lo = 0.0;
  double hi = c.speed_limit_mps;
  if (gap.follower) {
    const auto bound = lowest_satisfying(
        [&](double v) { return def1_1_margin_m(c, *gap.follower, v); }, lo, hi);
    if (!bound) return {};
    lo = *bound;
  }
  if (gap.leader) {
    const auto bound = highest_satisfying(
        [&](double v) { return def1_2_margin_m(c, *gap.leader, v); }, 0.0, c.speed_limit_mps);
    if (!bound || *bound < lo) return {};
    hi = *bound;
  }
  return SpeedInterval{true, lo, hi};
}

double halt_point_x_m(const Road& road, double halt_margin_m, double ego_length_m,
                      double standstill_merge_length_m) {
  return road.side_lane_end_x_m - halt_margin_m - 0.5 * ego_length_m - standstill_merge_length_m;
}

double halt_speed_cap_mps(double ego_x_m, double halt_x_m, double brake_mps2) {
  const double remaining_m = halt_x_m - ego_x_m;
  return remaining_m > 0.0 ? std::sqrt(2.0 * brake_mps2 * remaining_m) : 0.0;
}

}  // namespace mg
