#include "rules/smoothness_monitor.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace mg {

MonitorOutput monitor_smoothness_oscillation(const MonitorContext& ctx) {
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("smoothness_oscillation", steps.size());
  // Each observed merge attempt (an abort back to the side lane and a new start is a new one, spec
  // §6) may change the lateral speed's sign a few times; more is oscillation. At least one attempt
  // is allowed for, so that a weave in a lane without any merge is judged too.
  const int merges = std::max(ctx.phases.count(MergePhaseKind::kStart), 1);
  const int allowed = ctx.params.max_lat_speed_sign_changes_per_merge * merges;
  const double h = ctx.params.lat_speed_hysteresis_mps;
  // Lateral motion before the first start is the ego keeping (or centring itself in) its lane:
  // the merges' reversals are counted from there.
  const std::optional<MergePhaseEvent> first_start = ctx.phases.first(MergePhaseKind::kStart);
  int sign = 0, changes = 0;
  for (std::size_t i = first_start ? first_start->step : 0; i < steps.size(); ++i) {
    const double vy = ego_of(steps[i]).vy_mps;
    const int now = vy > h ? 1 : vy < -h ? -1 : 0;
    if (now != 0 && sign != 0 && now != sign) ++changes;
    if (now != 0) sign = now;
    if (acc.record(i, steps[i].time_s, allowed - changes, Party::ego(), allowed, changes)) {
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
    const ObservedState& e = ego_of(steps[i]);
    // The velocity's angle to the heading, from the road-frame velocity (the body-frame one is
    // not observable): beta = atan2(vy, vx) - yaw, wrapped to (-pi, pi].
    const double body_vx = e.vx_mps * std::cos(e.yaw_rad) + e.vy_mps * std::sin(e.yaw_rad);
    if (body_vx < ctx.params.sideslip_min_speed_mps) continue;
    const double beta = std::remainder(std::atan2(e.vy_mps, e.vx_mps) - e.yaw_rad, 2.0 * M_PI);
    if (acc.record(i, steps[i].time_s, limit - std::abs(beta), Party::ego(), limit, beta)) {
      std::ostringstream os;
      os << "ego sideslip " << beta << " rad exceeds " << limit << " rad at t = " << steps[i].time_s << " s";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
