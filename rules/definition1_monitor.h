// Definition 1 of RCPP (non-cooperative merge; spec §4) judged from observation: at each observed
// merge attempt, whether ineq. (1.1) and (1.2) gave the ego the right of way (an ego that merged
// with neither them nor an accepted Definition 2 request breaks them); the follower's and leader's
// obligations in their windows once the ego held it; and the halt of 1.3.
#pragma once

#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_def1_1_gap(const MonitorContext& ctx);
MonitorOutput monitor_def1_1_follower(const MonitorContext& ctx);
MonitorOutput monitor_def1_2_gap(const MonitorContext& ctx);
MonitorOutput monitor_def1_2_leader(const MonitorContext& ctx);
MonitorOutput monitor_def1_3_halt(const MonitorContext& ctx);

}  // namespace mg
