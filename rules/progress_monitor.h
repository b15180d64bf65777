// Progress (RCPP Def. 1.3: the ego halts only while space is insufficient; RCPP exists to merge):
// an ego whose centre is in the side lane must not let the right of way pass, at any speed. While
// some gap of the rightmost main lane offers it Definition 1's right of way from its observed
// state (def1_gaps_feasible), or a timely Definition 2 acceptance addressed to it is in force,
// continuously for longer than progress_grace_s, and the ego neither merges (an attempt whose body
// reaches into the main lane) nor is in its RSS proper response, the rule fails, ego liable.
// Waiting for a better gap within the grace is allowed; so is any wait while nothing is offered.
#pragma once

#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_progress(const MonitorContext& ctx);

}  // namespace mg
