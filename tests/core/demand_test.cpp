// MG_DEMAND stays on in the build the suite runs (Release: NDEBUG is defined, assert() is off).
#include <gtest/gtest.h>

#include "core/demand.h"

namespace mg {
namespace {

int checked_half(int even) {
  MG_DEMAND(even % 2 == 0);
  return even / 2;
}

TEST(Demand, AHeldInvariantPassesThrough) { EXPECT_EQ(checked_half(8), 4); }

TEST(DemandDeathTest, ABrokenInvariantAbortsNamingTheConditionEvenWithNdebug) {
#ifndef NDEBUG
  GTEST_SKIP() << "built without NDEBUG: the point is that the check survives it";
#endif
  EXPECT_DEATH(checked_half(3), "invariant failed: even % 2 == 0 \\(.*demand_test.cpp:[0-9]+\\)");
}

}  // namespace
}  // namespace mg
