// Lateral control of the ego (spec §7): the Stanley controller (Hoffmann et al., 2007) on
// the planner's road-frame reference polyline, with curvature feed-forward and yaw-rate damping.
#pragma once

#include <vector>

#include "core/scenario.h"
#include "core/vehicle_state.h"
#include "planner/merge_path.h"
#include "planner/planner.h"

namespace mg {

struct PathTrackerGains {
  double cross_track_gain = 1.0;     // k of Stanley, 1/s
  double preview_min_m = 3.0;        // heading/curvature chord: max(preview_min, preview_time * v)
  double preview_time_s = 0.3;
  double softening_mps = 2.0;        // k_soft: keeps the gain finite at low speed
  double yaw_rate_damping_s = 0.05;  // k_d on (r_path - r)
  // Comfort envelope of the driver: the request is capped at the steering whose kinematic
  // sideslip atan(l_r tan(delta) / L) equals this, below the rules' sideslip bound (0.05 rad).
  // Without it, Stanley's cross-track term at low speed (atan(k e / (k_soft + v))) steers up to
  // ~0.1 rad for a 0.3 m offset, i.e. a kinematic sideslip of ~0.06 rad right after a start.
  // RCPP draws its merges within this envelope, so it is declared with them.
  double sideslip_max_rad = kPathTrackerSideslipRad;
};

// Signed lateral error of a point against a polyline (positive: point left of the path) and the
// path's heading and curvature at the projection, measured over chords reaching preview_m
// back and ahead along the path, so that a jagged polyline (a gradient-following planner's)
// does not turn into steering noise. Beyond either end the end segment extends straight.
// The path must have >= 2 points with increasing X.
struct PathProjection {
  double cross_track_m = 0.0;
  double heading_rad = 0.0;
  double curvature_per_m = 0.0;
};
PathProjection project_on_path(const std::vector<PathPoint>& path, double x_m, double y_m, double preview_m = 2.0);

// Where the sideslip envelope binds. The sideslip rule judges the ego from sideslip_judged_from_mps
// (rules.sideslip_min_speed_mps) on; below it the request may steer harder, by as much as the
// steering rate can take back while the ego, accelerating at its accel_max_mps2, reaches that
// speed, from the speed a step ahead (step_s: the request is held for a step): the envelope holds
// whenever the rule judges, and a crawl merge, whose path is as sharp as half the steering
// ability (planner/merge_path.h, path_curvature_cap_per_m), is followed instead of lagged by a
// metre (its midpoint seconds late, the right of way judged at a follower that had meanwhile
// closed in: def1_1_gap, a campaign finding). 0 (the default): the envelope at every speed.
struct SteeringEnvelope {
  double sideslip_judged_from_mps = 0.0;
  double accel_max_mps2 = 0.0;
  double step_s = 0.0;
};

// Steering request that brings the front axle onto the path, within the sideslip envelope.
double stanley_steering_rad(const std::vector<PathPoint>& path, const VehicleState& ego, const EgoDynamics& d,
                            const PathTrackerGains& gains = {}, const SteeringEnvelope& envelope = {});

// A straight path at constant Y ahead of and behind x_m (used before the first plan).
std::vector<PathPoint> straight_path(double x_m, double y_m);

}  // namespace mg
