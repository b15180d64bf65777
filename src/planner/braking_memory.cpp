#include "planner/braking_memory.h"

#include <algorithm>

#include "planner/rcpp_world.h"

namespace mg {

WorldSnapshot BrakingMemory::apply(const WorldSnapshot& w) {
  WorldSnapshot out = w;
  for (ObservedVehicle& o : out.others) {
    const double accel = std::min(0.0, o.state.accel_mps2);
    const auto it = seen_.find(o.id);
    if (it == seen_.end() || accel <= it->second.accel_mps2 || w.time_s - it->second.time_s > kBrakingMemoryS)
      seen_[o.id] = Seen{accel, w.time_s};
    // A vehicle accelerating beyond its declared a_accel^max is not between braking bursts: what
    // it does now is the breach the planner must see (a remembered -0.0002 m/s2 hid a follower
    // racing at 2.5 times its limit for 2 s).
    if (accelerating_beyond_limit(w, o)) continue;
    // A breach of b_max is seen while it lasts and not remembered beyond the declared limit: the
    // planner skips a gap whose leader brakes beyond its b_max, and a breach that had ended kept
    // that gap closed for kBrakingMemoryS while the progress rule, which reads what is observed,
    // offered it.
    const double remembered_mps2 = std::max(seen_[o.id].accel_mps2, -o.limits.brake_max_mps2);
    if (remembered_mps2 < 0.0) o.state.accel_mps2 = std::min(o.state.accel_mps2, remembered_mps2);
  }
  return out;
}

}  // namespace mg
