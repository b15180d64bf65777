#include "planner/definition2.h"

#include <algorithm>

#include "core/rss.h"

namespace mg {

double d_lon_ego_rear_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps) {
  return rss_longitudinal_m({coop_ego_speed_after_mps(c, CoopCase::kEgoBehind), vo_star_mps, c.ego_length_m,
                             responder.length_m, c.response_time_s, c.ego_limits.accel_max_mps2,
                             c.ego_limits.brake_min_mps2, responder.limits.brake_max_mps2});
}

namespace {

// The responder starts when the request arrives: request_latency_s late at v_o instead of v_o*.
double latency_shift_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps) {
  return c.request_latency_s * (responder.speed_mps - vo_star_mps);
}

}  // namespace

double coop_ego_speed_after_mps(const CoopContext& c, CoopCase k) {
  if (k == CoopCase::kEgoAhead) return c.ego_speed_mps;
  return std::max(0.0, c.ego_speed_mps - c.ego_limits.brake_min_mps2 * c.comm_threshold_s);
}

double coop_ego_travel_m(const CoopContext& c, CoopCase k) {
  const SpeedRamp ramp{c.ego_speed_mps, coop_ego_speed_after_mps(c, k), c.ego_limits.accel_max_mps2,
                       c.ego_limits.brake_min_mps2};
  return ramp.distance_at_m(c.comm_threshold_s);
}

double coop_pc_m(const CoopContext& c, CoopCase k) {
  return c.ego_x_m + coop_ego_travel_m(c, k) + coop_ego_speed_after_mps(c, k) * 0.5 * c.merge_duration_s;
}

// RCPP Def. 2 (D*_lon), eq. (1) with the responder as the rear vehicle.
double d_lon_star_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps) {
  return rss_longitudinal_m({vo_star_mps, coop_ego_speed_after_mps(c, CoopCase::kEgoAhead), responder.length_m,
                             c.ego_length_m, c.response_time_s, responder.limits.accel_max_mps2,
                             responder.limits.brake_min_mps2, c.ego_limits.brake_max_mps2});
}

// RCPP ineq. (3); Def. 2.1 B.
double ineq3_margin_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps) {
  const double responder_x_m = responder.x_m + 0.5 * (responder.speed_mps + vo_star_mps) * c.comm_threshold_s +
                               vo_star_mps * 0.5 * c.merge_duration_s + latency_shift_m(c, responder, vo_star_mps);
  return coop_pc_m(c, CoopCase::kEgoAhead) - d_lon_star_m(c, responder, vo_star_mps) - responder_x_m -
         c.planning_buffer_m;
}

double ineq3_start_margin_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps) {
  const double responder_x_m = responder.x_m + 0.5 * (responder.speed_mps + vo_star_mps) * c.comm_threshold_s +
                               latency_shift_m(c, responder, vo_star_mps);
  return c.ego_x_m + coop_ego_travel_m(c, CoopCase::kEgoAhead) - d_lon_star_m(c, responder, vo_star_mps) -
         responder_x_m - c.planning_buffer_m;
}

// RCPP ineq. (4); Def. 2.2 B.
double ineq4_margin_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps) {
  const double responder_side_m = responder.x_m + 0.5 * (vo_star_mps + responder.speed_mps) * c.comm_threshold_s +
                                  latency_shift_m(c, responder, vo_star_mps) -
                                  d_lon_ego_rear_m(c, responder, vo_star_mps);
  return responder_side_m - (c.ego_x_m + coop_ego_travel_m(c, CoopCase::kEgoBehind)) - c.planning_buffer_m;
}

SpeedInterval vo_star_domain(const CoopContext& c, const MainLaneVehicle& responder, CoopCase k) {
  const double v_o = responder.speed_mps;
  if (k == CoopCase::kEgoAhead)
    return {true, std::max(0.0, v_o - responder.limits.brake_min_mps2 * c.comm_threshold_s), v_o};
  const double reachable = std::min(v_o + responder.limits.accel_max_mps2 * c.comm_threshold_s, c.speed_limit_mps);
  return {true, v_o, std::max(v_o, reachable)};
}

VoStar solve_vo_star(const CoopContext& c, const MainLaneVehicle& responder, CoopCase k) {
  const SpeedInterval domain = vo_star_domain(c, responder, k);
  VoStar out;
  out.coop_case = k;
  out.pc_m = coop_pc_m(c, k);
  std::optional<double> vo;
  if (k == CoopCase::kEgoAhead) {
    vo = highest_satisfying(
        [&](double v) { return std::min(ineq3_margin_m(c, responder, v), ineq3_start_margin_m(c, responder, v)); },
        domain.lo_mps, domain.hi_mps);
    if (vo) out.d_lon_star_m = d_lon_star_m(c, responder, *vo);
  } else {
    vo = lowest_satisfying([&](double v) { return ineq4_margin_m(c, responder, v); }, domain.lo_mps, domain.hi_mps);
    if (vo) out.d_lon_star_m = d_lon_ego_rear_m(c, responder, *vo);
  }
  if (!vo) return out;
  out.feasible = true;
  out.vo_star_mps = *vo;
  return out;
}

}  // namespace mg
