#include "planner/side_lane_path.h"

#include <algorithm>
#include <cmath>

#include "planner/merge_path.h"
#include "planner/rcpp_params.h"
#include "planner/rcpp_world.h"
#include "planner/sigmoid.h"
#include "planner/world_view.h"

namespace mg {
namespace {

// As short as the comfort bound at the ego's speed allows, or sharper, up to the trackability
// cap, where the comfortable one would carry the ego to within kReturnLaneLineMarginM of the main
// lane's line. A straight target line would make the tracker snap back; a level start, or one
// re-planned level every cycle, makes it reverse its steering at its cap while the ego still
// moves toward the lane, and the sideslip of that transient exceeded the rule's bound at merge
// speeds (docs/fuzzing.md). Below kReturnTangentMinSpeedMps the direction of travel is the
// heading. The cap also holds the linear model's steady-state sideslip within
// kPathSideslipMaxRad: at 25 m/s a soft neutral-steer ego has 8.7 m of it per unit curvature, 6
// times its kinematic l_r.
constexpr double kReturnPathMinOffsetM = 0.05;
constexpr double kReturnTangentMinSpeedMps = 1.0;
constexpr double kReturnLaneLineMarginM = 0.25;

// What a return or a hold may do at the ego's speed (planner/return_path.h, ReturnLimits).
ReturnLimits return_limits(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const double v = ego_speed_mps(w);
  ReturnLimits limits;
  limits.cap_curvature_per_m =
      std::min(path_curvature_cap_per_m(s),
               kPathSideslipMaxRad / std::abs(steady_sideslip_per_curvature_m(s.ego.dynamics, v)));
  limits.comfort_curvature_per_m =
      v >= kReturnTangentMinSpeedMps ? rcpp_params(s).lat_accel_comfort_mps2 / (v * v) : limits.cap_curvature_per_m;
  limits.y_max_m = -0.5 * s.road.lane_width_m - kReturnLaneLineMarginM;
  return limits;
}

// The ego's direction of travel as a slope dY/dX (its heading when nearly at rest).
double travel_slope(const WorldSnapshot& w) {
  const double v = ego_speed_mps(w);
  return v >= kReturnTangentMinSpeedMps ? ego_lat_speed_mps(w) / v : std::tan(w.ego.yaw_rad);
}

}  // namespace

SideLaneLateral lateral_after_abort(const WorldSnapshot& w) {
  // Barely begun: hold the lateral position rather than swing back to the centre and out
  // again at the next merge (each swing reverses the lateral speed; a random leader's bursts
  // drew a merge, an abort and a swing back every few seconds: smoothness_oscillation).
  SideLaneLateral lateral;
  lateral.hold_pending = w.ego.y_m - w.setup->road.side_lane_y_m() <= kHoldAfterAbortOffsetM;
  return lateral;
}

std::vector<PathPoint> side_lane_path(SideLaneLateral& lateral, const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const double from_x = w.ego.x_m - kPathBehindM, to_x = w.ego.x_m + tracked_path_ahead_m(w);
  if (lateral.hold_pending) {  // the first cycle after a shallow abort: stop the lateral motion, no swing back
    lateral.hold_pending = false;
    if (travel_slope(w) > 0.0) {
      lateral.return_path = plan_lateral_hold(w.ego.x_m, w.ego.y_m, travel_slope(w), return_limits(w));
      lateral.hold_y_m = lateral.return_path->back.y_at_m(lateral.return_path->end_x_m());
    } else {
      // Its lateral motion already spent (a merge aborted where it had stalled just short of the
      // start offset): the swing back to the centre alone was a reversal the judge counts, with
      // no start it credits (smoothness_oscillation; a campaign finding).
      lateral.hold_y_m = w.ego.y_m;
    }
  }
  if (lateral.return_path && w.ego.x_m < lateral.return_path->end_x_m())
    return sample_return_path(*lateral.return_path, from_x, to_x, kPathStepM);
  lateral.return_path.reset();
  if (lateral.hold_y_m) return sample_straight(*lateral.hold_y_m, from_x, to_x, kPathStepM);
  const double to_centre_m = s.road.side_lane_y_m() - w.ego.y_m;
  if (lateral.past_centre_m == 0.0 && std::abs(to_centre_m) < kReturnPathMinOffsetM)
    return sample_straight(s.road.side_lane_y_m(), from_x, to_x, kPathStepM);
  // An ego farther from the main lane than the side lane's centre holds its offset: moving toward
  // the main lane only to centre itself can make it laterally unsafe with a vehicle there (with a
  // long response time, D_lat grows with that lateral speed).
  if (to_centre_m > 0.0) return sample_straight(w.ego.y_m, from_x, to_x, kPathStepM);
  lateral.return_path = plan_return_path(w.ego.x_m, w.ego.y_m, travel_slope(w),
                                         s.road.side_lane_y_m() - lateral.past_centre_m, return_limits(w));
  return sample_return_path(*lateral.return_path, from_x, to_x, kPathStepM);
}

}  // namespace mg
