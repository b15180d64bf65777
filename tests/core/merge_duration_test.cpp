#include "core/merge_duration.h"

#include <cmath>

#include <gtest/gtest.h>

namespace mg {
namespace {

// The logistic path from 2 % to 98 % of W in rho at speed v has slope kappa = 2 ln 49 / (v rho)
// and peak lateral acceleration v^2 W kappa^2 / (6 sqrt 3): at the shortest comfortable duration
// that peak is the bound, whatever v.
TEST(MergeDuration, TheShortestComfortableMergePeaksAtTheBoundAtAnySpeed) {
  const double w = 3.5, a = 1.5;
  const double rho = shortest_comfortable_merge_s(w, a);
  EXPECT_NEAR(rho, 3.6882, 1e-4);
  for (const double v : {5.0, 20.0, 33.0}) {
    const double kappa = 2.0 * std::log(49.0) / (v * rho);
    EXPECT_NEAR(v * v * w * kappa * kappa / (6.0 * std::sqrt(3.0)), a, 1e-12);
  }
}

TEST(MergeDuration, ADeclaredDurationBelowTheShortestIsRaisedAndOneAboveIsKept) {
  const double shortest = shortest_comfortable_merge_s(3.5, 1.5);
  EXPECT_NEAR(merge_duration_base_s(2.2, 3.5, 1.5), kShortestMergeFactor * shortest, 1e-12);
  EXPECT_EQ(merge_duration_base_s(7.2, 3.5, 1.5), 7.2);
  // A wider lane or a lower bound needs longer.
  EXPECT_GT(shortest_comfortable_merge_s(4.0, 1.5), shortest);
  EXPECT_GT(shortest_comfortable_merge_s(3.5, 1.0), shortest);
}

}  // namespace
}  // namespace mg
