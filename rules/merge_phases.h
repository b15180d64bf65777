// The ego's merge as an observer sees it (issue #15; docs/rules.md, "Merge phases"): read from
// its observed lateral position and heading alone, with the rules' own thresholds
// (RuleParams::merge_*), never from what a planner says it is doing.
//
//   side lane centre  ──●──── start: Y > y_side + merge_start_offset_m moving toward the main lane
//                        ╲           (v_Y > lat_speed_hysteresis_mps), or any part of its body
//                         ╲          over the lane line, however slowly it got there
//                          ╲  abort: before the line, with its body back off it, back below
//                           ╲        y_side + merge_abort_offset_m, or moving back,
//                            ╲       merge_abort_reversal_m short of its furthest Y
//   lane line  ─ ─ ─ ─ ─ ─●─ midpoint: the centre reaches the line (Y >= -W/2)
//                          ╲
//   main lane centre  ──────●── complete: |Y| < merge_complete_offset_m, |yaw| < merge_complete_yaw_rad
//
// An ego whose body reaches over the lane line is always in an attempt: a slow drift into the main
// lane is a merge. Only an ego that starts in the side lane merges. After the midpoint an attempt is no longer
// aborted (the ego is in the main lane; the RSS rules judge what follows); after completion
// nothing more is read.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/observed_trace.h"

namespace mg {

enum class MergePhaseKind { kStart, kAbort, kMidpoint, kComplete };

struct MergePhaseEvent {
  MergePhaseKind kind = MergePhaseKind::kStart;
  std::size_t step = 0;  // the first step at which the phase is observed
  double time_s = 0.0;
};

struct MergePhases {
  std::vector<MergePhaseEvent> events;  // in time order
  int count(MergePhaseKind k) const;
  // The first event of kind k at or after time_s.
  std::optional<MergePhaseEvent> first(MergePhaseKind k, double from_time_s = 0.0) const;
};

// The Y of the ego's leftmost corner (toward the main lane) from its declared size and observed
// yaw.
double ego_left_edge_y_m(const ObservedTrace& t, const ObservedState& ego);

MergePhases observe_merge_phases(const ObservedTrace& t, const RuleParams& p);

}  // namespace mg
