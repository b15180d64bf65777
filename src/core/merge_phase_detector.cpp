#include "core/merge_phase_detector.h"

#include <algorithm>
#include <cmath>

namespace mg {

MergePhaseDetector::MergePhaseDetector(const Road& road, const RuleParams& p, const VehicleSize& ego_size,
                                       double initial_y_m)
    : side_y_m_(road.side_lane_y_m()),
      line_y_m_(-0.5 * road.lane_width_m),
      ego_size_(ego_size),
      start_offset_m_(p.merge_start_offset_m),
      abort_offset_m_(p.merge_abort_offset_m),
      abort_reversal_m_(p.merge_abort_reversal_m),
      complete_offset_m_(p.merge_complete_offset_m),
      complete_yaw_rad_(p.merge_complete_yaw_rad),
      hysteresis_mps_(p.lat_speed_hysteresis_mps),
      from_side_(initial_y_m < line_y_m_),
      direction_(p.lat_speed_hysteresis_mps),
      furthest_y_m_(side_y_m_) {}

double MergePhaseDetector::left_edge_y_m(const VehicleSize& size, double y_m, double yaw_rad) {
  return y_m + 0.5 * size.width_m * std::abs(std::cos(yaw_rad)) + 0.5 * size.length_m * std::abs(std::sin(yaw_rad));
}

MergePhaseStep MergePhaseDetector::step(double y_m, double vy_mps, double yaw_rad) {
  MergePhaseStep out;
  if (!from_side_ || completed_) return out;
  if (started_) furthest_y_m_ = std::max(furthest_y_m_, y_m);
  const bool over_line = left_edge_y_m(ego_size_, y_m, yaw_rad) > line_y_m_;
  direction_.reverses(vy_mps);
  // A start is motion toward the main lane, not an offset alone: an ego placed off its lane
  // centre, or drifting back to it, has not started merging. An approach that slows within the
  // hysteresis before it passes the offset (a crawl merge: 0.03 m/s of lateral speed there) is
  // still that motion. A body over the lane line is in the main lane whatever its lateral speed.
  if (!started_ && ((y_m > side_y_m_ + start_offset_m_ && direction_.sign() > 0 && vy_mps > 0.0) || over_line)) {
    started_ = out.start = true;
    furthest_y_m_ = y_m;
  } else if (started_ && !midpoint_ && !over_line &&
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
