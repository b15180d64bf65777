// The potential field of RCPP §II-B (spec §6): road marks (eq. 3), obstacles with coefficients
// from the RSS distances (eq. 4) and the lane centre in its two modes (eq. 5). Used to score the
// sigmoid candidates (docs/planner.md).
#pragma once

#include <vector>

#include "core/scenario.h"
#include "planner/rcpp_params.h"

namespace mg {

// RCPP eq. (3): P_rm = beta/2 (1/(Y - Y_b - l_w/2))^2 for one boundary, with the distance taken
// from the vehicle's edge nearest the boundary. The pole is guarded: distances below
// kRoadMarkMinDistance (and edges beyond the boundary) count as that distance.
inline constexpr double kRoadMarkMinDistanceM = 0.05;
double road_mark_potential(double y_m, double boundary_y_m, bool boundary_is_left, double ego_width_m,
                           double beta);

// RCPP eq. (4) with sigma_1 = 1/D_lat^2, sigma_2 = 1/D_lon^2 (the field falls to e^-1 at the RSS
// distances; spec §6): P_ob = gamma |exp(-[s1 (Y-Y_o)^2 + s2 (X-X_o)^2]) - U|.
struct ObstacleField {
  double x_m = 0.0;
  double y_m = 0.0;
  double sigma_lat_per_m2 = 1.0;
  double sigma_lon_per_m2 = 1.0;
};
ObstacleField obstacle_field_from_rss(double x_m, double y_m, double d_lat_m, double d_lon_m);
double obstacle_potential(double x_m, double y_m, const ObstacleField& o, double gamma, double u);

// RCPP eq. (5): xi d^2/2 when lane keeping, D* xi d - xi D*^2/2 when merging; d is the distance to
// the target waypoint on the lane centre.
enum class LaneCentreMode { kKeeping, kMerging };
double lane_centre_potential(double d_m, double xi, double search_distance_m, LaneCentreMode mode);

// The whole field at one instant: road boundaries of the road (the side lane's right edge where
// the side lane exists), the obstacles at their positions at that instant, and the target lane.
struct FieldScene {
  const Road* road = nullptr;
  double ego_width_m = 0.0;
  std::vector<ObstacleField> obstacles;
  double target_lane_y_m = 0.0;
  LaneCentreMode mode = LaneCentreMode::kMerging;
};
double field_potential(const FieldScene& scene, const RcppParams& p, double x_m, double y_m);
// A lower bound of field_potential at any position of any scene in `mode`, exact in floating
// point: the lane-centre term at distance D* (d = hypot(D*, dY) >= D*, and the term does not fall
// with d); the road-mark and obstacle terms are >= 0, and each addition is monotone.
double field_potential_floor(const RcppParams& p, LaneCentreMode mode);

}  // namespace mg
