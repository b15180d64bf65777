// Definition 1 of RCPP (non-cooperative merge; spec §4): ineq. (1) and (2) at every Def. 1
// decision, the follower's and leader's obligations in their windows, and the halt of 1.3.
#pragma once

#include <vector>

#include "rules/monitor.h"

namespace mg {

// A run of Def. 1 merge decisions toward the same gap; T_dec is its first decision.
struct MergeEpoch {
  const Decision* decision = nullptr;  // the first decision (T_dec = decision->time_s)
  double merge_duration_s = 0.0;       // rho used by that decision
};
std::vector<MergeEpoch> def1_merge_epochs(const Scenario& s, const Trace& t);

// Left minus right side of RCPP ineq. (1) (Def. 1.1) and (2) (Def. 1.2), >= 0 when they hold.
double def1_1_margin_m(const Scenario& s, const VehicleState& ego, std::size_t follower,
                       const VehicleState& follower_state, double ve_star_mps, double rho_m_s);
double def1_2_margin_m(const Scenario& s, const VehicleState& ego, std::size_t leader,
                       const VehicleState& leader_state, double ve_star_mps, double rho_m_s);

// Distance covered in tau seconds while changing speed from v to v_star at the given rates
// (then holding v_star): the ego's real position model of spec §4.
double speed_change_distance_m(double v, double v_star, double accel, double brake, double tau);

MonitorOutput monitor_def1_1_gap(const MonitorContext& ctx);
MonitorOutput monitor_def1_1_follower(const MonitorContext& ctx);
MonitorOutput monitor_def1_2_gap(const MonitorContext& ctx);
MonitorOutput monitor_def1_2_leader(const MonitorContext& ctx);
MonitorOutput monitor_def1_3_halt(const MonitorContext& ctx);

}  // namespace mg
