// A second, independent formulation of Definition 1's feasible v_e* (spec §4): the planner
// (src/planner/definition1.cpp) and the rules (rules/definition1_gap.cpp) both solve ineq. (1.1)
// and (1.2) by bisection on margins written the same way, so an error in that reading would be
// shared. Here the conditions are written again from the paper and spec §4 alone and checked by
// brute force: every sampled v_e* in [0, speed limit] is simulated (the ego's bounded-rate speed
// change integrated in 1 ms steps, the follower's acceleration and the leader's constant speed
// written out), with eq. (1) in its printed form (the limits are drawn so that every front vehicle
// brakes at least as hard as the rear one's b_min, where the printed bracket is exact, spec §3).
// Each clearly feasible sample must lie in both implementations' interval, each clearly infeasible
// one outside it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "core/observed_trace.h"
#include "planner/definition1.h"
#include "rules/definition1_gap.h"

namespace mg {
namespace {

// Uniform in [lo, hi) (gen::arbitrary scales with RapidCheck's size and would crowd lo).
double any_in(double lo, double hi) {
  const auto u = *rc::gen::inRange<std::uint64_t>(0, std::uint64_t{1} << 53);
  return lo + (hi - lo) * (static_cast<double>(u) * 0x1p-53);
}

struct Body {
  double x_m = 0.0;
  double v_mps = 0.0;
  double length_m = 4.8;
  Limits limits;
};

struct Case {
  Body ego, follower, leader;
  double response_time_s = 0.5;
  double rho_s = 4.0;
  double speed_limit_mps = 33.34;
};

Limits any_limits() {
  Limits l;
  l.accel_max_mps2 = any_in(0.5, 4.0);
  l.brake_min_mps2 = any_in(2.0, 5.0);
  l.brake_max_mps2 = any_in(6.0, 10.0);  // >= every b_min drawn
  return l;
}

Case any_case() {
  Case c;
  // Traffic near the ego's speed and gaps from too tight to roomy: about half the cases admit
  // some v_e*, and their intervals' ends fall anywhere in [0, speed limit].
  const double v_e = any_in(0.0, 33.0);
  const auto near_speed = [&] { return std::clamp(v_e + any_in(-8.0, 8.0), 0.0, 33.0); };
  c.ego = {0.0, v_e, any_in(3.0, 6.0), any_limits()};
  c.follower = {-any_in(0.0, 150.0), near_speed(), any_in(3.0, 6.0), any_limits()};
  c.leader = {any_in(5.0, 250.0), near_speed(), any_in(3.0, 6.0), any_limits()};
  c.response_time_s = any_in(0.2, 1.0);
  c.rho_s = any_in(2.0, 6.0);
  return c;
}

// RCPP eq. (1) as printed, with the half-lengths outside the bracket (spec §3).
double d_lon_m(double v_rear, const Body& rear, double v_front, const Body& front, double t_s) {
  const double a = rear.limits.accel_max_mps2;
  const double after_t = v_rear + a * t_s;
  const double bracket = v_rear * t_s + 0.5 * a * t_s * t_s + after_t * after_t / (2.0 * rear.limits.brake_min_mps2) -
                         v_front * v_front / (2.0 * front.limits.brake_max_mps2);
  return 0.5 * (rear.length_m + front.length_m) + std::max(0.0, bracket);
}

// The ego under the bounded-rate model: from v_e toward v_e* at a_accel^max up or b_min down,
// then holding it; position and speed after `tau`, integrated in 1 ms steps.
struct Reached {
  double x_m;
  double v_mps;
};
Reached ramp(const Body& ego, double target, double tau) {
  constexpr double kDt = 1e-3;
  double x = ego.x_m, v = ego.v_mps;
  for (double t = 0.0; t < tau - 1e-12;) {
    const double dt = std::min(kDt, tau - t);
    const double next = target >= v ? std::min(target, v + ego.limits.accel_max_mps2 * dt)
                                    : std::max(target, v - ego.limits.brake_min_mps2 * dt);
    x += 0.5 * (v + next) * dt;  // exact but within the step where the ramp ends
    v = next;
    t += dt;
  }
  return {x, v};
}

// The smallest margin of Definition 1's conditions at v_e* = v, both position models (spec §4):
// (1.1) at rho/2 toward the follower, accelerating at its a_accel^max until then; (1.2) at rho/2
// and rho toward the leader at constant speed.
double brute_margin_m(const Case& c, double v) {
  const double half = 0.5 * c.rho_s, T = c.response_time_s;
  const Body& f = c.follower;
  const double f_x = f.x_m + f.v_mps * half + 0.5 * f.limits.accel_max_mps2 * half * half;
  const double f_v = f.v_mps + f.limits.accel_max_mps2 * half;
  double m = std::numeric_limits<double>::infinity();
  for (const Reached e : {Reached{c.ego.x_m + v * half, v}, ramp(c.ego, v, half)})
    m = std::min(m, e.x_m - d_lon_m(f_v, f, e.v_mps, c.ego, T) - f_x);
  for (const double tau : {half, c.rho_s}) {
    const double l_x = c.leader.x_m + c.leader.v_mps * tau;
    for (const Reached e : {Reached{c.ego.x_m + v * tau, v}, ramp(c.ego, v, tau)})
      m = std::min(m, l_x - d_lon_m(e.v_mps, c.ego, c.leader.v_mps, c.leader, T) - e.x_m);
  }
  return m;
}

Def1Interval rules_interval(const Case& c) {
  ObservedTrace t;
  t.road.speed_limit_mps = c.speed_limit_mps;
  t.params.rss.response_time_s = c.response_time_s;
  ObservedStep step;
  int id = 0;
  for (const Body* b : {&c.ego, &c.follower, &c.leader}) {
    VehicleDeclaration d;
    d.id = id++;
    d.size.length_m = b->length_m;
    d.limits = b->limits;
    t.vehicles.push_back(d);
    step.vehicles.push_back(ObservedState{b->x_m, id == 1 ? -3.5 : 0.0, 0.0, b->v_mps});
  }
  t.steps = {step};
  return def1_interval(t, 0, GapIndices{1, 2}, c.rho_s);
}

SpeedInterval planner_interval(const Case& c) {
  const Def1Context ctx{c.ego.x_m, c.ego.v_mps, c.ego.length_m, c.ego.limits, c.response_time_s, c.rho_s,
                        c.speed_limit_mps};
  const auto vehicle = [](int id, const Body& b) { return MainLaneVehicle{id, b.x_m, b.v_mps, b.length_m, 1.9, b.limits}; };
  return solve_def1_interval(ctx, LaneGap{vehicle(1, c.follower), vehicle(2, c.leader)});
}

// A sample within this many metres of a condition's boundary is not used: the 1 ms integration
// and the bisections' 1e-6 / 1e-7 m/s tolerances decide it either way.
constexpr double kUndecidedM = 1e-3;
constexpr double kSpeedSlackMps = 1e-5;

RC_GTEST_PROP(Definition1BruteForce, SampledSpeedsAgreeWithTheRulesAndThePlannersInterval, ()) {
  const Case c = any_case();
  const Def1Interval rules = rules_interval(c);
  const SpeedInterval planner = planner_interval(c);
  constexpr int kSamples = 120;
  int feasible_samples = 0, infeasible_samples = 0;
  for (int k = 0; k <= kSamples; ++k) {
    const double v = c.speed_limit_mps * k / kSamples;
    const double m = brute_margin_m(c, v);
    if (std::abs(m) < kUndecidedM) continue;
    const bool in_rules = rules.feasible() && v >= rules.ve_lo_mps - kSpeedSlackMps && v <= rules.ve_hi_mps + kSpeedSlackMps;
    const bool in_planner = planner.feasible && v >= planner.lo_mps - kSpeedSlackMps && v <= planner.hi_mps + kSpeedSlackMps;
    RC_LOG() << "v_e* " << v << ": brute-force margin " << m << " m; rules [" << rules.ve_lo_mps << ", "
             << rules.ve_hi_mps << "], planner " << planner.feasible << " [" << planner.lo_mps << ", " << planner.hi_mps
             << "]\n";
    RC_ASSERT(in_rules == (m > 0.0));
    RC_ASSERT(in_planner == (m > 0.0));
    feasible_samples += m > 0.0;
    infeasible_samples += m < 0.0;
  }
  RC_TAG(feasible_samples == 0 ? "no v_e* feasible" : infeasible_samples == 0 ? "every v_e* feasible" : "some v_e* feasible");
}

}  // namespace
}  // namespace mg
