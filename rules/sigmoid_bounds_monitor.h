// The sigmoid's P_c bounds (RCPP §II-C, spec §6): every merge decision keeps P_c inside its
// [pc_min, pc_max], and when the ego centre really crosses the lane boundary it lies between
// the follower and the leader of the target lane with their safe distances.
#pragma once

#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_sigmoid_pc_bounds(const MonitorContext& ctx);

}  // namespace mg
