#include "planner/rcpp_world.h"

#include <algorithm>
#include <cmath>

#include "core/rss.h"
#include "planner/rcpp_params.h"
#include "planner/sigmoid.h"
#include "planner/world_view.h"

namespace mg {

double planned_rho_m_s(const PlannerSetup& s) {
  return std::max(s.params.planner.merge_duration_s, s.params.rules.merge_duration_s);
}

Def1Context def1_context(const WorldSnapshot& w, double rho_s) {
  const PlannerSetup& s = *w.setup;
  return Def1Context{w.ego.x_m, ego_speed_mps(w), s.ego.size.length_m, s.ego.limits,
                     s.params.rss.response_time_s, rho_s, s.road.speed_limit_mps};
}

CoopContext coop_context(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  // v_o* with slack: solved exactly, ineq. (3) left the responder 0.29 m inside the ego's safe
  // distance at the midpoint once the request's latency delayed it (docs/planner.md).
  return CoopContext{w.ego.x_m,
                     ego_speed_mps(w),
                     s.ego.size.length_m,
                     s.ego.limits,
                     s.params.rss.response_time_s,
                     planned_rho_m_s(s),
                     s.params.planner.comm_threshold_s,
                     s.road.speed_limit_mps,
                     s.ego.v2v.latency_s,
                     kOccupancyPlanningBufferM};
}

const ObservedVehicle* observed_vehicle(const WorldSnapshot& w, int id) {
  for (const ObservedVehicle& o : w.others)
    if (o.id == id) return &o;
  return nullptr;
}

double observed_accel_mps2(const WorldSnapshot& w, int id) {
  const ObservedVehicle* o = observed_vehicle(w, id);
  return o ? o->state.accel_mps2 : 0.0;
}

LeaderHorizon leader_horizon(const WorldSnapshot& w, double horizon_s) {
  return LeaderHorizon{horizon_s, w.setup->params.rss.response_time_s};
}

Track predicted_leader(const WorldSnapshot& w, const std::vector<MainLaneVehicle>& lane, const MainLaneVehicle& l,
                       double horizon_s) {
  const MainLaneVehicle* ahead = next_in_lane(lane, l);
  const auto accel_of = [&](int id) { return observed_accel_mps2(w, id); };
  const LeaderHorizon h = leader_horizon(w, horizon_s);
  return leader_track(l, observed_accel_mps2(w, l.id), ahead, ahead ? chained_accel_mps2(lane, *ahead, accel_of, h) : 0.0,
                      h);
}

double leader_bound_margin_m(const PlannerSetup& s, const MainLaneVehicle& o, double x_o_m, double v_o_mps, double v_at_mps,
                             double pc_m) {
  const double dl = rss_longitudinal_m({v_at_mps, v_o_mps, s.ego.size.length_m, o.length_m,
                                        s.params.rss.response_time_s, s.ego.limits.accel_max_mps2,
                                        s.ego.limits.brake_min_mps2, o.limits.brake_max_mps2});
  return x_o_m - dl - pc_m;
}

std::optional<double> time_to_reach_s(const WorldSnapshot& w, const SpeedRamp& ramp, double x_m) {
  const double to_m = x_m - w.ego.x_m;
  if (to_m <= 0.0) return 0.0;
  return lowest_satisfying([&](double t) { return ramp.distance_at_m(t) - to_m; }, 0.0, 600.0, 1e-4);
}

bool accelerating_beyond_limit(const WorldSnapshot& w, const ObservedVehicle& o) {
  return o.state.accel_mps2 > o.limits.accel_max_mps2 + w.setup->params.rules.accel_tolerance_mps2;
}

bool accelerating_beyond_limit(const WorldSnapshot& w, int id) {
  const ObservedVehicle* o = observed_vehicle(w, id);
  return o && accelerating_beyond_limit(w, *o);
}

bool braking_beyond_limit(const WorldSnapshot& w, int id) {
  const ObservedVehicle* o = observed_vehicle(w, id);
  return o && o->state.accel_mps2 < -(o->limits.brake_max_mps2 + w.setup->params.rules.accel_tolerance_mps2);
}

bool beyond_declared_limits(const WorldSnapshot& w, int id) {
  return accelerating_beyond_limit(w, id) || braking_beyond_limit(w, id);
}

bool can_still_halt(const WorldSnapshot& w) { return can_still_halt(w, w.setup->ego.limits.brake_min_mps2); }

bool can_still_halt(const WorldSnapshot& w, double brake_mps2) {
  const PlannerSetup& s = *w.setup;
  const double v = ego_speed_mps(w);
  const double room_m =
      s.road.side_lane_end_x_m - 0.5 * s.ego.size.length_m - w.ego.x_m - v * s.params.sim.planner_cycle_s;
  return room_m > 0.0 && v * v / (2.0 * brake_mps2) < room_m;
}

std::vector<BesideTrack> beside_tracks(const WorldSnapshot& w) {
  const double lane_w = w.setup->road.lane_width_m;
  std::vector<BesideTrack> tracks;
  for (const ObservedVehicle& o : w.others) {
    const double lane_y_m = std::round(o.state.y_m / lane_w) * lane_w;
    if (lane_y_m < 0.5 * lane_w) continue;  // the target lane
    tracks.push_back(beside_track(to_lane_vehicle(o), lane_y_m, o.state.accel_mps2, w.setup->road.speed_limit_mps));
  }
  return tracks;
}

double constant_speed_x(const ObservedVehicle& o, double t_s) {
  return o.state.x_m + std::max(0.0, o.state.road_vx_mps()) * t_s;
}

double standstill_merge_length_m(const PlannerSetup& s) {
  const RcppParams p = rcpp_params(s);
  const double kappa = std::max(
      p.kappa_min_per_m,
      std::min(kappa_comfort_max_per_m(kStandstillMergeSpeedMps, s.road.lane_width_m, p.lat_accel_comfort_mps2),
               kappa_cap_per_m(s)));
  return (half_span_times_kappa() + ln_ratio(side_lane_exit_fraction(s.ego.size.width_m, s.road.lane_width_m))) /
             kappa +
         kSideExitMarginM;
}

double accel_limit_toward(const PlannerSetup& s, double current_mps, double target_mps) {
  return target_mps >= current_mps ? s.ego.limits.accel_max_mps2 : s.ego.limits.brake_min_mps2;
}

}  // namespace mg
