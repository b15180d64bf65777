#include "rules/merge_phases.h"

#include <algorithm>

namespace mg {

int MergePhases::count(MergePhaseKind k) const {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [k](const MergePhaseEvent& e) { return e.kind == k; }));
}

std::optional<MergePhaseEvent> MergePhases::first(MergePhaseKind k, double from_time_s) const {
  for (const MergePhaseEvent& e : events)
    if (e.kind == k && e.time_s >= from_time_s) return e;
  return std::nullopt;
}

double ego_left_edge_y_m(const ObservedTrace& t, const ObservedState& ego) {
  return MergePhaseDetector::left_edge_y_m(t.vehicles[0].size, ego.y_m, ego.yaw_rad);
}

MergePhases observe_merge_phases(const ObservedTrace& t, const RuleParams& p) {
  MergePhases out;
  if (t.steps.empty()) return out;
  MergePhaseDetector detector(t.road, p, t.vehicles[0].size, t.steps[0].vehicles[0].y_m);
  for (std::size_t k = 0; k < t.steps.size() && !detector.completed(); ++k) {
    const ObservedState& ego = t.steps[k].vehicles[0];
    const MergePhaseStep phase = detector.step(ego.y_m, ego.vy_mps, ego.yaw_rad);
    const auto emit = [&](bool entered, MergePhaseKind kind) {
      if (entered) out.events.push_back({kind, k, t.steps[k].time_s});
    };
    emit(phase.start, MergePhaseKind::kStart);
    emit(phase.abort, MergePhaseKind::kAbort);
    emit(phase.midpoint, MergePhaseKind::kMidpoint);
    emit(phase.complete, MergePhaseKind::kComplete);
  }
  return out;
}

}  // namespace mg
