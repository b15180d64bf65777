// What an acceptance of the ego's request (rules/coop_exchange.h) gives a merge attempt
// (rules/merge_attempts.h): whether the attempt may rest on it, its request's P_c against the
// observed crossing, and Definition 1 for the gap's other vehicle at the request. `progress`
// offers an acceptance on the same test of the other vehicle (other_gap_vehicle_clear).
#pragma once

#include <cstddef>

#include "core/observed_trace.h"
#include "core/params.h"
#include "rules/coop_exchange.h"
#include "rules/merge_attempts.h"

namespace mg {

// An acceptance an attempt may rest on: delivered by its entry (or start), and inside its decision
// window or still binding its sender when the attempt starts (until t_r + rho_c + rho_m, the span
// for which `progress` offers it: an ego that let it pass would fail there, so a merge begun on it
// then, after an abort or a wait for the gap's other vehicle, is made on it).
bool delivered_in_window(const CoopExchange& x, const MergeAttempt& a, double from_s, const RuleParams& p);

// A request's P_c against where the attempt's centre crossed the lane line (PcCheck); x is the
// exchange at index i.
PcCheck pc_check_of(const ObservedTrace& t, const CoopExchange& x, std::size_t i, const MergeAttempt& a);

// Definition 1 for the pair of the ego and the gap's other vehicle at the request of an
// acceptance: the leader (2.1: the partner its follower) by ineq. (1.2) over rho_c + rho_m, the
// follower (2.2: the partner its leader) by ineq. (1.1) over 2 rho_c + rho_m, with the ego at
// the speed the request's case gives it after rho_c (2.1: its speed; 2.2: after braking at b_min).
// +inf for an open side.
double other_vehicle_margin_m(const ObservedTrace& t, const RuleParams& p, const CoopExchange& x, int other,
                              bool other_is_follower);

// The vehicle of the lane next to the responder of `x` on the side the ego merges on, at the
// request (the gap the request asked for): for an attempt whose gap entered is not known.
int requested_gap_other(const ObservedTrace& t, const CoopExchange& x);

// Whether the gap's vehicle other than the partner of an accepted request leaves room for the
// Definition 2 merge, judged at the request as for the right of way (the vehicle ahead of the
// partner for 2.1 by ineq. (1.2) over rho_c + rho_m, the one behind it for 2.2 by ineq. (1.1) over
// 2 rho_c + rho_m; an open side is clear).
bool other_gap_vehicle_clear(const ObservedTrace& t, const RuleParams& p, const CoopExchange& x);

}  // namespace mg
