#include "rules/merge_phases.h"

#include <algorithm>
#include <cmath>

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
  const VehicleSize& size = t.vehicles[0].size;
  return ego.y_m + 0.5 * size.width_m * std::abs(std::cos(ego.yaw_rad)) +
         0.5 * size.length_m * std::abs(std::sin(ego.yaw_rad));
}

MergePhases observe_merge_phases(const ObservedTrace& t, const RuleParams& p) {
  MergePhases out;
  if (t.steps.empty()) return out;
  const double side_y = t.road.side_lane_y_m(), line_y = -0.5 * t.road.lane_width_m;
  if (!(t.steps[0].vehicles[0].y_m < line_y)) return out;  // not in the side lane: no merge
  bool started = false, midpoint = false;
  double furthest_y = side_y;  // the attempt's furthest lateral position toward the main lane
  for (std::size_t k = 0; k < t.steps.size(); ++k) {
    const ObservedState& ego = t.steps[k].vehicles[0];
    const auto emit = [&](MergePhaseKind kind) { out.events.push_back({kind, k, t.steps[k].time_s}); };
    if (started) furthest_y = std::max(furthest_y, ego.y_m);
    const bool over_line = ego_left_edge_y_m(t, ego) > line_y;
    // A start is motion toward the main lane, not an offset alone: an ego placed off its lane
    // centre, or drifting back to it, has not started merging. A body over the lane line is in the
    // main lane whatever its lateral speed.
    if (!started && ((ego.y_m > side_y + p.merge_start_offset_m && ego.vy_mps > p.lat_speed_hysteresis_mps) || over_line)) {
      started = true;
      furthest_y = ego.y_m;
      emit(MergePhaseKind::kStart);
    } else if (started && !midpoint && !over_line &&
               (ego.y_m < side_y + p.merge_abort_offset_m ||
                (ego.y_m < furthest_y - p.merge_abort_reversal_m && ego.vy_mps < -p.lat_speed_hysteresis_mps))) {
      // Back in the side lane, or turned back toward it by more than the reversal hysteresis
      // (which keeps path-tracking ripple from counting): the next departure toward the main
      // lane is a new attempt.
      started = false;
      emit(MergePhaseKind::kAbort);
    }
    if (started && !midpoint && ego.y_m >= line_y) {
      midpoint = true;
      emit(MergePhaseKind::kMidpoint);
    }
    if (midpoint && std::abs(ego.y_m) < p.merge_complete_offset_m && std::abs(ego.yaw_rad) < p.merge_complete_yaw_rad) {
      emit(MergePhaseKind::kComplete);
      break;
    }
  }
  return out;
}

}  // namespace mg
