// Inequalities (3) and (4) of RCPP Definition 2 (spec §5), judged from the
// channel and the observed states:
//  - def2_request_sound: every request the ego sent was sound when it sent it: for 2.1 (ego
//    ahead) ineq. (3) holds with the request's P_c, D*_lon and v_o* and the states at the send,
//    D*_lon covers eq. (1) with the responder at v_o*, and v_o* is reachable at b_min,o within
//    rho_c; for 2.2 (ego behind) ineq. (4) holds and v_o* is reachable at a_acc,o (and legal).
//    Liable: the ego.
//  - def2_positions: after an acceptance, the positions the inequalities count on: the responder
//    no farther (2.1) / no less far (2.2) than its accepted profile takes it. Liable: the
//    responder. (The ego's side of ineq. (4), braking at b_min for rho_c, is not a position rule:
//    an ego may drop its request for a Definition 1 merge, and its place toward the responder is
//    judged at the midpoint by sigmoid_pc_bounds and throughout by the RSS rules; spec §8.)
//  - def2_request_truthful: every request states a case the observed order at its send allows
//    (ego ahead: the ego's body not wholly behind the responder's; coop_exchange.h), and where an
//    acceptance is what the ego merged on, the ego's centre crossed the lane line no nearer its
//    responder than the request's P_c said, within the tolerance of PcCheck
//    (rules/merge_attempts.h). Liable: the ego.
#pragma once

#include <cstddef>

#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_def2_request_sound(const MonitorContext& ctx);
MonitorOutput monitor_def2_positions(const MonitorContext& ctx);
MonitorOutput monitor_def2_request_truthful(const MonitorContext& ctx);

// The responder of an accepted request `x` (vehicle k) on the profile ineq. (3)/(4) count on, at
// `time_s`: from its state at the acceptance linearly to v_o* (2.2: capped by the speed limit) by
// t_r + rho_c, then v_o* (t_r: the send of the request it answered). And the farthest from the
// ego's side a responder keeping its acceptance may be, def2_positions' bound: the same ramp to
// t_r + rho_c + T (its response time), for 2.1 the farthest along and the fastest, for 2.2 the
// least far and the slowest, within yield_speed_tolerance_mps of speed and that much travel per
// second since the acceptance. Valid up to the end of the responder's duties, t_r + rho_c +
// rho_m; after that nothing bounds it.
struct ProfileBound {
  bool valid = false;
  double profile_x_m = 0.0;
  double profile_v_mps = 0.0;
  double bound_x_m = 0.0;
  double bound_v_mps = 0.0;
};
ProfileBound accepted_profile_bound(const ObservedTrace& t, const RuleParams& p, const CoopExchange& x, std::size_t k,
                                    double time_s);
ProfileBound accepted_profile_bound(const MonitorContext& ctx, const CoopExchange& x, std::size_t k, double time_s);

// RCPP eq. (1) between trace vehicles rear and front at the given speeds (negative speeds as 0),
// with their declared sizes and limits.
double d_lon_m(const ObservedTrace& s, std::size_t rear, double v_rear, std::size_t front, double v_front);

// Whether the responder k of an accepted request was beyond def2_positions' bound at a step of
// [acceptance, until_s]: it broke what it accepted.
bool responder_broke_acceptance(const ObservedTrace& t, const RuleParams& p, const CoopExchange& x, std::size_t k,
                                double until_s);

// Distance covered in tau_s by a vehicle at v0 that changes speed linearly to v_star by ramp_s
// (ramp_s <= 0: at v_star at once) and then holds v_star.
double ramp_distance_m(double v0_mps, double v_star_mps, double ramp_s, double tau_s);

}  // namespace mg
