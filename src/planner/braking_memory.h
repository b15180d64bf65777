// What RCPP remembers of the other vehicles' braking (docs/planner.md "Leaders behind slow
// vehicles"): braking seen within kBrakingMemoryS counts as braking now. A leader braking in
// bursts (a bounded random driver, or one keeping its distance bang-bang) drew a new merge in
// each lull and an abort in the next burst, and the ego wove.
#pragma once

#include <map>

#include "planner/planner.h"

namespace mg {

inline constexpr double kBrakingMemoryS = 2.0;

class BrakingMemory {
 public:
  // `w` with each other vehicle's acceleration replaced by the harshest braking seen from it in
  // the last kBrakingMemoryS (at most its declared b_max), after remembering this cycle's; not for
  // a vehicle seen accelerating beyond its declared a_accel^max.
  WorldSnapshot apply(const WorldSnapshot& w);

 private:
  struct Seen {
    double accel_mps2 = 0.0;  // <= 0
    double time_s = 0.0;
  };
  std::map<int, Seen> seen_;  // vehicle id -> harshest recent braking
};

}  // namespace mg
