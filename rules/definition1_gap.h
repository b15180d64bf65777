// RCPP Definition 1's gap inequalities as the rules evaluate them from observation (spec §4,
// docs/spec_rules.md "Right of way from observation"): ineq. (1.1) toward the follower and (1.2) toward the leader for a
// merge speed v_e* and a merge duration rho, and the interval of v_e* for which both hold.
//
// An inequality holds only when it holds under both the paper's model (the ego already at v_e*)
// and the bounded-rate model of spec §4 (the ego changing speed toward v_e* at a_accel^max /
// b_min), as the planner of spec §4 requires: the paper's model alone would let an ego at speed
// "be" at v_e* = 0 at once and so claim the gap behind any vehicle alongside it.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/observed_trace.h"

namespace mg {

// Distance covered in tau seconds while changing speed from v to v_star at the given rates
// (then holding v_star): the ego's real position model of spec §4.
double speed_change_distance_m(double v, double v_star, double accel, double brake, double tau);

// Vehicle indices into ObservedTrace::vehicles (0 = ego) of a gap; -1 = open side.
struct GapIndices {
  int follower = -1;
  int leader = -1;
  bool operator==(const GapIndices&) const = default;
};

// Left minus right side of ineq. (1.1) at step `step`, >= 0 when it holds (+inf for no follower).
double def1_1_margin_m(const ObservedTrace& t, std::size_t step, int follower, double ve_star_mps, double rho_s);
// The same for ineq. (1.2), which must hold over the whole interval [T_dec, T_dec + rho] ("c_e is
// behind c_o^i"): checked at its midpoint and its end (+inf for no leader).
double def1_2_margin_m(const ObservedTrace& t, std::size_t step, int leader, double ve_star_mps, double rho_s);

struct Def1Interval {
  double ve_lo_mps = 0.0;  // the slowest v_e* in [0, speed limit] satisfying (1.1)
  double ve_hi_mps = 0.0;  // the fastest satisfying (1.2)
  bool feasible() const { return ve_lo_mps <= ve_hi_mps; }
};
// (1.1)'s margin grows with v_e* and (1.2)'s falls, so the v_e* satisfying both are one interval,
// found by bisection over [0, speed limit] to within 1e-6 m/s. With margin_m > 0 both must hold by
// that much.
Def1Interval def1_interval(const ObservedTrace& t, std::size_t step, const GapIndices& gap, double rho_s,
                           double margin_m = 0.0);
// def1_interval(...).feasible(), exactly, with each bisection stopped as soon as the comparison of
// its ends is decided (the rules ask this of every gap at every step of some runs).
bool def1_feasible(const ObservedTrace& t, std::size_t step, const GapIndices& gap, double rho_s,
                   double margin_m = 0.0);
// The v_e* that maximises min((1.1), (1.2)): where the two margins cross, or an end of the domain.
double def1_best_speed_mps(const ObservedTrace& t, std::size_t step, const GapIndices& gap, double rho_s);

// The follower and leader of the ego in the rightmost main lane (centre within half a lane width
// of Y = 0) at `step`: the nearest vehicles with X <= and X > the ego's.
GapIndices gap_around_ego(const ObservedTrace& t, std::size_t step);
// Every gap of that lane at `step`, rear to front, open ends included.
std::vector<GapIndices> lane_gaps(const ObservedTrace& t, std::size_t step);

}  // namespace mg
