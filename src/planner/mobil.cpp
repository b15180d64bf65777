#include "planner/mobil.h"

#include <algorithm>
#include <cmath>

#include "core/demand.h"

namespace mg {

double idm_free_road_mps2(double speed_mps, const IdmParams& p) {
  MG_DEMAND(p.desired_speed_mps > 0.0);
  // IDM eq. (1), Treiber et al. 2000: a [1 - (v/v0)^delta]
  return p.max_accel_mps2 * (1.0 - std::pow(speed_mps / p.desired_speed_mps, p.exponent));
}

double idm_desired_gap_m(double speed_mps, double approach_rate_mps, const IdmParams& p) {
  MG_DEMAND(p.max_accel_mps2 > 0.0 && p.comfort_brake_mps2 > 0.0);
  // IDM eq. (2), Treiber et al. 2000, s1 = 0: s0 + max(0, v T + v dv / (2 sqrt(a b)))
  const double dynamic = speed_mps * p.time_headway_s +
                         speed_mps * approach_rate_mps / (2.0 * std::sqrt(p.max_accel_mps2 * p.comfort_brake_mps2));
  return p.min_gap_m + std::max(0.0, dynamic);
}

double idm_interaction_mps2(double speed_mps, const IdmLeader& leader, const IdmParams& p) {
  const double s_star = idm_desired_gap_m(speed_mps, speed_mps - leader.speed_mps, p);
  const double ratio = s_star / std::max(leader.gap_m, kIdmMinGapM);
  // IDM eq. (1), Treiber et al. 2000: -a (s*/s)^2
  return -p.max_accel_mps2 * ratio * ratio;
}

double idm_accel_mps2(double speed_mps, const std::optional<IdmLeader>& leader, const IdmParams& p) {
  const double free_road = idm_free_road_mps2(speed_mps, p);
  return leader ? free_road + idm_interaction_mps2(speed_mps, *leader, p) : free_road;
}

bool mobil_safe(const MobilSituation& s, const MobilParams& p) {
  // Kesting et al. 2007 eq. (2): a~_n >= -b_safe
  return !s.new_follower_after_mps2 || *s.new_follower_after_mps2 >= -p.safe_brake_mps2;
}

double mobil_advantage_mps2(const MobilSituation& s, const MobilParams& p) {
  MG_DEMAND(s.new_follower_before_mps2.has_value() == s.new_follower_after_mps2.has_value());
  MG_DEMAND(s.old_follower_before_mps2.has_value() == s.old_follower_after_mps2.has_value());
  const double new_follower = s.new_follower_after_mps2 ? *s.new_follower_after_mps2 - *s.new_follower_before_mps2 : 0.0;
  const double old_follower = s.old_follower_after_mps2 ? *s.old_follower_after_mps2 - *s.old_follower_before_mps2 : 0.0;
  // Kesting et al. 2007 eq. (3), left-hand side: a~_c - a_c + p (a~_n - a_n + a~_o - a_o)
  return s.ego_after_mps2 - s.ego_before_mps2 + p.politeness * (new_follower + old_follower);
}

bool mobil_incentive(const MobilSituation& s, const MobilParams& p) {
  // Kesting et al. 2007 eq. (3), with the asymmetric rules' bias toward the target lane
  return mobil_advantage_mps2(s, p) > p.threshold_mps2 - p.bias_mps2;
}

bool mobil_changes_lane(const MobilSituation& s, const MobilParams& p) { return mobil_safe(s, p) && mobil_incentive(s, p); }

}  // namespace mg
