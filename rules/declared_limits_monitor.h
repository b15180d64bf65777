// Every vehicle keeps within the limits it declared (spec §8, "Declared limits"): the observed
// acceleration never exceeds its a_accel^max nor its braking its a_brake^max, at any time, not
// only inside an RSS-dangerous episode or a Definition 1/2 window.
#pragma once

#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_declared_limits(const MonitorContext& ctx);

// Whether vehicle k is seen beyond its declared limits at step i: accelerating harder than its
// a_accel^max or braking harder than its a_brake^max, by more than accel_tolerance_mps2 (what
// declared_limits fails on).
bool beyond_declared_limits(const ObservedTrace& t, const RuleParams& p, std::size_t i, std::size_t k);

}  // namespace mg
