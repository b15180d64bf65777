#include "rules/progress_monitor.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "rules/definition1_gap.h"

namespace mg {
namespace {

constexpr double kProgressEvalS = 0.1;
// At rest. (Braking toward a stop cannot be told from braking toward a merge speed by observation
// alone, so the grace period counts from the standstill.)
bool halting(const MonitorContext& ctx, const ObservedState& ego) { return speed_of(ego) < ctx.params.halted_speed_mps; }

}  // namespace

std::optional<FeasibleMerge> def1_gap_feasible(const ObservedTrace& t, const RuleParams& p, std::size_t step,
                                               double margin_m, double leader_braking_mps2) {
  const auto& v = t.steps[step].vehicles;
  const double rho = p.merge_duration_s;
  const Limits& ego = t.vehicles[0].limits;
  const double front_x_m = v[0].x_m + 0.5 * t.vehicles[0].size.length_m;
  if (t.road.side_lane_end_x_m - front_x_m < p.progress_min_room_m) return std::nullopt;
  for (const GapIndices& gap : lane_gaps(t, step)) {
    if (gap.leader > 0 && v[static_cast<std::size_t>(gap.leader)].accel_mps2 < -leader_braking_mps2) continue;
    Def1Interval in = def1_interval(t, step, gap, rho, margin_m);
    in.ve_lo_mps = std::max(in.ve_lo_mps, p.progress_min_merge_speed_mps);
    if (!in.feasible()) continue;
    const double to_mid_m = speed_change_distance_m(std::max(v[0].vx_mps, 0.0), in.ve_lo_mps, ego.accel_max_mps2,
                                                    ego.brake_min_mps2, 0.5 * rho);
    if (v[0].x_m + to_mid_m + 0.5 * t.vehicles[0].size.length_m > t.road.side_lane_end_x_m - margin_m) continue;
    const auto id = [&](int k) { return k < 1 ? -1 : t.vehicles[static_cast<std::size_t>(k)].id; };
    return FeasibleMerge{id(gap.follower), id(gap.leader), rho, in.ve_lo_mps};
  }
  return std::nullopt;
}

MonitorOutput monitor_progress(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("progress", steps.size());
  const double grace = ctx.params.progress_grace_s;
  double run_start = -1.0;
  double last_eval = -1.0;
  std::optional<FeasibleMerge> feasible;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const ObservedStep& st = steps[i];
    if (!halting(ctx, ego_of(st)) || ego_of(st).y_m >= -s.road.lane_width_m / 2.0) {
      run_start = -1.0;
      last_eval = -1.0;
      continue;
    }
    // Feasibility is re-evaluated every kProgressEvalS (no planner reacts instantly).
    if (last_eval < 0.0 || st.time_s - last_eval >= kProgressEvalS - 1e-9) {
      feasible = def1_gap_feasible(s, ctx.params, i, ctx.params.progress_gap_margin_m,
                                   ctx.params.progress_leader_braking_mps2);
      last_eval = st.time_s;
    }
    if (!feasible) {
      run_start = -1.0;
      acc.record(i, st.time_s, grace, Party::ego(), grace, 0.0);
      continue;
    }
    if (run_start < 0.0) run_start = st.time_s;
    const double needless = st.time_s - run_start;
    if (acc.record(i, st.time_s, grace - needless, Party::ego(), grace, needless)) {
      std::ostringstream os;
      const auto id = [](int i) { return i < 0 ? std::string("open") : std::to_string(i); };
      os << "ego halted in the side lane for " << needless << " s from t = " << run_start
         << " s while a Def. 1 gap was feasible (at t = " << st.time_s << " s: gap (follower " << id(feasible->follower_id)
         << ", leader " << id(feasible->leader_id) << "), rho = " << feasible->merge_duration_s
         << " s, v_e* = " << feasible->ve_star_mps << " m/s)";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
