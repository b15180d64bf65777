// Definition 1 of RCPP (non-cooperative lane merge, spec §4): gap enumeration, the exact
// feasible interval of the merge speed v_e* per gap from ineq. (1.1) and (1.2), and the
// Definition 1.3 halt point.
//
// Fix of the paper (spec §4): the paper assumes the ego already travels at v_e* at the decision
// time. Here the ego changes speed from v_e toward v_e* at a bounded rate (accel_max upward,
// brake_min downward) and every inequality uses the position and speed it really reaches.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/scenario.h"

namespace mg {

// Bounded-rate speed change: from speed v0 the ego moves toward v_target, accelerating at
// accel_mps2 or braking at brake_mps2, then holds v_target.
struct SpeedRamp {
  double v0_mps = 0.0;
  double v_target_mps = 0.0;
  double accel_mps2 = 0.0;   // > 0
  double brake_mps2 = 0.0;   // > 0
  // Defined inline below: the planner's searches evaluate them millions of times a second.
  double speed_at_mps(double t_s) const;
  double distance_at_m(double t_s) const;  // non-decreasing in v_target_mps for every t_s >= 0
  // Squared speed once the ramp has covered distance_m (closed form: v^2 = v0^2 +- 2 rate d while
  // ramping, then v_target^2); between v0^2 and v_target^2 for distance_m >= 0.
  double speed_squared_at_distance_m2ps2(double distance_m) const;
  // The larger of v0^2 and v_target^2: no squared speed of the ramp exceeds it.
  double top_speed_squared_m2ps2() const { return std::max(v0_mps * v0_mps, v_target_mps * v_target_mps); }
};

inline double SpeedRamp::speed_at_mps(double t_s) const {
  if (v_target_mps >= v0_mps) return std::min(v_target_mps, v0_mps + accel_mps2 * t_s);
  return std::max(v_target_mps, v0_mps - brake_mps2 * t_s);
}

inline double SpeedRamp::distance_at_m(double t_s) const {
  const double dv = v_target_mps - v0_mps;
  if (dv == 0.0) return v0_mps * t_s;
  const double rate = dv >= 0.0 ? accel_mps2 : brake_mps2;
  const double ramp_s = std::abs(dv) / rate;
  if (t_s <= ramp_s) {  // still changing speed
    const double signed_rate = dv >= 0.0 ? rate : -rate;
    return v0_mps * t_s + 0.5 * signed_rate * t_s * t_s;
  }
  // Ramp completed: average speed during the ramp, then v_target.
  return 0.5 * (v0_mps + v_target_mps) * ramp_s + v_target_mps * (t_s - ramp_s);
}

inline double SpeedRamp::speed_squared_at_distance_m2ps2(double distance_m) const {
  const double v_sq = v0_mps * v0_mps;
  const double target_sq = v_target_mps * v_target_mps;
  if (v_target_mps >= v0_mps) return std::min(target_sq, v_sq + 2.0 * accel_mps2 * distance_m);
  return std::max(target_sq, v_sq - 2.0 * brake_mps2 * distance_m);
}

// A main-lane vehicle as Definition 1 sees it (its declared limits and current state).
struct MainLaneVehicle {
  int id = 0;
  double x_m = 0.0;
  double speed_mps = 0.0;
  double length_m = 0.0;
  double width_m = 0.0;
  Limits limits;
};

// The ego and the parameters the inequalities need, at the decision time T_dec.
struct Def1Context {
  double ego_x_m = 0.0;
  double ego_speed_mps = 0.0;
  double ego_length_m = 0.0;
  Limits ego_limits;
  double response_time_s = 0.0;    // T_lag of eq. (1)
  double merge_duration_s = 0.0;   // rho_m
  double speed_limit_mps = 0.0;    // upper end of the v_e* domain [0, speed_limit]

