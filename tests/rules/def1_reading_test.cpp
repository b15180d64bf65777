// Definition 1 readings of an attempt's decision window (rules/def1_reading.h): the merge duration
// each is read over, and the pair margins at a reading.
#include "rules/def1_reading.h"

#include <gtest/gtest.h>

#include "rules/definition1_gap.h"
#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

// The ego at X = 0, 20 m/s in the side lane; vehicle 1 80 m behind it and vehicle 2 200 m ahead,
// both in the main lane at 20 m/s, over 10 s (T = 0.5 s, rho_m = 4 s by default).
struct Fixture {
  Scenario s = [] {
    Scenario sc = base_scenario();
    sc.vehicles = {vehicle(1, -80.0, 20.0), vehicle(2, 200.0, 20.0)};
    return sc;
  }();
  ObservedTrace t = test::observed(s, constant_accel_trace(s, 10.0));
  RuleParams p = s.params.rules;
  GapIndices gap{1, 2};
};

// Definition 1.1 lets the follower accelerate until the ego merges: an attempt whose midpoint
// came 7 s after the reading is read over twice that time less T, not over rho_m.
TEST(Def1Reading, AnAttemptWhoseMidpointCameLateIsReadOverTheTimeItTook) {
  const Fixture f;
  const Def1Reading r = read_def1(f.t, f.p, ReadingSpan{7.0, true}, f.gap, 0);
  EXPECT_DOUBLE_EQ(r.rho_s, 2.0 * (7.0 - 0.0 - f.t.params.rss.response_time_s));
  EXPECT_EQ(r.step, 0u);
  EXPECT_TRUE(r.gap == f.gap);
}

TEST(Def1Reading, AnAttemptAbortedBeforeItsMidpointIsReadOverRhoM) {
  const Fixture f;
  const Def1Reading r = read_def1(f.t, f.p, ReadingSpan{std::nullopt, true}, f.gap, 50);
  EXPECT_DOUBLE_EQ(r.rho_s, f.p.merge_duration_s);
  EXPECT_TRUE(r.interval.feasible());
}

// v_e* is the feasible value nearest the ego's observed speed at the midpoint, and the reading's
// margins are the inequalities' at that v_e*.
TEST(Def1Reading, TheMarginsAreStatedAtTheFeasibleSpeedNearestTheObservedOne) {
  const Fixture f;
  const Def1Reading r = read_def1(f.t, f.p, ReadingSpan{2.0, true}, f.gap, 0);
  ASSERT_TRUE(r.interval.feasible());
  EXPECT_DOUBLE_EQ(r.observed_mps, 20.0);
  EXPECT_DOUBLE_EQ(r.ve_star_mps, std::clamp(20.0, r.interval.ve_lo_mps, r.interval.ve_hi_mps));
  EXPECT_DOUBLE_EQ(r.margin_11_m, def1_1_margin_m(f.t, 0, 1, r.ve_star_mps, r.rho_s));
  EXPECT_DOUBLE_EQ(r.margin_12_m, def1_2_margin_m(f.t, 0, 2, r.ve_star_mps, r.rho_s));
}

TEST(Def1Reading, APairMarginIsIneq11TowardAFollowerAndIneq12TowardALeader) {
  const Fixture f;
  const Def1Reading r = read_def1(f.t, f.p, ReadingSpan{2.0, true}, f.gap, 0);
  EXPECT_DOUBLE_EQ(pair_margin_m(f.t, r, 1, true), r.margin_11_m);
  EXPECT_DOUBLE_EQ(pair_margin_m(f.t, r, 2, false), r.margin_12_m);
  EXPECT_NE(pair_margin_m(f.t, r, 1, true), pair_margin_m(f.t, r, 1, false));
}

}  // namespace
}  // namespace mg
