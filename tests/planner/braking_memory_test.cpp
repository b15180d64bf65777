#include "planner/braking_memory.h"

#include <gtest/gtest.h>

namespace mg {
namespace {

// One other vehicle (id 1, declared a_accel^max 2 m/s2, b_max 6 m/s2) at `accel_mps2`, at `time_s`.
WorldSnapshot seen(const PlannerSetup& setup, double time_s, double accel_mps2) {
  WorldSnapshot w;
  w.time_s = time_s;
  w.setup = &setup;
  ObservedVehicle o;
  o.id = 1;
  o.limits.accel_max_mps2 = 2.0;
  o.limits.brake_max_mps2 = 6.0;
  o.state.accel_mps2 = accel_mps2;
  w.others = {o};
  return w;
}

TEST(BrakingMemory, BrakingSeenWithinTheMemoryCountsAsBrakingNow) {
  const PlannerSetup setup;
  BrakingMemory memory;
  EXPECT_DOUBLE_EQ(memory.apply(seen(setup, 0.0, -3.0)).others[0].state.accel_mps2, -3.0);
  EXPECT_DOUBLE_EQ(memory.apply(seen(setup, 1.0, 1.0)).others[0].state.accel_mps2, -3.0);  // a lull
  EXPECT_DOUBLE_EQ(memory.apply(seen(setup, 2.0, -1.0)).others[0].state.accel_mps2, -3.0);
  EXPECT_DOUBLE_EQ(memory.apply(seen(setup, 2.5, 0.5)).others[0].state.accel_mps2, 0.5);  // forgotten after 2 s
}

TEST(BrakingMemory, AVehicleAcceleratingBeyondItsDeclaredLimitIsSeenAsItIs) {
  // A vehicle that braked a little and then races at 9 m/s2, beyond its a_accel^max of 2: the
  // planner must see the breach (its prediction of a follower and its breach checks read it).
  const PlannerSetup setup;
  BrakingMemory memory;
  memory.apply(seen(setup, 0.0, -0.001));
  EXPECT_DOUBLE_EQ(memory.apply(seen(setup, 0.1, 9.0)).others[0].state.accel_mps2, 9.0);
  EXPECT_DOUBLE_EQ(memory.apply(seen(setup, 0.2, 2.0)).others[0].state.accel_mps2, -0.001);  // within the limit
}

TEST(BrakingMemory, ABrakingBreachIsSeenWhileItLastsAndRememberedAtTheDeclaredLimit) {
  // A leader braking at 9 m/s2, beyond its b_max of 6, and then within it: the planner skips a gap
  // whose leader brakes beyond its b_max, so a remembered breach would close the gap for 2 s after
  // the breach ended, while the progress rule offers it.
  const PlannerSetup setup;
  BrakingMemory memory;
  EXPECT_DOUBLE_EQ(memory.apply(seen(setup, 0.0, -9.0)).others[0].state.accel_mps2, -9.0);
  EXPECT_DOUBLE_EQ(memory.apply(seen(setup, 0.1, 0.4)).others[0].state.accel_mps2, -6.0);
  EXPECT_DOUBLE_EQ(memory.apply(seen(setup, 1.9, -7.0)).others[0].state.accel_mps2, -7.0);
}

}  // namespace
}  // namespace mg
