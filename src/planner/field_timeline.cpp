#include "planner/field_timeline.h"

#include <algorithm>
#include <utility>

#include "core/rss.h"
#include "planner/world_view.h"

namespace mg {
namespace {

// (D_lat, D_lon) between the ego and each other vehicle at the decision instant, the one behind
// answering for the longitudinal distance.
std::vector<std::pair<double, double>> rss_distances(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const double v_e = ego_speed_mps(w);
  std::vector<std::pair<double, double>> d_lat_lon;
  for (const ObservedVehicle& o : w.others) {
    const double v_o = std::max(0.0, o.state.road_vx_mps());
    const bool ego_rear = o.state.x_m >= w.ego.x_m;
    const double d_lon = ego_rear
        ? rss_longitudinal_m({v_e, v_o, s.ego.size.length_m, o.size.length_m, s.params.rss.response_time_s,
                              s.ego.limits.accel_max_mps2, s.ego.limits.brake_min_mps2, o.limits.brake_max_mps2})
        : rss_longitudinal_m({v_o, v_e, o.size.length_m, s.ego.size.length_m, s.params.rss.response_time_s,
                              o.limits.accel_max_mps2, o.limits.brake_min_mps2, s.ego.limits.brake_max_mps2});
    const double d_lat = rss_lateral_m({0.0, 0.0, o.size.width_m, s.ego.size.width_m, s.params.rss.response_time_s,
                                        s.ego.limits.lat_accel_max_mps2, s.ego.limits.lat_brake_min_mps2,
                                        s.params.rss.fluctuation_margin_m});
    d_lat_lon.emplace_back(d_lat, d_lon);
  }
  return d_lat_lon;
}

}  // namespace

FieldTimeline field_timeline(const WorldSnapshot& w, double duration_s,
                             const std::function<double(const ObservedVehicle&, double)>& other_x_at) {
  const PlannerSetup& s = *w.setup;
  const std::vector<std::pair<double, double>> d_lat_lon = rss_distances(w);
  FieldTimeline field{duration_s, {}};
  field.scenes.reserve(kFieldSamples + 1);
  for (int k = 0; k <= kFieldSamples; ++k) {
    const double t = duration_s * k / kFieldSamples;
    FieldScene scene{&s.road, s.ego.size.width_m, {}, 0.0, LaneCentreMode::kMerging};
    for (std::size_t i = 0; i < w.others.size(); ++i)
      scene.obstacles.push_back(obstacle_field_from_rss(other_x_at(w.others[i], t), w.others[i].state.y_m,
                                                        d_lat_lon[i].first, d_lat_lon[i].second));
    field.scenes.push_back(std::move(scene));
  }
  return field;
}

double field_cost_floor(const RcppParams& p) {
  const double floor = field_potential_floor(p, LaneCentreMode::kMerging);
  double sum = 0.0;
  for (int k = 0; k <= kFieldSamples; ++k) sum += floor;
  return sum / (kFieldSamples + 1);
}

}  // namespace mg
