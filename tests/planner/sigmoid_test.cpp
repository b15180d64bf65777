// Sigmoid planner (src/planner/sigmoid.cpp): shape of f_sig (RCPP §II-C), comfort bound, and the
// candidate search.
#include "planner/sigmoid.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg {
namespace {

Sigmoid gen_sigmoid() {
  return Sigmoid{*rc::gen::inRange(20, 60) / 10.0, *rc::gen::inRange(1, 1000) / 1000.0,
                 *rc::gen::inRange(-5000, 5000) / 10.0, *rc::gen::inRange(-100, 100) / 10.0};
}

RC_GTEST_PROP(Sigmoid, MonotoneAndWithinOffsetAndOffsetPlusWidth, ()) {
  const Sigmoid s = gen_sigmoid();
  double prev = s.offset_m;
  for (int i = -400; i <= 400; ++i) {
    const double y = s.y_at_m(s.pc_m + i * 0.05 / s.kappa_per_m);
    RC_ASSERT(y >= prev);
    RC_ASSERT(y >= s.offset_m);
    RC_ASSERT(y <= s.offset_m + s.width_m);
    prev = y;
  }
}

RC_GTEST_PROP(Sigmoid, MidpointIsHalfWayAndFractionsInvert, ()) {
  const Sigmoid s = gen_sigmoid();
  RC_ASSERT(std::abs(s.y_at_m(s.pc_m) - (s.offset_m + s.width_m / 2)) < 1e-9);
  const double f = *rc::gen::inRange(1, 99) / 100.0;
  RC_ASSERT(std::abs(s.y_at_m(s.x_at_fraction_m(f)) - (s.offset_m + f * s.width_m)) < 1e-9 * (1 + s.width_m));
}

// The merge path from an ego off its side lane's centre toward the main lane (W = 3.5 m, ego at
// Y = -3.0, P_c = 100 m): the paper's logistic rescaled to run from the ego's Y to the target
// lane's centre, crossing the lane line (-1.75) at P_c whatever kappa, so that what the search
// checked at P_c (and the occupancy memo shares across a ramp's kappa candidates) is where the
// ego enters. At or below the centre, and from within the paper's 2 % start, the paper's own.
TEST(Sigmoid, AMergeFromOffItsCentreRunsFromTheEgoAndCrossesTheLaneLineAtPc) {
  for (const double kappa : {0.05, 0.2, 0.5}) {
    const Sigmoid m = merge_sigmoid(3.5, -3.0, kappa, 100.0);
    EXPECT_DOUBLE_EQ(m.offset_m, -3.0);
    EXPECT_DOUBLE_EQ(m.offset_m + m.width_m, 0.0);
    EXPECT_NEAR(lane_line_x_m(m, 3.5), 100.0, 1e-9);
    EXPECT_NEAR(m.y_at_m(100.0), -1.75, 1e-9);
    EXPECT_GT(m.pc_m, 100.0);  // its own midpoint, Y = -1.5, lies beyond
    EXPECT_NEAR(m.y_at_m(100.0 - 40.0 / kappa), -3.0, 1e-6);
  }
  for (const double ego_y_m : {-3.5, -3.8, -3.5 + 0.5 * kSigmoidEndFraction * 3.5}) {
    const Sigmoid m = merge_sigmoid(3.5, ego_y_m, 0.2, 100.0);
    EXPECT_DOUBLE_EQ(m.offset_m, -3.5);
    EXPECT_DOUBLE_EQ(m.width_m, 3.5);
    EXPECT_DOUBLE_EQ(m.pc_m, 100.0);
  }
}

TEST(Sigmoid, PeakLateralAccelerationMatchesNumericCurvature) {
  // Max |y''| of the logistic is W kappa^2 / (6 sqrt 3); at 20 m/s, W = 3.5, kappa = 0.1:
  // 400 * 3.5 * 0.01 / 10.392 = 1.347 m/s2.
  const Sigmoid s{3.5, 0.1, 0.0, -3.5};
  double max_ypp = 0;
  const double h = 1e-3;
  for (double x = -60; x <= 60; x += 0.01)
    max_ypp = std::max(max_ypp, std::abs(s.y_at_m(x + h) - 2 * s.y_at_m(x) + s.y_at_m(x - h)) / (h * h));
  EXPECT_NEAR(sigmoid_peak_lat_accel_mps2(20, 3.5, 0.1), 400 * max_ypp, 1e-3);
  EXPECT_NEAR(sigmoid_peak_lat_accel_mps2(20, 3.5, 0.1), 1.3472, 1e-4);
}

// peak_lat_accel_along_mps2 skips samples that cannot beat the peak so far (docs/performance.md):
// it must return exactly the maximum over all 41 samples, whatever the ramp (speeding up, slowing
// down, to a stop) and wherever it starts relative to the sigmoid.
RC_GTEST_PROP(Sigmoid, PeakLateralAccelerationIsTheMaximumOverEverySample, ()) {
  const Sigmoid sig = gen_sigmoid();
  const SpeedRamp ramp{*rc::gen::inRange(0, 400) / 10.0, *rc::gen::inRange(0, 400) / 10.0,
                       *rc::gen::inRange(1, 50) / 10.0, *rc::gen::inRange(1, 90) / 10.0};
  const double origin_x_m = sig.pc_m + *rc::gen::inRange(-3000, 1000) / 10.0;
  double full = 0.0;
  for (int i = 0; i <= 40; ++i) {  // the samples: u = kappa (x - P_c) from -4 to 4, every 0.2
    const double u = 4.0 * (2.0 * i / 40 - 1.0);
    const double sgm = 1.0 / (1.0 + std::exp(-u));
    const double x = sig.pc_m + u / sig.kappa_per_m;
    const double ypp = sig.width_m * sig.kappa_per_m * sig.kappa_per_m * sgm * (1.0 - sgm) * std::abs(1.0 - 2.0 * sgm);
    full = std::max(full, ramp.speed_squared_at_distance_m2ps2(std::max(0.0, x - origin_x_m)) * ypp);
  }
  RC_ASSERT(peak_lat_accel_along_mps2(sig, ramp, origin_x_m) == full);
  // The profile-free bound the comfort search uses to skip flat sigmoids is never below it.
  RC_ASSERT(peak_lat_accel_bound_mps2(sig, ramp) >= full);
}

RC_GTEST_PROP(Sigmoid, ComfortBoundIsTheLargestComfortableKappa, ()) {
  const double v = *rc::gen::inRange(1, 400) / 10.0;
  const double w = *rc::gen::inRange(20, 60) / 10.0;
  const double a = *rc::gen::inRange(1, 50) / 10.0;
  const double k = kappa_comfort_max_per_m(v, w, a);
  RC_ASSERT(std::abs(sigmoid_peak_lat_accel_mps2(v, w, k) - a) < 1e-9 * a);
  RC_ASSERT(sigmoid_peak_lat_accel_mps2(v, w, 1.01 * k) > a);
}

RC_GTEST_PROP(Sigmoid, ChosenCandidateLiesWithinBounds, ()) {
  const double pc_min = *rc::gen::inRange(0, 1000) / 10.0;
  const double pc_max = pc_min + *rc::gen::inRange(0, 1000) / 10.0;
  const double k_lo = *rc::gen::inRange(1, 100) / 1000.0;
  const double k_hi = k_lo + *rc::gen::inRange(0, 100) / 1000.0;
  const double pc_pref = *rc::gen::inRange(0, 2000) / 10.0;
  const auto choice = choose_sigmoid(
      even_grid(pc_min, pc_max, *rc::gen::inRange(1, 20)),
      [&](double) -> KappaRange { return std::make_pair(k_lo, k_hi); },
      *rc::gen::inRange(1, 10), [&](double pc, double kappa) { return std::abs(pc - pc_pref) + kappa; });
  RC_ASSERT(choice.has_value());
  RC_ASSERT(choice->param >= pc_min && choice->param <= pc_max);
  RC_ASSERT(choice->kappa_per_m >= k_lo && choice->kappa_per_m <= k_hi);
}

// The best-first search returns exactly choose_sigmoid's choice, ties and inadmissible
// candidates included, whatever valid lower bounds it is given, and nothing that does not beat an
// incumbent.
RC_GTEST_PROP(Sigmoid, TheBestFirstSearchChoosesWhatTheGridSearchChooses, ()) {
  const int n_params = *rc::gen::inRange(1, 12);
  const int n_kappa = *rc::gen::inRange(1, 6);
  std::vector<double> params;
  std::vector<KappaRange> ranges;
  for (int i = 0; i < n_params; ++i) {
    params.push_back(static_cast<double>(i));
    const int lo = *rc::gen::inRange(1, 20);
    if (*rc::gen::inRange(0, 5) == 0) ranges.push_back(std::nullopt);
    else ranges.push_back(std::make_pair(lo / 100.0, (lo + *rc::gen::inRange(-2, 10)) / 100.0));
  }
  // Few distinct costs, so that ties are common; -1 marks an inadmissible candidate.
  const auto cost_table = *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(n_params * n_kappa),
                                                                rc::gen::inRange(-1, 6));
  const auto slack = *rc::gen::container<std::vector<int>>(cost_table.size(), rc::gen::inRange(0, 4));
  const auto slot = [&](std::size_t i, double kappa) {
    const auto& r = *ranges[i];
    int k = 0;
    while (k + 1 < even_grid_size(r.first, r.second, n_kappa) && even_grid_at(r.first, r.second, n_kappa, k) != kappa) ++k;
    return i * static_cast<std::size_t>(n_kappa) + static_cast<std::size_t>(k);
  };
  const auto cost = [&](std::size_t i, double kappa) {
    const int c = cost_table[slot(i, kappa)];
    return c < 0 ? std::numeric_limits<double>::infinity() : static_cast<double>(c);
  };
  // A bound at most the cost (an inadmissible candidate's bound is anything up to +inf) and a
  // parameter floor at most every bound of its candidates.
  const auto bound = [&](std::size_t i, double kappa) {
    const std::size_t at = slot(i, kappa);
    return cost_table[at] < 0 ? 10.0 - slack[at] : cost_table[at] - slack[at] * 0.5;
  };
  const auto floor_of = [&](std::size_t i) { return -1.0 - static_cast<double>(i % 3); };
  const auto range_of = [&](std::size_t i) { return ranges[i]; };
  // The parameters are their own indices, so that the grid search's callbacks can name them.
  const auto expected = choose_sigmoid(
      params, [&](double v) { return range_of(static_cast<std::size_t>(v)); }, n_kappa,
      [&](double v, double kappa) { return cost(static_cast<std::size_t>(v), kappa); });
  const auto best_first = choose_sigmoid_best_first(params, floor_of, range_of, n_kappa, bound, cost);
  RC_ASSERT(best_first.has_value() == expected.has_value());
  if (expected) {
    RC_ASSERT(best_first->cost == expected->cost);
    RC_ASSERT(best_first->kappa_per_m == expected->kappa_per_m);
    RC_ASSERT(best_first->param == expected->param);
  }
  const double incumbent = *rc::gen::inRange(0, 7);
  const auto beaten = choose_sigmoid_best_first(params, floor_of, range_of, n_kappa, bound, cost, incumbent);
  RC_ASSERT(beaten.has_value() == (expected && expected->cost < incumbent));
  if (beaten) RC_ASSERT(beaten->cost == expected->cost && beaten->kappa_per_m == expected->kappa_per_m);
}

TEST(Sigmoid, NoAdmissibleKappaMeansNoChoice) {
  const auto choice = choose_sigmoid(
      even_grid(0, 10, 5), [](double) -> KappaRange { return std::nullopt; }, 5, [](double, double) { return 0.0; });
  EXPECT_FALSE(choice.has_value());
}

}  // namespace
}  // namespace mg
