// RSS safe distances with proper response (RCPP eq. 1, 2; RSS Def. 1, 4, 5; DESIGN §3, §8).
// A pair is dangerous when both its longitudinal and lateral distances are unsafe; an unsafe
// state is a violation only of the party that did not respond properly (see rules/catalog.json).
#pragma once

#include <cstddef>

#include "rules/monitor.h"

namespace mg {

// Geometry of vehicles i and j (0 = ego) at one trace step, with their RSS distances.
struct PairGeometry {
  std::size_t rear = 0, front = 0;  // by X
  std::size_t left = 0, right = 0;  // by Y
  double gap_m = 0.0;               // |X_front - X_rear|, centre to centre
  double d_lon_m = 0.0;             // RCPP eq. (1) with rear/front as above
  double dy_m = 0.0;                // |Y_left - Y_right|
  double d_lat_m = 0.0;             // RCPP eq. (2) (RSS Def. 4)
  bool lon_unsafe() const { return gap_m < d_lon_m; }
  bool lat_unsafe() const { return dy_m < d_lat_m; }
};

PairGeometry pair_geometry(const Scenario& s, const TraceStep& step, std::size_t i, std::size_t j);

MonitorOutput monitor_rss_longitudinal(const MonitorContext& ctx);
MonitorOutput monitor_rss_lateral(const MonitorContext& ctx);

}  // namespace mg
