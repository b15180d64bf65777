#include "planner/potential_field.h"

#include <algorithm>
#include <cmath>

#include "core/demand.h"

namespace mg {

// RCPP eq. (3).
double road_mark_potential(double y_m, double boundary_y_m, bool boundary_is_left, double ego_width_m,
                           double beta) {
  const double edge_gap_m = boundary_is_left ? boundary_y_m - y_m - 0.5 * ego_width_m
                                             : y_m - boundary_y_m - 0.5 * ego_width_m;
  const double d = std::max(edge_gap_m, kRoadMarkMinDistanceM);
  return 0.5 * beta / (d * d);
}

ObstacleField obstacle_field_from_rss(double x_m, double y_m, double d_lat_m, double d_lon_m) {
  MG_DEMAND(d_lat_m > 0.0 && d_lon_m > 0.0);
  return ObstacleField{x_m, y_m, 1.0 / (d_lat_m * d_lat_m), 1.0 / (d_lon_m * d_lon_m)};
}

// RCPP eq. (4).
double obstacle_potential(double x_m, double y_m, const ObstacleField& o, double gamma, double u) {
  const double dy = y_m - o.y_m;
  const double dx = x_m - o.x_m;
  return gamma * std::abs(std::exp(-(o.sigma_lat_per_m2 * dy * dy + o.sigma_lon_per_m2 * dx * dx)) - u);
}

// RCPP eq. (5).
double lane_centre_potential(double d_m, double xi, double search_distance_m, LaneCentreMode mode) {
  if (mode == LaneCentreMode::kKeeping) return 0.5 * xi * d_m * d_m;
  return search_distance_m * xi * d_m - 0.5 * xi * search_distance_m * search_distance_m;
}

double field_potential(const FieldScene& scene, const RcppParams& p, double x_m, double y_m) {
  MG_DEMAND(scene.road != nullptr);
  const Road& road = *scene.road;
  const double w = road.lane_width_m;
  const bool side_lane_here = x_m >= road.side_lane_start_x_m && x_m <= road.side_lane_end_x_m;
  const double right_boundary_y_m = side_lane_here ? -1.5 * w : -0.5 * w;
  const double left_boundary_y_m = (road.main_lanes - 0.5) * w;
  double total = road_mark_potential(y_m, right_boundary_y_m, false, scene.ego_width_m, p.pf_road_beta) +
                 road_mark_potential(y_m, left_boundary_y_m, true, scene.ego_width_m, p.pf_road_beta);
  for (const ObstacleField& o : scene.obstacles)
    total += obstacle_potential(x_m, y_m, o, p.pf_obstacle_gamma, p.pf_obstacle_u);
  // Target waypoint on the target lane centre, D* ahead (RCPP eq. 5).
  const double dy = y_m - scene.target_lane_y_m;
  const double d = std::hypot(p.pf_search_distance_m, dy);
  total += lane_centre_potential(d, p.pf_lane_xi, p.pf_search_distance_m, scene.mode);
  return total;
}

double field_potential_floor(const RcppParams& p, LaneCentreMode mode) {
  return lane_centre_potential(p.pf_search_distance_m, p.pf_lane_xi, p.pf_search_distance_m, mode);
}

}  // namespace mg
