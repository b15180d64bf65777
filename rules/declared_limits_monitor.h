// Every vehicle keeps within the limits it declared (spec §8, "Declared limits"): the observed
// acceleration never exceeds its a_accel^max nor its braking its a_brake^max, at any time, not
// only inside an RSS-dangerous episode or a Definition 1/2 window.
#pragma once

#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_declared_limits(const MonitorContext& ctx);

// Vehicle k's margin to its declared limits at step i, m/s2: how far its acceleration stays below
// its a_accel^max and its braking below its a_brake^max, each widened by accel_tolerance_mps2 (the
// smaller; declared_limits' margin).
double declared_limits_margin_mps2(const ObservedTrace& t, const RuleParams& p, std::size_t i, std::size_t k);
// Whether vehicle k is seen beyond its declared limits at step i (that margin below zero).
bool beyond_declared_limits(const ObservedTrace& t, const RuleParams& p, std::size_t i, std::size_t k);

}  // namespace mg
