// The league's statistics (src/league/league_stats.cpp): Wilson's interval against published
// values and its properties, and the quantiles.
#include "league/league_stats.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg::league {
namespace {

TEST(LeagueStats, WilsonIntervalMatchesKnownValues) {
  // 0 of 10: [0, 0.2775] and 5 of 10: [0.2366, 0.7634] (by hand); 81 of 263: [0.2553, 0.3662]
  // (Newcombe, Statistics in Medicine 17, 1998, its example of the score method).
  const Interval none = wilson_interval(0, 10);
  EXPECT_DOUBLE_EQ(none.lo, 0.0);
  EXPECT_NEAR(none.hi, 0.2775, 1e-4);
  const Interval half = wilson_interval(5, 10);
  EXPECT_NEAR(half.lo, 0.2366, 1e-4);
  EXPECT_NEAR(half.hi, 0.7634, 1e-4);
  const Interval n263 = wilson_interval(81, 263);
  EXPECT_NEAR(n263.lo, 0.2553, 1e-4);
  EXPECT_NEAR(n263.hi, 0.3662, 1e-4);
  const Interval empty = wilson_interval(0, 0);
  EXPECT_EQ(empty.lo, 0.0);
  EXPECT_EQ(empty.hi, 1.0);
}

RC_GTEST_PROP(LeagueStats, WilsonIntervalHoldsTheShareInsideZeroOne, ()) {
  const auto n = *rc::gen::inRange<std::uint64_t>(1, 100000);
  const auto k = *rc::gen::inRange<std::uint64_t>(0, n + 1);
  const Interval ci = wilson_interval(k, n);
  const double p = static_cast<double>(k) / static_cast<double>(n);
  RC_ASSERT(0.0 <= ci.lo && ci.lo <= p + 1e-12 && p <= ci.hi + 1e-12 && ci.hi <= 1.0);
  RC_ASSERT(ci.hi > ci.lo);
  // Four times the runs, the same share: a narrower interval.
  const Interval more = wilson_interval(4 * k, 4 * n);
  RC_ASSERT(more.hi - more.lo < ci.hi - ci.lo);
}

TEST(LeagueStats, QuantilesInterpolateBetweenRanks) {
  EXPECT_FALSE(quantile({}, 0.5).has_value());
  EXPECT_DOUBLE_EQ(*quantile({3.0}, 0.95), 3.0);
  EXPECT_DOUBLE_EQ(*quantile({1.0, 2.0, 3.0}, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(*quantile({1.0, 2.0, 3.0, 4.0}, 0.5), 2.5);
  // numpy.percentile(range(1, 21), 95) = 19.05
  std::vector<double> v;
  for (int i = 1; i <= 20; ++i) v.push_back(i);
  EXPECT_NEAR(*quantile(v, 0.95), 19.05, 1e-12);
  EXPECT_DOUBLE_EQ(*quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(*quantile(v, 1.0), 20.0);
}

}  // namespace
}  // namespace mg::league
