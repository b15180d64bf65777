// What the planners read from a WorldSnapshot: the ego's road-frame speeds, the vehicles of the
// merge target lane (the rightmost main lane, centre Y = 0), and the RSS following speed.
#pragma once

#include <optional>
#include <vector>

#include "planner/definition1.h"
#include "planner/planner.h"

namespace mg {

double ego_speed_mps(const WorldSnapshot& w);      // road-frame longitudinal speed, >= 0
double ego_lat_speed_mps(const WorldSnapshot& w);  // road-frame lateral speed (+Y left)

// How far ahead of the ego a planned path reaches: 10 m plus one second of driving beyond where
// the ego can get before the next cycle's path replaces it (its speed plus a_max for a cycle), far
// more than a tracker's preview. A fixed 160 m sampled every cycle would cost a tenth of a run,
// and half of the baseline's.
double tracked_path_ahead_m(const WorldSnapshot& w);

MainLaneVehicle to_lane_vehicle(const ObservedVehicle& o);
// Vehicles whose centre lies in the rightmost main lane (|Y| < W/2), sorted by x then id.
std::vector<MainLaneVehicle> target_lane_vehicles(const WorldSnapshot& w);
// The nearest vehicle of the target lane ahead of x_m (strictly), if any.
std::optional<MainLaneVehicle> leader_ahead_of(const std::vector<MainLaneVehicle>& lane, double x_m);

// The highest ego speed in [0, speed_limit] whose RSS distance (RCPP eq. 1, ego as the rear
// vehicle) plus kFollowBufferM fits in the current centre distance; 0 when even standing still
// does not. The buffer keeps a bumper gap at standstill despite speed-tracking error.
inline constexpr double kFollowBufferM = 2.0;
double rss_follow_speed_mps(const WorldSnapshot& w, const MainLaneVehicle& leader);

}  // namespace mg
