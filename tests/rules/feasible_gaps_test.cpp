#include "rules/feasible_gaps.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

TEST(FeasibleGaps, AGapIsJudgedAlongTheWholeMergeNotOnlyAtItsMidpointAndEnd) {
  // Vehicle 1 overtakes the ego (12 m/s) at 20 m/s from alongside it on 3 m lanes. Ineq. (1.2)
  // holds at rho/2 and rho for a v_e* the ego brakes to, and holds there whatever the lateral
  // slack; but a merge leaving the side lane while the leader is still beside the ego comes within
  // D_lat plus the slack of it without D_lon behind it. With the largest slack (1.5 m) the ego is
  // that near it from the first instant, and the gap is not offered; with none it is.
  Scenario s = base_scenario();
  s.road.lane_width_m = 3.0;
  s.ego.y_m = -3.0;
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 12.0;
  s.vehicles = {vehicle(1, 100.0, 20.0)};
  const auto j = test::judge(s, constant_accel_trace(s, 1.0));
  j->params.progress_lateral_margin_m = 1.5;
  EXPECT_TRUE(def1_gaps_feasible(j->trace, j->params, 0).empty());
  j->params.progress_lateral_margin_m = 0.0;
  EXPECT_FALSE(def1_gaps_feasible(j->trace, j->params, 0).empty());
}

TEST(FeasibleGaps, ADeclaredMergeDurationBelowTheShortestComfortableOneIsRaisedToIt) {
  // rho_m = 2 s: a lane change of 3.5 m in 2 s needs 4.4 m/s^2 of lateral acceleration on the
  // flattest witness (c = 2 ln 49, cut at 2 %): with the default bound (1.5 m/s^2) the empty
  // road is offered at the shortest comfortable duration, 1.05 * 2 ln 49 / sqrt(6 sqrt 3 * 1.5 /
  // 3.5) = 3.87 s; with a bound of 5 m/s^2 at 2.12 s; at rho_m = 5 s (above both) at rho_m.
  const Scenario s = base_scenario();
  const auto j = test::judge(s, constant_accel_trace(s, 1.0));
  j->params.merge_duration_s = 2.0;
  const auto offered = [&] {
    const std::vector<FeasibleMerge> gaps = def1_gaps_feasible(j->trace, j->params, 0);
    EXPECT_EQ(gaps.size(), 1u);
    return gaps.empty() ? 0.0 : gaps.front().merge_duration_s;
  };
  EXPECT_NEAR(offered(), 3.8726, 1e-4);
  j->params.progress_lat_accel_max_mps2 = 5.0;
  EXPECT_NEAR(offered(), 1.05 * 2.0 * std::log(49.0) / std::sqrt(6.0 * std::sqrt(3.0) * 5.0 / 3.5), 1e-9);
  j->params.merge_duration_s = 5.0;
  EXPECT_NEAR(offered(), 5.0, 1e-12);
}

TEST(FeasibleGaps, TheTurnInAndOutAreTheSteepestSigmoidWithinTheSideslipBound) {
  // c = tan(0.05) / 2.4 (half the 4.8 m length); from the side-lane centre (Y = -3.5, A = 3.5) the
  // steepest logistic has kappa = sqrt(6 sqrt 3 c / 3.5) = 0.2489/m and reaches the line (its
  // middle) ln 49 / kappa = 15.64 m after its 2 % point; from Y = -2.5 (A = 2.5, the line at
  // f = 0.3) the same with logit(0.3); at the line itself, nothing.
  const Scenario s = base_scenario();
  const auto j = test::judge(s, constant_accel_trace(s, 0.1));
  const double c = std::tan(0.05) / 2.4;
  const double k35 = std::sqrt(6.0 * std::sqrt(3.0) * c / 3.5), k25 = std::sqrt(6.0 * std::sqrt(3.0) * c / 2.5);
  EXPECT_NEAR(shortest_turn_in_m(j->trace, j->params, -3.5), std::log(49.0) / k35, 1e-9);
  EXPECT_NEAR(shortest_turn_in_m(j->trace, j->params, -3.5), 15.64, 0.01);
  EXPECT_NEAR(shortest_turn_in_m(j->trace, j->params, -2.5), (std::log(0.3 / 0.7) + std::log(49.0)) / k25, 1e-9);
  EXPECT_NEAR(shortest_turn_in_m(j->trace, j->params, -1.75), 0.0, 1e-12);
  // The turn-out, from the line to the 98 % point: symmetric from the lane centre; from Y = -2.5
  // the rest of the way from f = 0.3.
  EXPECT_NEAR(shortest_turn_out_m(j->trace, j->params, -3.5), std::log(49.0) / k35, 1e-9);
  EXPECT_NEAR(shortest_turn_out_m(j->trace, j->params, -2.5), (std::log(49.0) - std::log(0.3 / 0.7)) / k25, 1e-9);
  EXPECT_NEAR(shortest_turn_out_m(j->trace, j->params, -1.75), 0.0, 1e-12);
}

}  // namespace
}  // namespace mg
