// RCPP's own tunables (RCPP §II-B/C, docs/planner.md): the sigmoid's comfort bound, slope range
// and candidate counts, the potential field's coefficients (eq. 3-5) and the cost weights. A
// scenario sets them in params.planner beside the keys every planner shares (core/params.h),
// but they are RCPP's: core keeps them as PlannerParams::tunables without knowing them,
// planner/planner_params.h checks them as a scenario is read, and rcpp_params() reads them.
#pragma once

#include "core/param_table.h"
#include "core/scenario.h"

namespace mg {

struct RcppParams {
  double lat_accel_comfort_mps2 = 1.5;  // bound on the sigmoid's peak lateral acceleration
  double kappa_min_per_m = 0.05;        // smallest sigmoid slope considered
  double kappa_max_per_m = 1.0;         // largest sigmoid slope considered
  int pc_candidates = 15;               // v_e* (hence P_c) samples scored by the field
  int kappa_candidates = 8;             // kappa samples scored by the field
  double pf_road_beta = 0.5;            // beta, road-mark repulsion (eq. 3)
  double pf_obstacle_gamma = 10.0;      // gamma, obstacle repulsion (eq. 4)
  double pf_obstacle_u = 0.01;          // U, small positive offset (eq. 4)
  double pf_lane_xi = 0.2;              // xi, lane-centre attraction (eq. 5)
  double pf_search_distance_m = 20.0;   // D*, search target distance of the merging mode (eq. 5)
  // Cost weights for choosing gap and v_e* (docs/planner.md, "Cost").
  double cost_time_weight = 1.0;
  double cost_speed_change_weight = 0.5;
  double cost_traffic_speed_weight = 0.2;
  bool operator==(const RcppParams&) const = default;
};

const ParamTable<RcppParams>& rcpp_param_table();

// The tunables `p` sets, the defaults for the others. A value out of its range raises InputError
// (a scenario read by planner_scenario_from_json has none).
RcppParams rcpp_params(const PlannerParams& p);
inline RcppParams rcpp_params(const PlannerSetup& s) { return rcpp_params(s.params.planner); }

}  // namespace mg
