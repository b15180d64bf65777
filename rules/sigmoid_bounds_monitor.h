// The sigmoid's P_c bounds (RCPP §II-C, spec §6) as observed: when the ego centre crosses the lane
// boundary (its midpoint P_c) it lies between the follower and the leader of the target lane with
// their safe distances. (Whether a planner's own P_c lay in its own bounds is not observable.)
#pragma once

#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_sigmoid_pc_bounds(const MonitorContext& ctx);

}  // namespace mg
