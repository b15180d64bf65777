// Definition 2 of RCPP (cooperative lane merge over V2V, spec §5): the speed v_o* the ego asks
// of the responder, from ineq. (3) (Def. 2.1, ego ahead: the responder brakes at most its
// a_brake^min) and ineq. (4) (Def. 2.2, ego behind: the ego brakes at b_min, the responder
// accelerates at most its a_accel^max), bounded by the responder's rate limit and the speed limit.
#pragma once

#include "core/v2v_message.h"
#include "planner/definition1.h"

namespace mg {

struct CoopContext {
  double ego_x_m = 0.0;
  double ego_speed_mps = 0.0;     // v_e at T_dec: the ego asks at its current speed (paper §II-A)
  double ego_length_m = 0.0;
  Limits ego_limits;
  double response_time_s = 0.0;   // T_lag
  double merge_duration_s = 0.0;  // rho_m
  double comm_threshold_s = 0.0;  // rho_c
  double speed_limit_mps = 0.0;
  // The planner's slack over the paper's inequalities (both 0 = ineq. (3)/(4) as written): the
  // responder starts changing speed only when the request arrives, request_latency_s after T_dec,
  // which shifts it by latency (v_o - v_o*); and v_o* leaves planning_buffer_m beyond D_lon.
  double request_latency_s = 0.0;
  double planning_buffer_m = 0.0;
};

// The ego's speed once the exchange window rho_c is over: unchanged in Def. 2.1; after braking at
// its a_brake^min for rho_c (never below 0) in Def. 2.2 A.
double coop_ego_speed_after_mps(const CoopContext& c, CoopCase k);
// Where the ego is after rho_c: X + v_e rho_c (2.1); X + v_e rho_c - b_min rho_c^2/2 (2.2), with
// the stopping distance v_e^2/(2 b_min) when it would halt earlier (fix: the paper's parabola
// would move the ego backwards after halting).
double coop_ego_travel_m(const CoopContext& c, CoopCase k);
// P_c of the cooperative merge: the ego merges after rho_c at its post-exchange speed and
// reaches the sigmoid midpoint rho_m/2 later.
double coop_pc_m(const CoopContext& c, CoopCase k);

// D*_lon of Def. 2 / ineq. (3): the ego's predicted RSS distance at P_c, the responder behind it
// as the rear vehicle at v_o*, the ego in front at its post-exchange speed. RCPP eq. (1).
double d_lon_star_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps);

// D_lon of ineq. (4) (Def. 2.2): the ego as the rear vehicle after the exchange, the responder in
// front at v_o*. RCPP eq. (1).
double d_lon_ego_rear_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps);
// RCPP ineq. (3); Def. 2.1 B. Margin (m, >= 0 holds):
//   P_c - D*_lon - [X_o + (v_o + v_o*)/2 rho_c + v_o* rho_m/2]. Non-increasing in v_o*.
double ineq3_margin_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps);

// Conservative addition to ineq. (3) (docs/planner.md): the ego's lateral motion starts at
// T_dec + rho_c, so the same RSS distance must already hold then:
//   X + ego travel during rho_c - D*_lon - [X_o + (v_o + v_o*)/2 rho_c]. Non-increasing in v_o*.
// solve_vo_star requires both this and ineq. (3), so every v_o* it returns satisfies ineq. (3).
double ineq3_start_margin_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps);

// RCPP ineq. (4); Def. 2.2 B. Margin (m, >= 0 holds):
//   [X_o + (v_o* + v_o)/2 rho_c - D_lon] - [X + ego travel during rho_c], D_lon with the ego as
//   the rear vehicle at its post-exchange speed and the responder in front at v_o*.
//   Non-decreasing in v_o*.
double ineq4_margin_m(const CoopContext& c, const MainLaneVehicle& responder, double vo_star_mps);

// Rate-limited domain of v_o*: 2.1 [max(0, v_o - b_min,o rho_c), v_o] (brake at most b_min);
// 2.2 [v_o, max(v_o, min(v_o + a_accel,o rho_c, speed limit))] (accelerate at most a_accel).
SpeedInterval vo_star_domain(const CoopContext& c, const MainLaneVehicle& responder, CoopCase k);

struct VoStar {
  bool feasible = false;
  CoopCase coop_case = CoopCase::kEgoAhead;
  double vo_star_mps = 0.0;
  double pc_m = 0.0;
  double d_lon_star_m = 0.0;   // what the request carries
};

// The least demanding v_o* (closest to v_o) in the rate-limited domain that satisfies ineq. (3)
// resp. (4), found by bisection on the monotone margin; infeasible when none exists.
VoStar solve_vo_star(const CoopContext& c, const MainLaneVehicle& responder, CoopCase k);

}  // namespace mg
