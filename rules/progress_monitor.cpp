#include "rules/progress_monitor.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "planner/definition1.h"
#include "planner/merge_path.h"
#include "planner/sigmoid.h"

namespace mg {
namespace {

// The first index in [lo, hi) where pred is false, pred being true on a prefix; hi if none.
// (std::ranges::partition_point over an iota_view does not compile with clang and libstdc++ 12.)
template <class Pred>
int first_index_where_not(int lo, int hi, Pred pred) {
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (pred(mid)) lo = mid + 1; else hi = mid;
  }
  return lo;
}

}  // namespace

// Ineq. (1.1) and (1.2), the merge path's admissibility and the occupancy check are the planner's
// own pure functions (planner/definition1.h, planner/merge_path.h), so the rule and the planner
// cannot disagree about what a feasible, drivable, comfortable and RSS-clear merge is; the rule
// adds `margin` to both inequalities and to the side lane's end, and stays independent of the
// planner's choices: which gap, P_c and kappa, the cost, and its prediction of braking leaders (a
// braking leader simply offers no gap here). For each v_e* the path is the sharpest admissible
// sigmoid with its midpoint where the ego is at rho/2: it starts its lateral motion last, so it is
// the one most likely to find the lane clear. v_e* is scanned (the comfort and occupancy checks
// are not monotone in it), so a very narrow feasible interval may be missed: the rule errs toward
// calling a halt justified.
std::optional<FeasibleMerge> def1_gap_feasible(const Scenario& s, const TraceStep& step, double margin,
                                               double leader_braking_mps2) {
  std::vector<MainLaneVehicle> lane;  // rightmost main lane
  std::vector<std::pair<int, double>> accel_by_id;  // id, current acceleration
  std::vector<Track> beside;                        // the other main lanes
  for (std::size_t k = 1; k <= s.vehicles.size(); ++k) {
    const MainVehicle& m = s.vehicles[k - 1];
    const VehicleState& o = state_of(step, k);
    const MainLaneVehicle v{m.id, o.x_m, std::max(speed_of(o), 0.0), m.size.length_m, m.size.width_m, m.limits};
    if (m.lane != 0) {
      beside.push_back(beside_track(v, m.lane * s.road.lane_width_m, o.accel_mps2));
      continue;
    }
    lane.push_back(v);
    accel_by_id.emplace_back(m.id, o.accel_mps2);
  }
  const auto accel_mps2 = [&](int id) {
    for (const auto& [i, a] : accel_by_id)
      if (i == id) return a;
    return 0.0;
  };
  const double w = s.road.lane_width_m;
  const double exit_after_pc_times_kappa = ln_ratio(side_lane_exit_fraction(s.ego.size.width_m, w));
  const double rho_base = merge_duration_base_s(s.params.planner.merge_duration_s, w, s.params.planner.lat_accel_comfort_mps2);
  const double x0 = step.ego.x_m;
  OccupancyMemo memo;  // only for its hint: the speeds scanned mostly fail at the same instant
  for (const LaneGap& gap : enumerate_gaps(lane)) {
    // Def. 1.2 rests on the leader holding its speed; a leader seen braking offers no Def. 1 gap
    // until it stops braking (it may be braking for slower traffic ahead of it).
    if (gap.leader && accel_mps2(gap.leader->id) < -leader_braking_mps2) continue;
    for (const double factor : kMergeDurationFactors) {
      const Def1Context c{x0, std::max(speed_of(step.ego), 0.0), s.ego.size.length_m, s.ego.limits,
                          s.params.rss.response_time_s, factor * rho_base, s.road.speed_limit_mps};
      const auto ve_at = [&](int i) { return c.speed_limit_mps * i / kProgressSpeedSamples; };
      // Ineq. (1.1)'s margin grows with v_e* and (1.2)'s falls (definition1.h), so the samples
      // that satisfy both are one run [first, end): found by bisection over the sample indices.
      // Most gaps fail one inequality at every speed: the end of the run that would satisfy it
      // is tried first.
      const int n = kProgressSpeedSamples + 1;
      const auto fails_11 = [&](int i) { return def1_1_margin_m(c, *gap.follower, ve_at(i)) < margin; };
      const auto holds_12 = [&](int i) { return def1_2_margin_m(c, *gap.leader, ve_at(i)) >= margin; };
      const int first = !gap.follower ? 0 : fails_11(n - 1) ? n
                                          : first_index_where_not(0, n - 1, fails_11);
      if (first == n) continue;
      const int end = !gap.leader ? n : !holds_12(first) ? first
                                        : first_index_where_not(first + 1, n, holds_12);
      if (first == end) continue;
      // The gap's leader is not braking (above); the vehicles ahead of it as seen.
      GapTracks tracks = gap_tracks(lane, gap, c.merge_duration_s, accel_mps2);
      tracks.beside = beside;
      for (int i = first; i < end; ++i) {
        const double ve = ve_at(i);
        const SpeedRamp ramp = c.ramp_to(ve);
        const double pc = x0 + ramp.distance_at_m(0.5 * c.merge_duration_s);
        const KappaRange kappa = kappa_range_for(s, pc, x0, x0 + ramp.distance_at_m(c.merge_duration_s), ramp, x0);
        if (!kappa) continue;
        if (pc + exit_after_pc_times_kappa / kappa->second > side_exit_limit_x_m(s) - margin) continue;
        const Sigmoid path{w, kappa->second, pc, -w};
        memo.forget_ramp();
        if (!occupancy_clear(s, x0, step.ego.y_m, path, ramp, OccupancyInstants::over(c.merge_duration_s), tracks,
                             kOccupancyPlanningBufferM, &memo)) continue;
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
      feasible = def1_gap_feasible(s, st, ctx.params.progress_gap_margin_m, ctx.params.progress_leader_braking_mps2);
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
