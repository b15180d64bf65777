// The formulas of the `mobil` baseline (planner/mobil_planner.h), as pure functions:
//
// - the Intelligent Driver Model, IDM (M. Treiber, A. Hennecke, D. Helbing, "Congested traffic
//   states in empirical observations and microscopic simulations", Phys. Rev. E 62, 1805, 2000):
//   eq. (1) dv/dt = a [1 - (v/v0)^delta - (s*(v, dv)/s)^2] and
//   eq. (2) s*(v, dv) = s0 + s1 sqrt(v/v0) + v T + v dv / (2 sqrt(a b)), here with s1 = 0 and
//   the dynamic term kept non-negative, as the model's later statement has it (Treiber & Kesting,
//   "Traffic Flow Dynamics", 2013);
// - MOBIL, "Minimizing Overall Braking Induced by Lane changes" (A. Kesting, M. Treiber,
//   D. Helbing, "General lane-changing model MOBIL for car-following models", Transportation
//   Research Record 1999, 86-94, 2007): its safety criterion, eq. (2), and its incentive criterion,
//   eq. (3), with the bias its asymmetric passing rules give one lane (here the main lane, since
//   the side lane ends).
//
// Accelerations are m/s^2, positive forward; a gap is bumper to bumper.
#pragma once

#include <optional>

namespace mg {

struct IdmParams {
  double desired_speed_mps = 33.3;      // v0
  double time_headway_s = 1.6;          // T
  double min_gap_m = 2.0;               // s0
  double max_accel_mps2 = 0.73;         // a
  double comfort_brake_mps2 = 1.67;     // b
  double exponent = 4.0;                // delta
};

// What a follower sees of its leader.
struct IdmLeader {
  double gap_m = 0.0;       // s: bumper to bumper
  double speed_mps = 0.0;   // the leader's speed (0 for a standing obstacle such as a lane's end)
};

// IDM eq. (1), its free-road part: a [1 - (v/v0)^delta].
double idm_free_road_mps2(double speed_mps, const IdmParams& p);
// IDM eq. (2) with s1 = 0: s0 + max(0, v T + v dv / (2 sqrt(a b))), dv = v - v_leader.
double idm_desired_gap_m(double speed_mps, double approach_rate_mps, const IdmParams& p);
// IDM eq. (1), its interaction part: -a (s*/s)^2. Gaps below kIdmMinGapM count as that gap (the
// term's pole): an overlap reads as the hardest braking, finite.
inline constexpr double kIdmMinGapM = 0.01;
double idm_interaction_mps2(double speed_mps, const IdmLeader& leader, const IdmParams& p);
// IDM eq. (1): the free-road part plus the interaction with the leader, if any.
double idm_accel_mps2(double speed_mps, const std::optional<IdmLeader>& leader, const IdmParams& p);

struct MobilParams {
  double politeness = 0.5;         // p
  double safe_brake_mps2 = 4.0;    // b_safe
  double threshold_mps2 = 0.1;     // Delta a_th
  double bias_mps2 = 0.3;          // Delta a_bias, toward the main lane
};

// The accelerations MOBIL weighs, each before (a) and after (a~) the prospective change: the ego
// (c), the new follower in the target lane (n) and the old follower in the current lane (o). A
// follower that does not exist contributes nothing.
struct MobilSituation {
  double ego_before_mps2 = 0.0;
  double ego_after_mps2 = 0.0;
  std::optional<double> new_follower_before_mps2;
  std::optional<double> new_follower_after_mps2;   // present when new_follower_before_mps2 is
  std::optional<double> old_follower_before_mps2;
  std::optional<double> old_follower_after_mps2;   // present when old_follower_before_mps2 is
};

// Kesting et al. 2007 eq. (2): a~_n >= -b_safe (safe when there is no new follower).
bool mobil_safe(const MobilSituation& s, const MobilParams& p);
// The left-hand side of Kesting et al. 2007 eq. (3): a~_c - a_c + p (a~_n - a_n + a~_o - a_o).
double mobil_advantage_mps2(const MobilSituation& s, const MobilParams& p);
// eq. (3) with the asymmetric rules' bias toward the target lane: advantage > Delta a_th - bias.
bool mobil_incentive(const MobilSituation& s, const MobilParams& p);
// Both criteria: the change is made.
bool mobil_changes_lane(const MobilSituation& s, const MobilParams& p);

}  // namespace mg
