#include "fuzz/round_real.h"

#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg::fuzz {
namespace {

constexpr RealRange kRange{2.0, 40.0, 20.0, 0.1};

bool on_resolution_grid(double v, double resolution) {
  return std::abs(v / resolution - std::round(v / resolution)) < 1e-6;
}

RC_GTEST_PROP(RoundReal, GeneratedValuesLieInTheRangeOnTheGrid, ()) {
  const double v = *gen_real(kRange);
  RC_ASSERT(v >= kRange.lo);
  RC_ASSERT(v <= kRange.hi);
  RC_ASSERT(on_resolution_grid(v, kRange.resolution));
}

RC_GTEST_PROP(RoundReal, EveryShrinkStaysInTheRangeOnTheGrid, ()) {
  const double v = *gen_real(kRange);
  for (double s : real_shrinks(kRange, v)) {
    RC_ASSERT(s >= kRange.lo);
    RC_ASSERT(s <= kRange.hi);
    RC_ASSERT(on_resolution_grid(s, kRange.resolution));
    RC_ASSERT(s != v);
  }
}

TEST(RoundReal, ShrinksTryTheNominalValueFirst) {
  const auto shrinks = real_shrinks(kRange, 33.7);
  ASSERT_FALSE(shrinks.empty());
  EXPECT_EQ(shrinks.front(), 20.0);
}

TEST(RoundReal, ShrinksTowardRounderNumbers) {
  const auto shrinks = real_shrinks(kRange, 33.7);
  EXPECT_NE(std::find(shrinks.begin(), shrinks.end(), 30.0), shrinks.end());
  EXPECT_NE(std::find(shrinks.begin(), shrinks.end(), 34.0), shrinks.end());
}

TEST(RoundReal, TheNominalValueHasNoShrinks) { EXPECT_TRUE(real_shrinks(kRange, 20.0).empty()); }

TEST(RoundReal, ShrinkingTerminatesFromEveryGridValue) {
  // Follow the first shrink repeatedly (the longest chains are toward the nominal value).
  for (double v = kRange.lo; v <= kRange.hi; v += 0.7) {
    double x = snap_to_grid(v, kRange.resolution);
    int steps = 0;
    for (auto s = real_shrinks(kRange, x); !s.empty(); s = real_shrinks(kRange, x)) {
      x = s.back();  // the least aggressive candidate makes the longest chain
      ASSERT_LT(++steps, 1000) << "from " << v;
    }
    EXPECT_EQ(x, kRange.nominal) << "from " << v;
  }
}

TEST(RoundReal, SnapPrintsDecimalsExactly) {
  EXPECT_EQ(snap_to_grid(20.1000000003, 0.1), 20.1);
  EXPECT_EQ(snap_to_grid(1234.0, 10.0), 1230.0);
}

}  // namespace
}  // namespace mg::fuzz
