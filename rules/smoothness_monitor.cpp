#include "rules/smoothness_monitor.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mg {

MonitorOutput monitor_smoothness_oscillation(const MonitorContext& ctx) {
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("smoothness_oscillation", steps.size());
  int merges = ctx.phases.count(MergePhaseKind::kStart);
  // An aborted merge (spec §6: abort when the P_c bounds cross) is a merge attempt of its own:
  // out, back, and out again later is not oscillation. Aborts are merge decisions followed (RSS
  // overrides aside) by a side-lane decision, or by a merge decision with another sigmoid: an
  // abort whose side-lane decisions were all overridden by the RSS proper response shows only
  // as the new merge. With k aborts there were at least k + 1 attempts.
  int aborts = 0;
  const Decision* last = nullptr;
  const auto is_merge = [](const Decision& d) {
    return d.mode == DecisionMode::kDef1Merge || d.mode == DecisionMode::kDef2Merge;
  };
  for (const Decision& d : ctx.trace.decisions) {
    if (d.mode == DecisionMode::kProperResponse) continue;
    if (last && is_merge(*last)) {
      const bool to_side_lane = d.mode == DecisionMode::kDef1Halt || d.mode == DecisionMode::kDef2Request ||
                                d.mode == DecisionMode::kKeepLane;
      const bool new_sigmoid = is_merge(d) && (d.pc_m != last->pc_m || d.kappa_per_m != last->kappa_per_m);
      aborts += to_side_lane || new_sigmoid;
    }
    last = &d;
  }
  merges = std::max(merges, aborts + 1);
  const int allowed = ctx.params.max_lat_speed_sign_changes_per_merge * merges;
  const double h = ctx.params.lat_speed_hysteresis_mps;
  int sign = 0, changes = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double vy = steps[i].ego.road_vy_mps();
    const int now = vy > h ? 1 : vy < -h ? -1 : 0;
    if (now != 0 && sign != 0 && now != sign) ++changes;
    if (now != 0) sign = now;
    if (acc.record(i, steps[i].time_s, allowed - changes, kEgoId, allowed, changes)) {
      std::ostringstream os;
      os << "ego lateral velocity changed sign " << changes << " times (" << merges << " merge(s), at most "
         << allowed << " allowed) by t = " << steps[i].time_s << " s: the path oscillates";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

MonitorOutput monitor_sideslip(const MonitorContext& ctx) {
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("sideslip", steps.size());
  const double limit = ctx.params.sideslip_max_rad;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const VehicleState& e = steps[i].ego;
    if (e.vx_mps < ctx.params.sideslip_min_speed_mps) continue;
    const double beta = std::atan2(e.vy_mps, e.vx_mps);
    if (acc.record(i, steps[i].time_s, limit - std::abs(beta), kEgoId, limit, beta)) {
      std::ostringstream os;
      os << "ego sideslip " << beta << " rad exceeds " << limit << " rad at t = " << steps[i].time_s << " s";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
