// Party: the serialized codes and the report names are the ones earlier outputs used, so that a
// report or corpus case written before stays byte-identical and readable.
#include <algorithm>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "core/party.h"

namespace mg {
namespace {

TEST(Party, CodesAreTheSerializedNumbers) {
  EXPECT_EQ(Party::nobody().code(), -1);
  EXPECT_EQ(Party::ego().code(), 0);
  EXPECT_EQ(Party::main_lane().code(), -2);
  EXPECT_EQ(Party::vehicle(3).code(), 3);
}

TEST(Party, EveryCodeRoundTrips) {
  for (const Party p : {Party::nobody(), Party::ego(), Party::main_lane(), Party::vehicle(1), Party::vehicle(1000000)}) {
    const std::optional<Party> back = Party::from_code(p.code());
    ASSERT_TRUE(back.has_value()) << p.code();
    EXPECT_EQ(*back, p);
  }
}

TEST(Party, ACodeThatNamesNoPartyIsRefused) {
  EXPECT_FALSE(Party::from_code(-3).has_value());
  EXPECT_FALSE(Party::from_code(-1000).has_value());
}

TEST(Party, NamesAreTheReportWording) {
  EXPECT_EQ(party_name(Party::nobody()), "none");
  EXPECT_EQ(party_name(Party::ego()), "ego");
  EXPECT_EQ(party_name(Party::main_lane()), "main lane");
  EXPECT_EQ(party_name(Party::vehicle(3)), "vehicle 3");
}

TEST(Party, AVehicleIdOfATraceIsTheEgoOrAVehicle) {
  EXPECT_TRUE(Party::from_vehicle_id(0).is_ego());
  const Party v = Party::from_vehicle_id(7);
  EXPECT_TRUE(v.is_vehicle());
  EXPECT_FALSE(v.is_ego() || v.is_nobody() || v.is_main_lane());
  EXPECT_EQ(v.vehicle_id(), 7);
  EXPECT_EQ(v, Party::vehicle(7));
  EXPECT_NE(v, Party::vehicle(8));
}

TEST(Party, OrdersByCode) {
  std::vector<Party> parties = {Party::vehicle(2), Party::ego(), Party::main_lane(), Party::vehicle(1), Party::nobody()};
  std::sort(parties.begin(), parties.end());
  const std::vector<Party> expected = {Party::main_lane(), Party::nobody(), Party::ego(), Party::vehicle(1), Party::vehicle(2)};
  EXPECT_EQ(parties, expected);
}

TEST(PartyDeathTest, AVehicleNeedsAPositiveId) {
  EXPECT_DEATH((void)Party::vehicle(0), "invariant failed: id >= 1");
  EXPECT_DEATH((void)Party::ego().vehicle_id(), "invariant failed: is_vehicle\\(\\)");
}

}  // namespace
}  // namespace mg
