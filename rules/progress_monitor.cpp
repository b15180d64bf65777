#include "rules/progress_monitor.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "planner/definition1.h"

namespace mg {

// The planner's own Definition 1 functions (planner/definition1.h: the paper's literal form AND
// the bounded-rate form of DESIGN §4) judge feasibility, so the rule and the planner cannot
// disagree about what a feasible gap is; the rule only adds `margin` to both inequalities.
bool def1_gap_feasible(const Scenario& s, const TraceStep& step, double rho, double margin,
                       double min_midpoint_ahead_m) {
  std::vector<MainLaneVehicle> lane;  // rightmost main lane
  for (std::size_t k = 1; k <= s.vehicles.size(); ++k) {
    const MainVehicle& m = s.vehicles[k - 1];
    if (m.lane != 0) continue;
    const VehicleState& o = state_of(step, k);
    lane.push_back(MainLaneVehicle{m.id, o.x_m, std::max(speed_of(o), 0.0), m.size.length_m, m.limits});
  }
  const Def1Context c{step.ego.x_m,  std::max(speed_of(step.ego), 0.0), s.ego.size.length_m, s.ego.limits,
                      s.params.rss.response_time_s, rho, s.road.speed_limit_mps};
  const double end_x = s.road.side_lane_end_x_m - s.params.planner.halt_margin_m - s.ego.size.length_m / 2.0;
  for (const LaneGap& gap : enumerate_gaps(lane)) {
    // Ineq. (1.1): non-decreasing in v_e*, so the smallest satisfying v_e* is the best for (1.2).
    double lo = 0.0;
    if (gap.follower) {
      const auto v = lowest_satisfying(
          [&](double ve) { return def1_1_margin_m(c, *gap.follower, ve) - margin; }, 0.0, c.speed_limit_mps);
      if (!v) continue;
      lo = *v;
    }
    // Ineq. (1.2) and the merge midpoint before the side lane end: non-increasing in v_e*.
    const double mid_x = c.ego_x_m + std::max(c.ramp_to(lo).distance_at_m(rho / 2.0), min_midpoint_ahead_m);
    double m = end_x - mid_x;
    if (gap.leader) m = std::min(m, def1_2_margin_m(c, *gap.leader, lo) - margin);
    if (m >= 0.0) return true;
  }
  return false;
}

MonitorOutput monitor_progress(const MonitorContext& ctx) {
  const Scenario& s = ctx.scenario;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("progress", steps.size());
  const double grace = ctx.params.progress_grace_s;
  double run_start = -1.0;
  double last_eval = -1.0;
  bool feasible = false;
  // The shortest way to the lane boundary that respects the sideslip rule: a logistic lane change
  // whose peak curvature W kappa^2 / (6 sqrt 3) stays within the kinematic-sideslip curvature
  // tan(sideslip_max) / l_r covers ln(49) / kappa from 2 % of the offset to its midpoint. From a
  // standstill just before the side lane's end no merge fits, whatever the gaps.
  const double curvature_max = std::tan(ctx.params.sideslip_max_rad) / s.ego.dynamics.cg_to_rear_m;
  const double kappa_max = std::sqrt(6.0 * std::sqrt(3.0) * curvature_max / s.road.lane_width_m);
  const double min_midpoint_ahead = std::log(49.0) / kappa_max;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const TraceStep& st = steps[i];
    const bool halting = st.ego_mode == DecisionMode::kDef1Halt || speed_of(st.ego) < ctx.params.halted_speed_mps;
    if (!halting || st.ego.y_m >= -s.road.lane_width_m / 2.0) {
      run_start = -1.0;
      last_eval = -1.0;
      continue;
    }
    // Feasibility is re-evaluated once per planner cycle (the planner cannot react faster).
    if (last_eval < 0.0 || st.time_s - last_eval >= s.params.sim.planner_cycle_s - 1e-9) {
      feasible = def1_gap_feasible(s, st, s.params.planner.merge_duration_s, ctx.params.progress_gap_margin_m,
                                   min_midpoint_ahead);
      last_eval = st.time_s;
    }
    if (!feasible) {
      run_start = -1.0;
      acc.record(i, st.time_s, grace, kEgoId, grace, 0.0);
      continue;
    }
    if (run_start < 0.0) run_start = st.time_s;
    const double needless = st.time_s - run_start;
    if (acc.record(i, st.time_s, grace - needless, kEgoId, grace, needless)) {
      std::ostringstream os;
      os << "ego halted (or kept braking to a halt) in the side lane for " << needless << " s from t = " << run_start
         << " s while a Def. 1 gap was feasible";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
