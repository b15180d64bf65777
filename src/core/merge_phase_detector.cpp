#include "core/merge_phase_detector.h"

#include <algorithm>
#include <cmath>

namespace mg {

MergePhaseDetector::MergePhaseDetector(const Road& road, const RuleParams& p, double initial_y_m)
    : side_y_m_(road.side_lane_y_m()),
      line_y_m_(-0.5 * road.lane_width_m),
      start_offset_m_(p.merge_start_offset_m),
      abort_offset_m_(p.merge_abort_offset_m),
      abort_reversal_m_(p.merge_abort_reversal_m),
      complete_offset_m_(p.merge_complete_offset_m),
      complete_yaw_rad_(p.merge_complete_yaw_rad),
      hysteresis_mps_(p.lat_speed_hysteresis_mps),
      from_side_(initial_y_m < line_y_m_),
      furthest_y_m_(side_y_m_) {}

MergePhaseStep MergePhaseDetector::step(double y_m, double vy_mps, double yaw_rad) {
  MergePhaseStep out;
  if (!from_side_ || completed_) return out;
  if (started_) furthest_y_m_ = std::max(furthest_y_m_, y_m);
  // A start is motion toward the main lane, not an offset alone: an ego placed off its lane
  // centre, or drifting back to it, has not started merging.
  if (!started_ && y_m > side_y_m_ + start_offset_m_ && vy_mps > hysteresis_mps_) {
    started_ = out.start = true;
    furthest_y_m_ = y_m;
  } else if (started_ && !midpoint_ &&
             (y_m < side_y_m_ + abort_offset_m_ || (y_m < furthest_y_m_ - abort_reversal_m_ && vy_mps < -hysteresis_mps_))) {
    // Back in the side lane, or turned back toward it by more than the reversal hysteresis
    // (which keeps path-tracking ripple from counting): the next departure toward the main lane
    // is a new attempt.
    started_ = false;
    out.abort = true;
  }
  if (started_ && !midpoint_ && y_m >= line_y_m_) midpoint_ = out.midpoint = true;
  if (midpoint_ && std::abs(y_m) < complete_offset_m_ && std::abs(yaw_rad) < complete_yaw_rad_) completed_ = out.complete = true;
  return out;
}

}  // namespace mg
