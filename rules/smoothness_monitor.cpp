#include "rules/smoothness_monitor.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/merge_phase_detector.h"

namespace mg {

namespace {

// The ego's merge approaches: its first observed start, each start after it came back within
// merge_abort_offset_m of its side-lane centre (an abort, which §6 may mandate, and a new
// attempt), and at most one start after an abort by reversal alone, the ego still off its lane
// centre (a planner that aborts and re-merges before it is back at the centre). Further starts
// after reversals continue the same approach: a weave toward the main lane earns no new allowance
// by turning back again and again.
int approaches(const MonitorContext& ctx) {
  const ObservedTrace& t = ctx.trace;
  const double centre_y = t.road.side_lane_y_m() + ctx.params.merge_abort_offset_m;
  int from_centre = 0, after_reversal = 0;
  std::size_t since = 0;  // the step after which a return to the lane centre counts
  for (const MergePhaseEvent& e : ctx.phases.events) {
    if (e.kind != MergePhaseKind::kStart) continue;
    bool returned = from_centre == 0;
    for (std::size_t i = since; i < e.step && !returned; ++i) returned = ego_of(t.steps[i]).y_m < centre_y;
    (returned ? from_centre : after_reversal) += 1;
    since = e.step;
  }
  return from_centre + std::min(after_reversal, 1);
}

}  // namespace

MonitorOutput monitor_smoothness_oscillation(const MonitorContext& ctx) {
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("smoothness_oscillation", steps.size());
  // Each merge approach may change the lateral speed's sign a few times; more is oscillation. At
  // least one approach is allowed for, so that a weave in a lane without any merge is judged too.
  const int merges = std::max(approaches(ctx), 1);
  const int allowed = ctx.params.max_lat_speed_sign_changes_per_merge * merges;
  // Lateral motion before the first start is the ego keeping (or centring itself in) its lane:
  // the merges' reversals are counted from there.
  const std::optional<MergePhaseEvent> first_start = ctx.phases.first(MergePhaseKind::kStart);
  LateralDirection direction(ctx.params.lat_speed_hysteresis_mps);
  int changes = 0;
  for (std::size_t i = first_start ? first_start->step : 0; i < steps.size(); ++i) {
    if (direction.reverses(ego_of(steps[i]).vy_mps)) ++changes;
    if (acc.record(i, steps[i].time_s, allowed - changes, Party::ego(), allowed, changes)) {
      std::ostringstream os;
      os << "ego lateral velocity changed sign " << changes << " times (" << merges << " merge approach(es), at most "
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
