#include "planner/proper_response.h"

#include <algorithm>
#include <cmath>

#include "core/rss.h"
#include "planner/world_view.h"

namespace mg {

std::optional<Danger> rss_danger_ahead(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const double v_e = ego_speed_mps(w);
  const double vy_e = ego_lat_speed_mps(w);
  for (const ObservedVehicle& o : w.others) {
    const double lon_m = o.state.x_m - w.ego.x_m;
    if (lon_m <= 0.0) continue;
    // RCPP eq. (1), the ego as the rear vehicle.
    const double d_lon_m = rss_longitudinal_m({v_e, std::max(0.0, o.state.road_vx_mps()), s.ego.size.length_m,
                                               o.size.length_m, s.params.rss.response_time_s,
                                               s.ego.limits.accel_max_mps2, s.ego.limits.brake_min_mps2,
                                               o.limits.brake_max_mps2});
    if (lon_m >= d_lon_m) continue;
    // RCPP eq. (2) (RSS Def. 4 signs), left = the vehicle with the larger Y.
    const bool ego_left = w.ego.y_m > o.state.y_m;
    const double vy_o = o.state.road_vy_mps();
    const double d_lat_m = rss_lateral_m({ego_left ? vy_e : vy_o, ego_left ? vy_o : vy_e,
                                          ego_left ? s.ego.size.width_m : o.size.width_m,
                                          ego_left ? o.size.width_m : s.ego.size.width_m,
                                          s.params.rss.response_time_s, s.ego.limits.lat_accel_max_mps2,
                                          s.ego.limits.lat_brake_min_mps2, s.params.rss.fluctuation_margin_m});
    const double lat_m = std::abs(o.state.y_m - w.ego.y_m);
    if (lat_m >= d_lat_m) continue;
    return Danger{o.id, lon_m, d_lon_m, lat_m, d_lat_m};
  }
  return std::nullopt;
}

}  // namespace mg
