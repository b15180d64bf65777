#include "fuzz/byte_scenario.h"

#include <set>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "fuzz/shrink.h"

namespace mg::fuzz {
namespace {

RC_GTEST_PROP(ByteScenario, EveryByteStringDecodesToALoadableScenario, (const std::vector<std::uint8_t>& bytes)) {
  const Scenario s = scenario_from_bytes(bytes.data(), bytes.size());
  RC_ASSERT(is_loadable(s));
  RC_ASSERT(s.vehicles.size() <= static_cast<std::size_t>(kByteScenarioMaxVehicles));
}

TEST(ByteScenario, EmptyInputIsTheNominalScenarioWithoutVehicles) {
  const Scenario s = scenario_from_bytes(nullptr, 0);
  EXPECT_TRUE(s.vehicles.empty());
  EXPECT_EQ(s.road.lane_width_m, range::kLaneWidth.nominal);
  EXPECT_EQ(s.ego.speed_mps, range::kEgoSpeed.nominal);
  EXPECT_EQ(s.params.sim.horizon_s, range::kHorizon.nominal);
}

TEST(ByteScenario, LongInputsDecodeVehiclesWithEveryBehaviour) {
  std::vector<std::uint8_t> bytes(4096);
  std::set<BehaviourType> behaviours;
  for (unsigned seed = 0; seed < 64; ++seed) {
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>((i * 131 + seed * 977) >> 3);
    for (const MainVehicle& v : scenario_from_bytes(bytes.data(), bytes.size()).vehicles) behaviours.insert(v.behaviour.type);
  }
  EXPECT_EQ(behaviours.size(), 6u);
}

}  // namespace
}  // namespace mg::fuzz
