#include "rules/road_monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mg {

double on_road_margin_m(const ObservedTrace& s, const ObservedState& ego) {
  const double w = s.road.lane_width_m;
  const double left = (s.road.main_lanes - 0.5) * w;
  const double c = std::cos(ego.yaw_rad), sn = std::sin(ego.yaw_rad);
  const double hl = size_of(s, 0).length_m / 2.0, hw = size_of(s, 0).width_m / 2.0;
  double m = std::numeric_limits<double>::infinity();
  for (const double sl : {-1.0, 1.0}) {
    for (const double sw : {-1.0, 1.0}) {
      const double x = ego.x_m + sl * hl * c - sw * hw * sn;
      const double y = ego.y_m + sl * hl * sn + sw * hw * c;
      const double right = x <= s.road.side_lane_end_x_m ? -1.5 * w : -0.5 * w;
      m = std::min({m, y - right, left - y});
    }
  }
  return m;
}

MonitorOutput monitor_on_road(const MonitorContext& ctx) {
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("on_road", steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double m = on_road_margin_m(ctx.trace, ego_of(steps[i])) + ctx.params.road_edge_tolerance_m;
    if (acc.record(i, steps[i].time_s, m, Party::ego(), 0.0, m)) {
      std::ostringstream os;
      os << "ego left the road at t = " << steps[i].time_s << " s (x = " << ego_of(steps[i]).x_m
         << " m, y = " << ego_of(steps[i]).y_m << " m)";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

MonitorOutput monitor_side_lane_end(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("side_lane_end", steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const ObservedState& e = ego_of(steps[i]);
    if (e.y_m >= -s.road.lane_width_m / 2.0) continue;
    const double front = e.x_m + size_of(s, 0).length_m / 2.0;
    const double m = s.road.side_lane_end_x_m - front;
    if (acc.record(i, steps[i].time_s, m, Party::ego(), s.road.side_lane_end_x_m, front)) {
      std::ostringstream os;
      os << "ego still in the side lane passed its end x = " << s.road.side_lane_end_x_m << " m at t = "
         << steps[i].time_s << " s";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
