#include "rules/collision_monitor.h"

#include <sstream>

namespace mg {

BoxPose box_pose_of(const Scenario& s, const TraceStep& step, std::size_t k) {
  const VehicleState& v = state_of(step, k);
  const VehicleSize& z = size_of(s, k);
  return {v.x_m, v.y_m, v.yaw_rad, z.length_m, z.width_m, z.height_m};
}

MonitorOutput monitor_collision(const MonitorContext& ctx) {
  const Scenario& s = ctx.scenario;
  const auto& steps = ctx.trace.steps;
  const std::size_t n = s.vehicles.size() + 1;
  MarginAccumulator acc("collision", steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const TraceStep& prev = steps[k == 0 ? 0 : k - 1];
    for (std::size_t i = 0; i < n; ++i) {
      const BoxPose a0 = box_pose_of(s, prev, i);
      const BoxPose a1 = box_pose_of(s, steps[k], i);
      for (std::size_t j = i + 1; j < n; ++j) {
        const PairCheck c = check_box_pair(a0, a1, box_pose_of(s, prev, j), box_pose_of(s, steps[k], j));
        if (acc.record(k, steps[k].time_s, c.margin_m, kNobody, 0.0, c.margin_m)) {
          std::ostringstream os;
          os << party_name(party_of(s, i)) << " and " << party_name(party_of(s, j)) << " collided at t = "
             << steps[k].time_s << " s (x = " << a1.x_m << " m"
             << (c.by_continuous ? ", found by the continuous check between steps" : "") << ")";
          acc.set_detail(os.str());
        }
      }
    }
  }
  return acc.finish();
}

}  // namespace mg
