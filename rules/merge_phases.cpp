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

namespace {

// EgoAt(k) -> {time_s, y_m, yaw_rad} of the ego at step k.
template <class EgoAt>
MergePhases observe(const Road& road, const RuleParams& p, std::size_t n_steps, EgoAt ego_at) {
  MergePhases out;
  if (n_steps == 0) return out;
  const double side_y = road.side_lane_y_m(), line_y = -0.5 * road.lane_width_m;
  if (!(ego_at(0).y_m < line_y)) return out;  // not in the side lane: no merge
  bool started = false, midpoint = false;
  for (std::size_t k = 0; k < n_steps; ++k) {
    const auto ego = ego_at(k);
    const auto emit = [&](MergePhaseKind kind) { out.events.push_back({kind, k, ego.time_s}); };
    if (!started && ego.y_m > side_y + p.merge_start_offset_m) {
      started = true;
      emit(MergePhaseKind::kStart);
    } else if (started && !midpoint && ego.y_m < side_y + p.merge_abort_offset_m) {
      started = false;  // back in the side lane: the next departure is a new attempt
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

struct EgoPose {
  double time_s, y_m, yaw_rad;
};

}  // namespace

MergePhases observe_merge_phases(const ObservedTrace& t) {
  return observe(t.road, t.params.rules, t.steps.size(), [&](std::size_t k) {
    return EgoPose{t.steps[k].time_s, t.steps[k].vehicles[0].y_m, t.steps[k].vehicles[0].yaw_rad};
  });
}

MergePhases observe_merge_phases(const Scenario& s, const Trace& t) {
  return observe(s.road, s.params.rules, t.steps.size(), [&](std::size_t k) {
    return EgoPose{t.steps[k].time_s, t.steps[k].ego.y_m, t.steps[k].ego.yaw_rad};
  });
}

}  // namespace mg
