// Every vehicle keeps within the limits it declared (spec §8, "Declared limits"): the observed
// acceleration never exceeds its a_accel^max nor its braking its a_brake^max, at any time, not
// only inside an RSS-dangerous episode or a Definition 1/2 window.
#pragma once

#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_declared_limits(const MonitorContext& ctx);

}  // namespace mg
