// Definition 2 (src/planner/definition2.cpp): every v_o* satisfies RCPP ineq. (3) or (4),
// re-evaluated independently, and the responder's rate limit.
#include "planner/definition2.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace mg {
namespace {

double ref_d_lon_eq(double vr, double vf, double lr, double lf, double t, double a, double bmin, double bmax) {
  const double inner = vr * t + a * t * t / 2 + (vr + a * t) * (vr + a * t) / (2 * bmin) - vf * vf / (2 * bmax);
  return (lr + lf) / 2 + (inner > 0 ? inner : 0);
}

// RCPP ineq. (3): X_o + (v_o + v_o*)/2 rho_c + v_o* rho_m/2 <= P_c - D*_lon, P_c = X + v_e (rho_c + rho_m/2).
double ref_ineq3(const CoopContext& c, const MainLaneVehicle& o, double vo) {
  const double pc = c.ego_x_m + c.ego_speed_mps * (c.comm_threshold_s + c.merge_duration_s / 2);
  const double d = ref_d_lon_eq(vo, c.ego_speed_mps, o.length_m, c.ego_length_m, c.response_time_s,
                                o.limits.accel_max_mps2, o.limits.brake_min_mps2, c.ego_limits.brake_max_mps2);
  return pc - d - (o.x_m + (o.speed_mps + vo) / 2 * c.comm_threshold_s + vo * c.merge_duration_s / 2);
}

// RCPP ineq. (4): X + v_e rho_c - b_min rho_c^2/2 <= X_o + (v_o* + v_o)/2 rho_c - D_lon (ego stops
// at most once: position v_e^2/(2 b_min) if it would halt within rho_c).
double ref_ineq4(const CoopContext& c, const MainLaneVehicle& o, double vo) {
  const double b = c.ego_limits.brake_min_mps2, rc = c.comm_threshold_s, ve = c.ego_speed_mps;
  const double travel = ve - b * rc >= 0 ? ve * rc - b * rc * rc / 2 : ve * ve / (2 * b);
  const double d = ref_d_lon_eq(std::max(0.0, ve - b * rc), vo, c.ego_length_m, o.length_m, c.response_time_s,
                                c.ego_limits.accel_max_mps2, b, o.limits.brake_max_mps2);
  return o.x_m + (vo + o.speed_mps) / 2 * rc - d - (c.ego_x_m + travel);
}

CoopContext gen_coop_context() {
  CoopContext c;
  c.ego_x_m = *rc::gen::inRange(0, 2000) / 10.0;
  c.ego_speed_mps = *rc::gen::inRange(0, 330) / 10.0;
  c.ego_length_m = *rc::gen::inRange(30, 60) / 10.0;
  c.ego_limits.accel_max_mps2 = *rc::gen::inRange(5, 40) / 10.0;
  c.ego_limits.brake_min_mps2 = *rc::gen::inRange(20, 60) / 10.0;
  c.ego_limits.brake_max_mps2 = c.ego_limits.brake_min_mps2 + *rc::gen::inRange(0, 50) / 10.0;
  c.response_time_s = *rc::gen::inRange(0, 20) / 10.0;
  c.merge_duration_s = *rc::gen::inRange(10, 80) / 10.0;
  c.comm_threshold_s = *rc::gen::inRange(1, 30) / 10.0;
  c.speed_limit_mps = *rc::gen::inRange(150, 400) / 10.0;
  return c;
}
MainLaneVehicle gen_responder(double ego_x) {
  MainLaneVehicle o{1, ego_x + *rc::gen::inRange(-800, 800) / 10.0, *rc::gen::inRange(0, 330) / 10.0,
                    *rc::gen::inRange(30, 120) / 10.0, 1.9, {}};
  o.limits.accel_max_mps2 = *rc::gen::inRange(0, 40) / 10.0;
  o.limits.brake_min_mps2 = *rc::gen::inRange(20, 60) / 10.0;
  o.limits.brake_max_mps2 = o.limits.brake_min_mps2 + *rc::gen::inRange(0, 50) / 10.0;
  return o;
}

constexpr double kTol = 1e-9;

TEST(Definition2, HandComputedEgoAheadSpeed) {
  // Ego X=50, v=20; responder X_o=25, v_o=20; rho_c=1.5, rho_m=4, T=0.5, default limits, 4.8 m cars.
  // D*(v) = 4.8 + 0.5v + 0.25 + (v+1)^2/8 - 400/16. Start of the lateral motion (binding, docs):
  // 50 + 30 - D*(v) >= 25 + 0.75 (20 + v)  <=>  v^2 + 12 v - 478.6 <= 0  ->  v_o* = 16.683 m/s;
  // ineq. (3) itself then holds with margin 40 - 2 v_o* = 6.63 m. Rate limit: 20 - 4*1.5 = 14 <= v_o*.
  const CoopContext c{50, 20, 4.8, {}, 0.5, 4, 1.5, 33.34};
  const MainLaneVehicle o{1, 25, 20, 4.8, 1.9, {}};
  const VoStar vo = solve_vo_star(c, o, CoopCase::kEgoAhead);
  ASSERT_TRUE(vo.feasible);
  EXPECT_NEAR(vo.vo_star_mps, (-12 + std::sqrt(144 + 4 * 478.6)) / 2, 1e-5);
  EXPECT_NEAR(ref_ineq3(c, o, vo.vo_star_mps), 40 - 2 * vo.vo_star_mps, 1e-5);
  EXPECT_DOUBLE_EQ(vo.pc_m, 120);
}

TEST(Definition2, HandComputedEgoBehindSpeed) {
  // Ego X=50, v=20 brakes at 4 for 1.5 s: travel 25.5 m, speed 14. Responder X_o=54, v_o=20.
  // D = 4.8 + 7 + 0.25 + 15^2/8 - v^2/16; ineq. (4): 54 + 0.75(20 + v) - D >= 75.5
  // <=> v^2 + 12 v - 746.8 >= 0 -> v_o* = 21.979 m/s <= 20 + 2*1.5 = 23 (rate limit).
  const CoopContext c{50, 20, 4.8, {}, 0.5, 4, 1.5, 33.34};
  const MainLaneVehicle o{1, 54, 20, 4.8, 1.9, {}};
  const VoStar vo = solve_vo_star(c, o, CoopCase::kEgoBehind);
  ASSERT_TRUE(vo.feasible);
  EXPECT_NEAR(vo.vo_star_mps, (-12 + std::sqrt(144 + 4 * 746.8)) / 2, 1e-5);
  EXPECT_DOUBLE_EQ(coop_ego_speed_after_mps(c, CoopCase::kEgoBehind), 14);
}

RC_GTEST_PROP(Definition2, EgoAheadSpeedSatisfiesIneq3AndBrakeLimit, ()) {
  const CoopContext c = gen_coop_context();
  MainLaneVehicle o = gen_responder(c.ego_x_m);
  o.x_m = c.ego_x_m - *rc::gen::inRange(0, 1000) / 10.0;  // behind the ego: often feasible
  const VoStar vo = solve_vo_star(c, o, CoopCase::kEgoAhead);
  RC_PRE(vo.feasible);
  RC_ASSERT(ref_ineq3(c, o, vo.vo_star_mps) >= -kTol);
  RC_ASSERT(vo.vo_star_mps <= o.speed_mps);
  RC_ASSERT(o.speed_mps - vo.vo_star_mps <= o.limits.brake_min_mps2 * c.comm_threshold_s + kTol);
  RC_ASSERT(vo.vo_star_mps >= 0.0);
}

RC_GTEST_PROP(Definition2, EgoBehindSpeedSatisfiesIneq4AndAccelLimit, ()) {
  const CoopContext c = gen_coop_context();
  MainLaneVehicle o = gen_responder(c.ego_x_m);
  o.x_m = c.ego_x_m + *rc::gen::inRange(0, 1000) / 10.0;  // ahead of the ego: often feasible
  const VoStar vo = solve_vo_star(c, o, CoopCase::kEgoBehind);
  RC_PRE(vo.feasible);
  RC_ASSERT(ref_ineq4(c, o, vo.vo_star_mps) >= -kTol);
  RC_ASSERT(vo.vo_star_mps >= o.speed_mps);
  RC_ASSERT(vo.vo_star_mps - o.speed_mps <= o.limits.accel_max_mps2 * c.comm_threshold_s + kTol);
  RC_ASSERT(vo.vo_star_mps <= std::max(o.speed_mps, c.speed_limit_mps) + kTol);
}

RC_GTEST_PROP(Definition2, InfeasibleRequestHasNoSpeedInTheRateLimitedDomain, ()) {
  const CoopContext c = gen_coop_context();
  const MainLaneVehicle o = gen_responder(c.ego_x_m);
  const CoopCase k = *rc::gen::element(CoopCase::kEgoAhead, CoopCase::kEgoBehind);
  const VoStar vo = solve_vo_star(c, o, k);
  RC_PRE(!vo.feasible);
  const SpeedInterval d = vo_star_domain(c, o, k);
  for (int i = 0; i <= 1000; ++i) {
    const double v = d.lo_mps + (d.hi_mps - d.lo_mps) * i / 1000;
    if (k == CoopCase::kEgoAhead)
      RC_ASSERT(std::min(ineq3_margin_m(c, o, v), ineq3_start_margin_m(c, o, v)) < 0);
    else
      RC_ASSERT(ref_ineq4(c, o, v) < 0);
  }
}

}  // namespace
}  // namespace mg
