// Collision freedom (spec §8): FCL boxes of every pair of vehicles, discrete at every step and
// continuous between steps (core/collision.h), behind an axis-aligned pre-filter.
#pragma once

#include "core/collision.h"
#include "rules/monitor.h"

namespace mg {

BoxPose box_pose_of(const ObservedTrace& s, const ObservedStep& step, std::size_t k);

// The collision rule does not name a liable party itself (Party::nobody()): the liability engine
// takes it from the broken obligations before the collision (rules/liability.h).
MonitorOutput monitor_collision(const MonitorContext& ctx);

}  // namespace mg
