#include "planner/braking_memory.h"

#include <algorithm>

namespace mg {

WorldSnapshot BrakingMemory::apply(const WorldSnapshot& w) {
  WorldSnapshot out = w;
  for (ObservedVehicle& o : out.others) {
    const double accel = std::min(0.0, o.state.accel_mps2);
    const auto it = seen_.find(o.id);
    if (it == seen_.end() || accel <= it->second.accel_mps2 || w.time_s - it->second.time_s > kBrakingMemoryS)
      seen_[o.id] = Seen{accel, w.time_s};
    const double remembered_mps2 = seen_[o.id].accel_mps2;
    if (remembered_mps2 < 0.0) o.state.accel_mps2 = std::min(o.state.accel_mps2, remembered_mps2);
  }
  return out;
}

}  // namespace mg
