// The ego's merge phases over an observable trace: the detector of core/merge_phase_detector.h
// (which documents the phases and their thresholds) run over every step of the ego.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/merge_phase_detector.h"
#include "core/observed_trace.h"

namespace mg {

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
// yaw (MergePhaseDetector::left_edge_y_m).
double ego_left_edge_y_m(const ObservedTrace& t, const ObservedState& ego);

MergePhases observe_merge_phases(const ObservedTrace& t, const RuleParams& p);

}  // namespace mg
