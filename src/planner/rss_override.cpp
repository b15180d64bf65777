#include "planner/rss_override.h"

#include <algorithm>

#include "core/fixed_text.h"
#include "planner/proper_response.h"
#include "planner/world_view.h"

namespace mg {

void apply_proper_response(const WorldSnapshot& w, RcppCycle& out) {
  const auto danger = rss_danger_ahead(w);
  if (!danger) return;
  const PlannerSetup& s = *w.setup;
  const auto o = std::find_if(w.others.begin(), w.others.end(),
                              [&](const ObservedVehicle& v) { return v.id == danger->vehicle_id; });
  out.proper_response = true;
  out.target_speed_mps = std::min(out.target_speed_mps, rss_follow_speed_mps(w, to_lane_vehicle(*o)));
  out.accel_limit_mps2 = std::max(out.accel_limit_mps2, s.ego.limits.brake_max_mps2);
  out.decision.mode = DecisionMode::kProperResponse;
  out.decision.reason = "RSS proper response: vehicle " + std::to_string(danger->vehicle_id) + " ahead at " +
                        fixed_text(danger->lon_distance_m, 1) + " m < D_lon " + fixed_text(danger->d_lon_m, 1) +
                        " m and lateral " + fixed_text(danger->lat_distance_m, 2) + " m < D_lat " +
                        fixed_text(danger->d_lat_m, 2) + " m; braking at least b_min (" + out.decision.reason + ")";
}

}  // namespace mg
