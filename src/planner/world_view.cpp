#include "planner/world_view.h"

#include <algorithm>
#include <cmath>

#include "core/rss.h"

namespace mg {

double ego_speed_mps(const WorldSnapshot& w) { return std::max(0.0, w.ego.road_vx_mps()); }
double ego_lat_speed_mps(const WorldSnapshot& w) { return w.ego.road_vy_mps(); }

double tracked_path_ahead_m(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const double cycle_s = s.params.sim.planner_cycle_s;
  const double reach_speed_mps = ego_speed_mps(w) + s.ego.limits.accel_max_mps2 * cycle_s;
  return 10.0 + reach_speed_mps * (cycle_s + 1.0);
}

MainLaneVehicle to_lane_vehicle(const ObservedVehicle& o) {
  return MainLaneVehicle{o.id, o.state.x_m, std::max(0.0, o.state.road_vx_mps()),
                         o.size.length_m, o.size.width_m, o.limits};
}

std::vector<MainLaneVehicle> target_lane_vehicles(const WorldSnapshot& w) {
  const double half_lane_m = 0.5 * w.setup->road.lane_width_m;
  std::vector<MainLaneVehicle> lane;
  for (const ObservedVehicle& o : w.others)
    if (std::abs(o.state.y_m) < half_lane_m) lane.push_back(to_lane_vehicle(o));
  std::sort(lane.begin(), lane.end(), [](const MainLaneVehicle& a, const MainLaneVehicle& b) {
    return a.x_m != b.x_m ? a.x_m < b.x_m : a.id < b.id;
  });
  return lane;
}

std::optional<MainLaneVehicle> leader_ahead_of(const std::vector<MainLaneVehicle>& lane, double x_m) {
  for (const MainLaneVehicle& v : lane)
    if (v.x_m > x_m) return v;
  return std::nullopt;
}

double rss_follow_speed_mps(const WorldSnapshot& w, const MainLaneVehicle& leader) {
  const PlannerSetup& s = *w.setup;
  const double gap_m = leader.x_m - w.ego.x_m - kFollowBufferM;
  const auto margin = [&](double v) {
    return gap_m - rss_longitudinal_m({v, leader.speed_mps, s.ego.size.length_m, leader.length_m,
                                       s.params.rss.response_time_s, s.ego.limits.accel_max_mps2,
                                       s.ego.limits.brake_min_mps2, leader.limits.brake_max_mps2});
  };
  return highest_satisfying(margin, 0.0, s.road.speed_limit_mps, 1e-4).value_or(0.0);
}

}  // namespace mg
