// RCPP's commitment stage (RCPP §II-C, spec §6): a merge once decided is followed along its
// sigmoid, re-checked every cycle against the gap vehicles as observed, and aborted while that is
// still sound; its speed is v_e*, capped behind a braking leader.
#pragma once

#include <vector>

#include "planner/rcpp_decision.h"
#include "planner/sigmoid.h"

namespace mg {

// A committed merge may be aborted (P_c bounds crossed) only while the ego has covered less than
// this fraction of its lateral move (from the side lane's centre, or from where it was when the
// merge was planned if that is nearer the main lane); later it completes, protected by the RSS
// override.
inline constexpr double kAbortLateralFraction = 0.25;

struct CommittedMerge {
  Sigmoid sigmoid;
  double target_speed_mps = 0.0;  // v_e* (Def. 1) or the speed after the exchange (Def. 2)
  RcppDecision decision;              // the decision that started it
  // Where the lateral move starts: the side lane's centre, or the ego's offset at the decision
  // if nearer the main lane (a merge planned while the ego is still on its way back from an
  // abort is not committed from its first cycle: it would then follow, at RSS distance, the
  // gap's follower it is about to pass, and stop behind it for good; a campaign finding).
  double start_y_m = 0.0;
  // Begun from a hold after an abort (side_lane_path), or from an offset toward the main lane the
  // ego started at: the path then stays at or above start_y_m (merge_path_points).
  bool from_hold = false;
  bool committed(double ego_y_m) const {
    const double move_m = sigmoid.offset_m + sigmoid.width_m - start_y_m;
    return ego_y_m - start_y_m >= kAbortLateralFraction * move_m;
  }
};

// The ego has reached the sigmoid's end: by lateral progress, or by X once within
// 1 - kSettledFraction of the lane change of its end. Lane keeping then takes the ego to the speed
// limit; a crawl merge's sharp sigmoid is tracked up to 0.9 m behind at its end, and an ego
// accelerating from there, still turned toward the lane, overshot the lane centre and failed
// smoothness_oscillation (a campaign finding), so until it has settled it keeps the merge's speed.
inline constexpr double kSettledFraction = 0.9;
inline constexpr double kSettledYawRad = 0.05;
bool merge_complete(const CommittedMerge& m, const WorldSnapshot& w);

// Abort now: not yet committed, no corner of the body over the lane line yet, still able to halt
// before the side lane's end, and the P_c bounds cross at the predicted positions (or, for a
// Definition 1 merge, the rest of the merge is occupied).
bool merge_should_abort(const CommittedMerge& m, const WorldSnapshot& w);

// The merge's reference path over [x_from_m, x_to_m]: the sigmoid, but for a merge begun from a
// hold never farther from the main lane than start_y_m. The ego keeps that offset until the
// sigmoid passes it: steering back to the sigmoid's start first would reverse the lateral motion,
// which an observer reads as an abort and a new attempt, and undo what the hold was for
// (merge_path.cpp's occupancy check already puts the ego no farther from the main lane than it
// is); so for an ego that started off its centre toward the main lane. A merge begun on the way
// back to the centre after an abort follows the sigmoid: that return also takes the ego away
// from the main lane's vehicles.
double merge_path_y_m(const CommittedMerge& m, double x_m);
std::vector<PathPoint> merge_path_points(const CommittedMerge& m, double x_from_m, double x_to_m, double step_m);

// Whether following m first takes the ego away from the main lane: its path at the ego's X lies
// more than kTurnAwayM below it (a merge begun on the way back from an abort follows its sigmoid).
inline constexpr double kTurnAwayM = 0.05;
bool turns_away_first(const CommittedMerge& m, const WorldSnapshot& w);
// Whether the ego is turned toward the main lane by no more than kHeadingMatchRad beyond the
// merge's path at its X: a path the ego would have to straighten onto (a gentle one replacing a
// crawl's steep one) is driven with the ego still turned toward the lane, its corner over the
// lane line sooner than the path's own heading puts it, and the occupancy check reads the path's.
inline constexpr double kHeadingMatchRad = 0.05;
bool heads_along(const CommittedMerge& m, const WorldSnapshot& w);

// This cycle's command along the merge.
RcppCycle follow_merge(const CommittedMerge& m, const WorldSnapshot& w);

}  // namespace mg
