// Definition 1 solver (src/planner/definition1.cpp): exactness of the v_e* interval against an
// independent re-evaluation of RCPP ineq. (1.1)/(1.2) and a dense scan.
#include "planner/definition1.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/rss.h"

namespace mg {
namespace {

// ---- independent re-implementation (paper inequalities written out, no planner code) ----
// D_lon is checked on its own in tests/core/rss_test.cpp (vectors and a brute-force oracle); the
// reference here re-derives the solver's inequalities around it.
double ref_d_lon(double vr, double vf, double lr, double lf, double t, double a, double bmin, double bmax) {
  return rss_longitudinal_m({vr, vf, lr, lf, t, a, bmin, bmax});
}
// Position and speed after t when moving from v0 toward v at rate a (up) or b (down).
double ref_pos(double v0, double v, double t, double a, double b) {
  if (v == v0) return v0 * t;
  const double rate = v > v0 ? a : -b;
  const double tr = (v - v0) / rate;
  return t < tr ? v0 * t + rate * t * t / 2 : v * t - (v - v0) * (v - v0) / (2 * rate);
}
double ref_speed(double v0, double v, double t, double a, double b) {
  return v > v0 ? std::min(v, v0 + a * t) : std::max(v, v0 - b * t);
}
// Ineq. (1.1) with the ego at (x, u) at rho/2; literal (ego at ve from T_dec) and ramped forms.
double ref_11(const Def1Context& c, const MainLaneVehicle& f, double x, double u) {
  const double rho = c.merge_duration_s, a_f = f.limits.accel_max_mps2;
  const double lhs = f.x_m + f.speed_mps * rho / 2 + a_f * rho * rho / 8;
  const double d = ref_d_lon(f.speed_mps + a_f * rho / 2, u, f.length_m, c.ego_length_m, c.response_time_s, a_f,
                             f.limits.brake_min_mps2, c.ego_limits.brake_max_mps2);
  return x - d - lhs;
}
double ref_margin_11(const Def1Context& c, const MainLaneVehicle& f, double ve) {
  const double h = c.merge_duration_s / 2, a = c.ego_limits.accel_max_mps2, b = c.ego_limits.brake_min_mps2;
  return std::min(ref_11(c, f, c.ego_x_m + ve * h, ve),
                  ref_11(c, f, c.ego_x_m + ref_pos(c.ego_speed_mps, ve, h, a, b), ref_speed(c.ego_speed_mps, ve, h, a, b)));
}
// Ineq. (1.2) at time t with the ego at (x, u).
double ref_12(const Def1Context& c, const MainLaneVehicle& l, double t, double x, double u) {
  const double d = ref_d_lon(u, l.speed_mps, c.ego_length_m, l.length_m, c.response_time_s,
                             c.ego_limits.accel_max_mps2, c.ego_limits.brake_min_mps2, l.limits.brake_max_mps2);
  return l.x_m + l.speed_mps * t - d - x;
}
double ref_margin_12(const Def1Context& c, const MainLaneVehicle& l, double ve) {
  const double a = c.ego_limits.accel_max_mps2, b = c.ego_limits.brake_min_mps2;
  double m = 1e300;
  for (const double t : {c.merge_duration_s / 2, c.merge_duration_s}) {
    m = std::min(m, ref_12(c, l, t, c.ego_x_m + ve * t, ve));
    m = std::min(m, ref_12(c, l, t, c.ego_x_m + ref_pos(c.ego_speed_mps, ve, t, a, b), ref_speed(c.ego_speed_mps, ve, t, a, b)));
  }
  return m;
}
bool ref_feasible(const Def1Context& c, const LaneGap& g, double ve) {
  return (!g.follower || ref_margin_11(c, *g.follower, ve) >= 0) && (!g.leader || ref_margin_12(c, *g.leader, ve) >= 0);
}

Limits gen_limits() {
  Limits l;
  l.accel_max_mps2 = *rc::gen::inRange(0, 40) / 10.0;
  l.brake_min_mps2 = *rc::gen::inRange(20, 60) / 10.0;
  l.brake_max_mps2 = l.brake_min_mps2 + *rc::gen::inRange(0, 50) / 10.0;
  return l;
}
MainLaneVehicle gen_vehicle(int id, double ego_x) {
  return MainLaneVehicle{id, ego_x + *rc::gen::inRange(-1200, 1200) / 10.0, *rc::gen::inRange(0, 330) / 10.0,
                         *rc::gen::inRange(30, 120) / 10.0, 1.9, gen_limits()};
}
Def1Context gen_def1_context() {
  Def1Context c;
  c.ego_x_m = *rc::gen::inRange(0, 2000) / 10.0;
  c.ego_speed_mps = *rc::gen::inRange(0, 330) / 10.0;
  c.ego_length_m = *rc::gen::inRange(30, 60) / 10.0;
  c.ego_limits = gen_limits();
  c.ego_limits.accel_max_mps2 = std::max(0.5, c.ego_limits.accel_max_mps2);
  c.response_time_s = *rc::gen::inRange(0, 20) / 10.0;
  c.merge_duration_s = *rc::gen::inRange(10, 80) / 10.0;
  c.speed_limit_mps = *rc::gen::inRange(150, 400) / 10.0;
  return c;
}
// Any gap around the ego (mostly infeasible ones).
LaneGap gen_gap(double ego_x) {
  LaneGap g;
  const int kind = *rc::gen::inRange(0, 3);  // 0 both, 1 follower only, 2 leader only
  if (kind != 2) g.follower = gen_vehicle(1, ego_x);
  if (kind != 1) g.leader = gen_vehicle(2, ego_x);
  if (g.follower && g.leader && g.follower->x_m > g.leader->x_m) std::swap(g.follower->x_m, g.leader->x_m);
  return g;
}
// A gap whose follower is behind and leader ahead of the ego (often feasible).
LaneGap gen_open_gap(double ego_x) {
  LaneGap g = gen_gap(ego_x);
  if (g.follower) g.follower->x_m = ego_x - *rc::gen::inRange(0, 2000) / 10.0;
  if (g.leader) g.leader->x_m = ego_x + *rc::gen::inRange(0, 2000) / 10.0;
  return g;
}

constexpr double kMarginTolM = 1e-9;

TEST(SpeedRamp, ReachesTargetThenHolds) {
  // 10 -> 20 m/s at 2 m/s2: 5 s ramp covering (10+20)/2*5 = 75 m; at 6 s, 75 + 20 = 95 m.
  const SpeedRamp up{10, 20, 2, 4};
  EXPECT_DOUBLE_EQ(up.distance_at_m(5), 75);
  EXPECT_DOUBLE_EQ(up.distance_at_m(6), 95);
  EXPECT_DOUBLE_EQ(up.speed_at_mps(2), 14);
  EXPECT_DOUBLE_EQ(up.speed_squared_at_distance_m2ps2(75), 400);
  EXPECT_DOUBLE_EQ(up.speed_squared_at_distance_m2ps2(40), 100 + 2 * 2 * 40);
  EXPECT_DOUBLE_EQ(up.speed_squared_at_distance_m2ps2(500), 400);
  // 20 -> 0 at 4 m/s2: stops after 5 s and 50 m, then stays.
  const SpeedRamp down{20, 0, 2, 4};
  EXPECT_DOUBLE_EQ(down.distance_at_m(5), 50);
  EXPECT_DOUBLE_EQ(down.distance_at_m(9), 50);
  EXPECT_DOUBLE_EQ(down.speed_squared_at_distance_m2ps2(32), 400 - 2 * 4 * 32);
  EXPECT_DOUBLE_EQ(down.speed_squared_at_distance_m2ps2(80), 0);
}

TEST(EnumerateGaps, OpenGapsAtBothEndsSortedByPosition) {
  const std::vector<MainLaneVehicle> lane{{7, 50, 20, 4.8, 1.9, {}}, {3, 10, 20, 4.8, 1.9, {}}};
  const auto gaps = enumerate_gaps(lane);
  ASSERT_EQ(gaps.size(), 3u);
  EXPECT_FALSE(gaps[0].follower);
  EXPECT_EQ(gaps[0].leader->id, 3);
  EXPECT_EQ(gaps[1].follower->id, 3);
  EXPECT_EQ(gaps[1].leader->id, 7);
  EXPECT_EQ(gaps[2].follower->id, 7);
  EXPECT_FALSE(gaps[2].leader);
}

TEST(Definition1, EmptyLaneAdmitsEverySpeed) {
  Def1Context c{0, 20, 4.8, {}, 0.5, 4, 33};
  const SpeedInterval iv = solve_def1_interval(c, LaneGap{});
  EXPECT_TRUE(iv.feasible);
  EXPECT_EQ(iv.lo_mps, 0);
  EXPECT_EQ(iv.hi_mps, 33);
}

TEST(Definition1, HaltSpeedCapStopsAtThePoint) {
  // v^2 = 2 b d: 20 m before the halt point at 2.5 m/s2 -> 10 m/s; at or past it -> 0.
  EXPECT_DOUBLE_EQ(halt_speed_cap_mps(80, 100, 2.5), 10);
  EXPECT_EQ(halt_speed_cap_mps(100, 100, 2.5), 0);
  EXPECT_EQ(halt_speed_cap_mps(120, 100, 2.5), 0);
}

RC_GTEST_PROP(Definition1, ReturnedIntervalSatisfiesBothInequalities, ()) {
  const Def1Context c = gen_def1_context();
  const LaneGap g = gen_open_gap(c.ego_x_m);
  const SpeedInterval iv = solve_def1_interval(c, g);
  RC_PRE(iv.feasible);
  RC_ASSERT(iv.lo_mps <= iv.hi_mps);
  RC_ASSERT(iv.lo_mps >= 0.0);
  RC_ASSERT(iv.hi_mps <= c.speed_limit_mps);
  for (const double v : {iv.lo_mps, 0.5 * (iv.lo_mps + iv.hi_mps), iv.hi_mps}) {
    if (g.follower) RC_ASSERT(ref_margin_11(c, *g.follower, v) >= -kMarginTolM);
    if (g.leader) RC_ASSERT(ref_margin_12(c, *g.leader, v) >= -kMarginTolM);
  }
}

RC_GTEST_PROP(Definition1, InfeasibleGapHasNoFeasibleSpeedInDenseScan, ()) {
  const Def1Context c = gen_def1_context();
  const LaneGap g = gen_gap(c.ego_x_m);
  const SpeedInterval iv = solve_def1_interval(c, g);
  RC_PRE(!iv.feasible);
  constexpr int kSteps = 4000;
  for (int i = 0; i <= kSteps; ++i) RC_ASSERT(!ref_feasible(c, g, c.speed_limit_mps * i / kSteps));
}

RC_GTEST_PROP(Definition1, IntervalEndsAreTight, ()) {
  // Exactness: just outside a bound the corresponding inequality fails.
  const Def1Context c = gen_def1_context();
  const LaneGap g = gen_open_gap(c.ego_x_m);
  const SpeedInterval iv = solve_def1_interval(c, g);
  RC_PRE(iv.feasible);
  const double eps = 1e-4;
  if (iv.lo_mps > eps) RC_ASSERT(!ref_feasible(c, g, iv.lo_mps - eps));
  if (iv.hi_mps < c.speed_limit_mps - eps) RC_ASSERT(!ref_feasible(c, g, iv.hi_mps + eps));
}

RC_GTEST_PROP(Definition1, Margin11NonDecreasingAndMargin12NonIncreasingInSpeed, ()) {
  const Def1Context c = gen_def1_context();
  const MainLaneVehicle o = gen_vehicle(1, c.ego_x_m);
  const double v1 = *rc::gen::inRange(0, 330) / 10.0;
  const double v2 = v1 + *rc::gen::inRange(0, 100) / 10.0;
  RC_ASSERT(def1_1_margin_m(c, o, v2) >= def1_1_margin_m(c, o, v1) - 1e-9);
  RC_ASSERT(def1_2_margin_m(c, o, v2) <= def1_2_margin_m(c, o, v1) + 1e-9);
}

}  // namespace
}  // namespace mg
