#include "rules/collision_monitor.h"

#include <sstream>
#include <utility>
#include <vector>

#include "rules/near_pairs.h"

namespace mg {

BoxPose box_pose_of(const ObservedTrace& s, const ObservedStep& step, std::size_t k) {
  const ObservedState& v = state_of(step, k);
  const VehicleSize& z = size_of(s, k);
  return {v.x_m, v.y_m, v.yaw_rad, z.length_m, z.width_m, z.height_m};
}

MonitorOutput monitor_collision(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  const std::size_t n = s.vehicles.size();
  MarginAccumulator acc("collision", steps.size());
  std::vector<BoxPose> pose_prev(n), pose_now(n);
  std::vector<Footprint> fp_now(n), swept(n);
  std::vector<double> lo_m(n), hi_m(n);
  NearPairs near;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    for (std::size_t v = 0; v < n; ++v) {
      pose_now[v] = box_pose_of(s, steps[k], v);
      const Footprint fp = footprint_of(pose_now[v]);
      swept[v] = k == 0 ? fp : unite(fp_now[v], fp);  // fp_now still holds step k-1 here
      fp_now[v] = fp;
      if (k == 0) pose_prev[v] = pose_now[v];
    }
    for (std::size_t v = 0; v < n; ++v) {
      lo_m[v] = swept[v].x_lo;
      hi_m[v] = swept[v].x_hi;
    }
    // Interaction bound: the clearance now is at least the X separation of the swept
    // rectangles; a pair apart by more than the smallest margin so far cannot touch (no FCL) nor
    // lower the rule's minimum, so it is not measured (exact: the same RuleResult). The pairs
    // come in the order of the loop over all pairs.
    for (const auto& [i, j] : near.find(lo_m, hi_m, acc.min_margin())) {
      const double x_apart_m = std::max(swept[j].x_lo - swept[i].x_hi, swept[i].x_lo - swept[j].x_hi);
      if (x_apart_m > 0.0 && x_apart_m >= acc.min_margin()) continue;
      PairCheck c;
      if (clearance_m(swept[i], swept[j]) > 0.0) {  // pre-filter: FCL only for pairs that could touch
        c.margin_m = clearance_m(fp_now[i], fp_now[j]);
      } else {
        c = check_box_pair_fcl(pose_prev[i], pose_now[i], pose_prev[j], pose_now[j], clearance_m(fp_now[i], fp_now[j]));
      }
      if (acc.record(k, steps[k].time_s, c.margin_m, Party::nobody(), 0.0, c.margin_m)) {
        std::ostringstream os;
        os << party_name(party_of(s, i)) << " and " << party_name(party_of(s, j)) << " collided at t = "
           << steps[k].time_s << " s (x = " << pose_now[i].x_m << " m"
           << (c.by_continuous ? ", found by the continuous check between steps" : "") << ")";
        const PairGeometry start = pair_geometry(s, steps[0], i, j);
        if (start.lon_unsafe() && start.lat_unsafe())
          os << "; the pair was already in a dangerous situation at t = 0 (the scenario starts unsafe, so no "
                "obligation could be broken before it)";
        acc.set_detail(os.str());
      }
    }
    std::swap(pose_prev, pose_now);
  }
  return acc.finish();
}

}  // namespace mg
