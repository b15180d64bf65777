#include "rules/progress_monitor.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "planner/definition1.h"
#include "planner/sigmoid.h"

namespace mg {

// The sharpest lane change the ego can really drive (DESIGN §6): the logistic path's peak
// curvature W kappa^2 / (6 sqrt 3) stays within both the kinematic-sideslip curvature of the
// lane-change budget, tan(budget)/l_r, and the steering limit tan(steer_max)/wheelbase, and kappa
// within the configured kappa_max.
double sharpest_kappa_per_m(const Scenario& s, double sideslip_budget_rad) {
  const EgoDynamics& d = s.ego.dynamics;
  const double curvature = std::min(std::tan(sideslip_budget_rad) / d.cg_to_rear_m,
                                    std::tan(d.steer_max_rad) / (d.cg_to_front_m + d.cg_to_rear_m));
  return std::min(s.params.planner.kappa_max_per_m,
                  std::sqrt(6.0 * std::sqrt(3.0) * curvature / s.road.lane_width_m));
}

// Ineq. (1.1) and (1.2) are the planner's own pure functions (planner/definition1.h: the paper's
// literal form AND the bounded-rate form of DESIGN §4), so the rule and the planner cannot
// disagree about the inequalities; the rule adds `margin` to both and to the side lane's end.
// The path is the gentlest logistic lane change that fits the ego's travel (2 % of the offset at
// the ego, the midpoint at rho/2, 98 % at rho): it must be drivable and within the planner's
// lateral comfort bound along the ego's speed profile (RCPP §II-C). v_e* is scanned (the comfort
// bound is not monotone in it), so a very narrow feasible interval may be missed: the rule errs
// toward calling a halt justified.
std::optional<FeasibleMerge> def1_gap_feasible(const Scenario& s, const TraceStep& step, double margin,
                                               double sideslip_budget_rad, double leader_braking_mps2) {
  std::vector<MainLaneVehicle> lane;  // rightmost main lane
  std::map<int, double> accel_mps2;   // id -> current acceleration
  for (std::size_t k = 1; k <= s.vehicles.size(); ++k) {
    const MainVehicle& m = s.vehicles[k - 1];
    if (m.lane != 0) continue;
    const VehicleState& o = state_of(step, k);
    lane.push_back(MainLaneVehicle{m.id, o.x_m, std::max(speed_of(o), 0.0), m.size.length_m, m.limits});
    accel_mps2[m.id] = o.accel_mps2;
  }
  const double w = s.road.lane_width_m;
  const double kappa_max = sharpest_kappa_per_m(s, sideslip_budget_rad);
  const double f = std::clamp(0.5 + s.ego.size.width_m / (2.0 * w), 0.5, 0.98);  // right edge leaves the side lane
  const double exit_limit_x = s.road.side_lane_end_x_m - 0.5 * s.ego.size.length_m - margin;
  const double rho_base = std::max(s.params.planner.merge_duration_s,
                                   shortest_comfortable_merge_s(w, s.params.planner.lat_accel_comfort_mps2));
  const double x0 = step.ego.x_m;
  for (const LaneGap& gap : enumerate_gaps(lane)) {
    // Def. 1.2 rests on the leader holding its speed; a leader seen braking offers no Def. 1 gap
    // until it stops braking (it may be braking for slower traffic ahead of it).
    if (gap.leader && accel_mps2[gap.leader->id] < -leader_braking_mps2) continue;
    for (const double factor : kProgressMergeDurationFactors) {
      const Def1Context c{x0, std::max(speed_of(step.ego), 0.0), s.ego.size.length_m, s.ego.limits,
                          s.params.rss.response_time_s, factor * rho_base, s.road.speed_limit_mps};
      for (int i = 0; i <= kProgressSpeedSamples; ++i) {
        const double ve = c.speed_limit_mps * i / kProgressSpeedSamples;
        if (gap.follower && def1_1_margin_m(c, *gap.follower, ve) < margin) continue;
        if (gap.leader && def1_2_margin_m(c, *gap.leader, ve) < margin) continue;
        const SpeedRamp ramp = c.ramp_to(ve);
        const double to_mid = ramp.distance_at_m(0.5 * c.merge_duration_s);
        const double kappa = std::log(49.0) / std::min(to_mid, ramp.distance_at_m(c.merge_duration_s) - to_mid);
        if (!(kappa <= kappa_max)) continue;
        if (x0 + to_mid + std::log(f / (1.0 - f)) / kappa > exit_limit_x) continue;
        const Sigmoid path{w, kappa, x0 + to_mid, -w};
        if (peak_lat_accel_along_mps2(path, ramp, x0) > s.params.planner.lat_accel_comfort_mps2) continue;
        return FeasibleMerge{gap.follower ? gap.follower->id : -1, gap.leader ? gap.leader->id : -1,
                             c.merge_duration_s, ve};
      }
    }
  }
  return std::nullopt;
}

MonitorOutput monitor_progress(const MonitorContext& ctx) {
  const Scenario& s = ctx.scenario;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("progress", steps.size());
  const double grace = ctx.params.progress_grace_s;
  double run_start = -1.0;
  double last_eval = -1.0;
  std::optional<FeasibleMerge> feasible;
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
      feasible = def1_gap_feasible(s, st, ctx.params.progress_gap_margin_m, ctx.params.progress_lane_change_sideslip_rad,
                                   ctx.params.progress_leader_braking_mps2);
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
      const auto id = [](int i) { return i < 0 ? std::string("open") : std::to_string(i); };
      os << "ego halted (or kept braking to a halt) in the side lane for " << needless << " s from t = " << run_start
         << " s while a Def. 1 gap was feasible (at t = " << st.time_s << " s: gap (follower " << id(feasible->follower_id)
         << ", leader " << id(feasible->leader_id) << "), rho = " << feasible->merge_duration_s
         << " s, v_e* = " << feasible->ve_star_mps << " m/s)";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
