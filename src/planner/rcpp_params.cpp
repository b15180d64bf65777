#include "planner/rcpp_params.h"

#include "core/json_reader.h"

namespace mg {
namespace {

using P = RcppParams;

constexpr Param<RcppParams> kRcppRows[] = {
    param("lat_accel_comfort_mps2", &P::lat_accel_comfort_mps2, "m/s²", above(0.0), at_most(10.0),
          "bound on the sigmoid's peak lateral acceleration"),
    param("kappa_min_per_m", &P::kappa_min_per_m, "1/m", above(0.0), at_most(10.0), "smallest sigmoid slope κ considered"),
    param("kappa_max_per_m", &P::kappa_max_per_m, "1/m", at_least_param("kappa_min_per_m"), at_most(10.0),
          "largest sigmoid slope κ considered"),
    param("pc_candidates", &P::pc_candidates, "", at_least(1.0), at_most(200.0),
          "v_e* (hence P_c) candidates scored by the field"),
    param("kappa_candidates", &P::kappa_candidates, "", at_least(1.0), at_most(200.0),
          "κ candidates scored by the field"),
    param("pf_road_beta", &P::pf_road_beta, "", at_least(0.0), at_most(1e6), "β of eq. 3: road-mark repulsion"),
    param("pf_obstacle_gamma", &P::pf_obstacle_gamma, "", at_least(0.0), at_most(1e6), "γ of eq. 4: obstacle repulsion"),
    param("pf_obstacle_u", &P::pf_obstacle_u, "", at_least(0.0), at_most(1.0), "U of eq. 4: small positive offset"),
    param("pf_lane_xi", &P::pf_lane_xi, "", at_least(0.0), at_most(1e6), "ξ of eq. 5: lane-centre attraction"),
    param("pf_search_distance_m", &P::pf_search_distance_m, "m", above(0.0), at_most(1000.0),
          "D* of eq. 5: search target distance of the merging mode"),
    param("cost_time_weight", &P::cost_time_weight, "1/s", at_least(0.0), at_most(1e3),
          "gap choice cost per second until the merge midpoint"),
    param("cost_speed_change_weight", &P::cost_speed_change_weight, "s/m", at_least(0.0), at_most(1e3),
          "gap choice cost per m/s of speed change"),
    param("cost_traffic_speed_weight", &P::cost_traffic_speed_weight, "s/m", at_least(0.0), at_most(1e3),
          "gap choice cost per m/s off the gap's traffic speed"),
};
static_assert(well_formed<RcppParams>(kRcppRows));

}  // namespace

const ParamTable<RcppParams>& rcpp_param_table() {
  static constexpr ParamTable<RcppParams> table{kRcppRows};
  return table;
}

RcppParams rcpp_params(const PlannerParams& p) {
  RcppParams out;
  // Mostly empty: a scenario read at the boundary keeps only the values off their defaults.
  if (p.tunables.empty()) return out;
  read_param_values(rcpp_param_table(), ObjectReader(p.tunables, "params", "/params/planner"), out);
  return out;
}

}  // namespace mg
