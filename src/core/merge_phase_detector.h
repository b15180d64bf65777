// The ego's merge as an observer sees it (docs/rules.md, "Merge phases"): read from its lateral
// position, lateral speed and heading alone, with the rules' own thresholds (RuleParams::merge_*),
// never from what a planner says it is doing. One detector serves the rules (rules/merge_phases.h
// over an observable trace), the simulator's merge events (sim/trace.h) and the tests, so that a
// merge is the same thing wherever it is counted.
//
//   side lane centre  ──●──── start: Y > y_side + merge_start_offset_m moving toward the main lane
//                        ╲           (v_Y > 0, its last |v_Y| beyond lat_speed_hysteresis_mps
//                        ╲           pointing that way), or any part of its body
//                         ╲          over the lane line, however slowly it got there
//                          ╲  abort: before the line, with its body back off it, back below
//                           ╲        y_side + merge_abort_offset_m, or moving back,
//                            ╲       merge_abort_reversal_m short of its furthest Y
//   lane line  ─ ─ ─ ─ ─ ─●─ midpoint: the centre reaches the line (Y >= -W/2)
//                          ╲
//   main lane centre  ──────●── complete: |Y| < merge_complete_offset_m, |yaw| < merge_complete_yaw_rad
//
// An ego whose body reaches over the lane line is always in an attempt: a slow drift into the main
// lane is a merge. Only an ego that starts in the side lane merges. After the midpoint an attempt
// is no longer aborted (the ego is in the main lane; the RSS rules judge what follows); after
// completion nothing more is read.
#pragma once

#include "core/params.h"
#include "core/scenario.h"

namespace mg {

enum class MergePhaseKind { kStart, kAbort, kMidpoint, kComplete };

// The direction of the ego's lateral motion as the rules read it: +1 toward the main lane, -1
// away from it, set by a lateral speed beyond lat_speed_hysteresis_mps and kept while the speed is
// within it (0 before any such motion). Its changes are the reversals `smoothness_oscillation`
// counts; a merge starts only while it points toward the main lane.
class LateralDirection {
 public:
  explicit LateralDirection(double hysteresis_mps = 0.0) : hysteresis_mps_(hysteresis_mps) {}
  // Reads the next lateral speed; true when it reverses the direction.
  bool reverses(double vy_mps) {
    const int now = vy_mps > hysteresis_mps_ ? 1 : vy_mps < -hysteresis_mps_ ? -1 : 0;
    const bool reversal = now != 0 && sign_ != 0 && now != sign_;
    if (now != 0) sign_ = now;
    return reversal;
  }
  int sign() const { return sign_; }

 private:
  double hysteresis_mps_;
  int sign_ = 0;
};

// The phases entered at one step, in the order they happen (a start or an abort, then the
// midpoint, then completion): one step can hold several.
struct MergePhaseStep {
  bool start = false, abort = false, midpoint = false, complete = false;
  bool any() const { return start || abort || midpoint || complete; }
};

class MergePhaseDetector {
 public:
  // initial_y_m decides whether the ego starts in the side lane, the only place it merges from;
  // ego_size (declared) places its body's corners against the lane line.
  MergePhaseDetector(const Road& road, const RuleParams& p, const VehicleSize& ego_size, double initial_y_m);

  // The next observed state of the ego.
  MergePhaseStep step(double y_m, double vy_mps, double yaw_rad);

  bool completed() const { return completed_; }

  // The Y of the ego's leftmost corner (toward the main lane) from its declared size and yaw.
  static double left_edge_y_m(const VehicleSize& size, double y_m, double yaw_rad);

 private:
  double side_y_m_, line_y_m_;
  VehicleSize ego_size_;
  double start_offset_m_, abort_offset_m_, abort_reversal_m_, complete_offset_m_, complete_yaw_rad_, hysteresis_mps_;
  bool from_side_;
  bool started_ = false, midpoint_ = false, completed_ = false;
  LateralDirection direction_;
  double furthest_y_m_ = 0.0;  // the attempt's furthest lateral position toward the main lane
};

}  // namespace mg
