// Smoothness (RCPP §IV: no trajectory oscillation): sign changes of the ego's lateral velocity
// per merge, and the sideslip bound.
#pragma once

#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_smoothness_oscillation(const MonitorContext& ctx);
MonitorOutput monitor_sideslip(const MonitorContext& ctx);

}  // namespace mg