  SpeedRamp ramp_to(double ve_star_mps) const;
};

// RCPP ineq. (1.1); Def. 1.1. Margin (m, >= 0 holds) of the ego ahead of `follower` at
// T_dec + rho_m/2: follower after accelerating at its a_accel^max for rho_m/2, RSS D_lon with the
// follower as the rear vehicle (at that speed) and the ego as the front one. The minimum of the
// paper's literal form (ego at v_e* from T_dec) and the bounded-rate form (position and speed the
// ramp reaches). Non-decreasing in ve_star_mps.
double def1_1_margin_m(const Def1Context& c, const MainLaneVehicle& follower, double ve_star_mps);

// RCPP ineq. (1.2); Def. 1.2. Margin (m, >= 0 holds) of the ego behind `leader` over
// [T_dec, T_dec + rho_m], evaluated at rho_m/2 and rho_m: leader at constant speed, RSS D_lon with
// the ego as the rear vehicle; minimum of the literal and the bounded-rate forms.
// Non-increasing in ve_star_mps.
double def1_2_margin_m(const Def1Context& c, const MainLaneVehicle& leader, double ve_star_mps);

// A gap of the merge lane: vehicles sorted by x define (follower, leader) pairs, plus the open
// gap behind the rearmost (no follower) and ahead of the frontmost (no leader).
struct LaneGap {
  std::optional<MainLaneVehicle> follower;
  std::optional<MainLaneVehicle> leader;
};
// The lane order of enumerate_gaps: by position, then id.
inline bool lane_order_before(const MainLaneVehicle& a, const MainLaneVehicle& b) {
  return a.x_m != b.x_m ? a.x_m < b.x_m : a.id < b.id;
}
// `lane_vehicles` in any order; returns gaps from the rearmost to the frontmost.
std::vector<LaneGap> enumerate_gaps(std::vector<MainLaneVehicle> lane_vehicles);

struct SpeedInterval {
  bool feasible = false;
  double lo_mps = 0.0;
  double hi_mps = 0.0;
};

// The exact feasible set of v_e* in [0, speed_limit] for one gap: 1.1 gives a lower bound, 1.2 an
// upper bound; each is found by bisection on its monotone margin to kSpeedTolerance, with the
// returned ends on the feasible side (so both margins are >= 0 at lo and hi).
inline constexpr double kSpeedToleranceMps = 1e-7;

// The v_e* grid the planner's search and the progress rule share: speed limit / 48 apart, so that
// every merge the rule can find, the planner's search tries too (docs/planner.md).
inline constexpr int kDef1SpeedGridSteps = 48;
SpeedInterval solve_def1_interval(const Def1Context& c, const LaneGap& gap);

// Generic helpers for the monotone bisections used by Definitions 1 and 2: the smallest
// (largest) v in [lo, hi] with f(v) >= 0 for a non-decreasing (non-increasing) f; nullopt when
// none. The result satisfies f >= 0.
template <class F>
std::optional<double> lowest_satisfying(F f, double lo, double hi, double tol = kSpeedToleranceMps);
template <class F>
std::optional<double> highest_satisfying(F f, double lo, double hi, double tol = kSpeedToleranceMps);

// Definition 1.3: the x at which the ego's centre must stand still: the side lane end, minus the
// halt margin, half the ego length, and the room a merge from standstill needs
// (standstill_merge_length_m), so that the ego can still merge after halting.
double halt_point_x_m(const Road& road, double halt_margin_m, double ego_length_m,
                      double standstill_merge_length_m);

// Definition 1.3 braking curve: the highest speed from which braking at brake_mps2 halts the ego
// by halt_x_m (0 at or beyond it).
double halt_speed_cap_mps(double ego_x_m, double halt_x_m, double brake_mps2);

// ---- template definitions ----
template <class F>
std::optional<double> lowest_satisfying(F f, double lo, double hi, double tol) {
  if (f(hi) < 0.0) return std::nullopt;
  if (f(lo) >= 0.0) return lo;
  while (hi - lo > tol) {  // invariant: f(lo) < 0 <= f(hi)
    const double mid = 0.5 * (lo + hi);
    if (f(mid) >= 0.0) hi = mid; else lo = mid;
  }
  return hi;
}

template <class F>
std::optional<double> highest_satisfying(F f, double lo, double hi, double tol) {
  if (f(lo) < 0.0) return std::nullopt;
  if (f(hi) >= 0.0) return hi;
  while (hi - lo > tol) {  // invariant: f(lo) >= 0 > f(hi)
    const double mid = 0.5 * (lo + hi);
    if (f(mid) >= 0.0) lo = mid; else hi = mid;
  }
  return lo;
}

}  // namespace mg
