// RCPP's return stage (spec §6, docs/planner.md): the ego's path while in the side lane. Its
// centre; from nearer the main lane (after an aborted merge, or a start off-centre) a path back to
// it (planner/return_path.h) that starts where and in the direction the ego is going and is kept
// until the ego reaches its end; after a shallow abort a hold of the lateral position instead.
#pragma once

#include <optional>
#include <vector>

#include "planner/planner.h"
#include "planner/return_path.h"

namespace mg {

// An abort this near the side lane's centre (toward the main lane) holds the lateral position
// instead of returning to the centre: well inside the 0.3 m the generator leaves between D_lat
// and the lanes' centres at rest (fuzz/scenario_spec.cpp), and below the rules' merge start.
inline constexpr double kHoldAfterAbortOffsetM = 0.1;

// What the side-lane path remembers between cycles.
struct SideLaneLateral {
  std::optional<ReturnPath> return_path;  // back to the centre (or a hold), kept until its end
  bool hold_pending = false;              // a shallow abort: the next path holds (plan_lateral_hold)
  std::optional<double> hold_y_m;         // after that hold: the Y kept until the next merge
  double past_centre_m = 0.0;             // a return planned now aims this far beyond the centre
};

// How far beyond the side lane's centre (away from the main lane) the way back of a merge
// deferred for the weaving budget aims (rcpp_planner.cpp, back_to_centre).
inline constexpr double kDeferredReturnPastCentreM = 0.1;

// The lateral state right after an abort at the ego's current Y.
SideLaneLateral lateral_after_abort(const WorldSnapshot& w);

// This cycle's path in the side lane; may plan and keep a return path or a hold in `lateral`.
std::vector<PathPoint> side_lane_path(SideLaneLateral& lateral, const WorldSnapshot& w);

}  // namespace mg
