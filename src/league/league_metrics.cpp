#include "league/league_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "rules/merge_phases.h"

namespace mg::league {
namespace {

const ObservedState& ego_at(const ObservedTrace& t, std::size_t step) { return t.steps[step].vehicles[0]; }

double arc_length_m(const ObservedTrace& t, std::size_t from_step, std::size_t to_step) {
  double length = 0.0;
  for (std::size_t k = from_step + 1; k <= to_step; ++k)
    length += std::hypot(ego_at(t, k).x_m - ego_at(t, k - 1).x_m, ego_at(t, k).y_m - ego_at(t, k - 1).y_m);
  return length;
}

// The completed merge: the completion and the last start before it.
void read_merge(const ObservedTrace& t, const RuleParams& rules, RunMetrics& m) {
  const MergePhases phases = observe_merge_phases(t, rules);
  const auto complete = phases.first(MergePhaseKind::kComplete);
  if (!complete) return;
  m.merged = true;
  m.merge_time_s = complete->time_s - t.steps.front().time_s;
  std::size_t start_step = 0;
  for (const MergePhaseEvent& e : phases.events)
    if (e.kind == MergePhaseKind::kStart && e.step <= complete->step) start_step = e.step;
  m.path_length_m = arc_length_m(t, start_step, complete->step);
}

}  // namespace

RunMetrics run_metrics(const ObservedTrace& t, const RuleParams& rules) {
  RunMetrics m;
  if (t.steps.size() < 2 || t.vehicles.empty()) return m;
  read_merge(t, rules, m);
  for (std::size_t k = 1; k < t.steps.size(); ++k) {
    const double dt = t.steps[k].time_s - t.steps[k - 1].time_s;
    const ObservedState& before = ego_at(t, k - 1);
    m.peak_lat_accel_mps2 = std::max(m.peak_lat_accel_mps2, std::abs(ego_at(t, k).vy_mps - before.vy_mps) / dt);
    if (std::hypot(before.vx_mps, before.vy_mps) < rules.halted_speed_mps) m.halted_s += dt;
  }
  return m;
}

}  // namespace mg::league
