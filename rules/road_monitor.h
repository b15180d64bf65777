// Staying on the road and never passing the side lane's end while in it (spec §2, §8).
// Road edges: left = (main_lanes - 1/2) W; right = -3W/2 up to side_lane_end_x (the on-ramp
// feeds the side lane from behind its start), -W/2 beyond.
#pragma once

#include "rules/monitor.h"

namespace mg {

// Smallest signed distance of the ego box's corners to the road edges (negative outside).
double on_road_margin_m(const ObservedTrace& s, const ObservedState& ego);

MonitorOutput monitor_on_road(const MonitorContext& ctx);
MonitorOutput monitor_side_lane_end(const MonitorContext& ctx);

}  // namespace mg
