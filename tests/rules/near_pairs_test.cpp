// NearPairs (rules/near_pairs.h): the sweep lists exactly the pairs the all-pairs loop would not
// prune, in the all-pairs order, whatever the intervals and however they move between steps.
#include "rules/near_pairs.h"

#include <algorithm>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg {
namespace {

// The all-pairs definition: a pair is left out when the later-starting interval begins more
// than 0 and at least cut after the earlier one ends (the lower index starts first on a tie).
std::vector<NearPairs::Pair> all_pairs_kept(const std::vector<double>& lo, const std::vector<double>& hi, double cut) {
  std::vector<NearPairs::Pair> out;
  for (std::size_t i = 0; i < lo.size(); ++i)
    for (std::size_t j = i + 1; j < lo.size(); ++j) {
      const bool i_first = lo[i] <= lo[j];
      const double apart = i_first ? lo[j] - hi[i] : lo[i] - hi[j];
      if (!(apart > 0.0 && apart >= cut)) out.emplace_back(i, j);
    }
  return out;
}

RC_GTEST_PROP(NearPairs, ListsExactlyTheUnprunedPairsInPairOrder, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(0, 24);
  NearPairs near;
  const int steps = *rc::gen::inRange(1, 5);  // the kept order is re-sorted between steps
  for (int step = 0; step < steps; ++step) {
    std::vector<double> lo(n), hi(n);
    for (std::size_t v = 0; v < n; ++v) {
      lo[v] = *rc::gen::inRange(-50, 50) * 2.5;  // coarse: ties happen
      hi[v] = lo[v] + *rc::gen::inRange(0, 8) * 2.5;
    }
    const double cut = *rc::gen::element(-1.0, 0.0, 2.5, 10.0, std::numeric_limits<double>::infinity());
    RC_ASSERT(near.find(lo, hi, cut) == all_pairs_kept(lo, hi, cut));
  }
}

TEST(NearPairs, DistantIntervalsArePrunedAndTouchingOnesKept) {
  NearPairs near;
  const std::vector<double> lo = {0.0, 100.0, 4.0}, hi = {5.0, 105.0, 6.0};
  EXPECT_EQ(near.find(lo, hi, 10.0), (std::vector<NearPairs::Pair>{{0, 2}}));
  EXPECT_EQ(near.find(lo, hi, std::numeric_limits<double>::infinity()).size(), 3u);
}

}  // namespace
}  // namespace mg
