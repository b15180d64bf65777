// The RSS override of RCPP Fig. 1 (spec §6): when the ego is in an RSS-dangerous situation with
// a vehicle ahead of it (longitudinal AND lateral distances both below D_lon and D_lat, RCPP
// eq. 1, 2), its proper response is to brake at least a_brake^min. When the ego is the front
// vehicle, the longitudinal response belongs to the rear vehicle (RSS Def. 5), so it is not
// flagged here.
#pragma once

#include <optional>

#include "planner/planner.h"

namespace mg {

struct Danger {
  int vehicle_id = 0;
  double lon_distance_m = 0.0;  // centre to centre
  double d_lon_m = 0.0;
  double lat_distance_m = 0.0;
  double d_lat_m = 0.0;
};

// The first vehicle (by id) ahead of the ego that puts it in a dangerous situation, if any.
std::optional<Danger> rss_danger_ahead(const WorldSnapshot& w);

}  // namespace mg
