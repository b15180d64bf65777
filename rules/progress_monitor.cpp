#include "rules/progress_monitor.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rules/definition1_monitor.h"

namespace mg {
namespace {

constexpr int kSpeedSamples = 16;

// Distance covered in tau seconds while changing speed from v to v_star at the given rates.
double distance_m(double v, double v_star, double accel, double brake, double tau) {
  const double rate = v_star >= v ? accel : brake;
  const double t_change = rate > 0.0 ? std::min(std::abs(v_star - v) / rate, tau) : 0.0;
  const double v_end = v + (v_star >= v ? 1.0 : -1.0) * rate * t_change;
  return (v + v_end) / 2.0 * t_change + v_end * (tau - t_change);
}

}  // namespace

bool def1_gap_feasible(const Scenario& s, const TraceStep& step, double rho, double margin) {
  std::vector<std::size_t> lane;  // rightmost main lane, sorted by X
  for (std::size_t k = 1; k <= s.vehicles.size(); ++k) {
    if (s.vehicles[k - 1].lane == 0) lane.push_back(k);
  }
  std::sort(lane.begin(), lane.end(),
            [&](std::size_t a, std::size_t b) { return state_of(step, a).x_m < state_of(step, b).x_m; });
  const VehicleState& ego = step.ego;
  const Limits& lim = s.ego.limits;
  const double v = std::max(speed_of(ego), 0.0);
  const double lo = std::max(0.0, v - lim.brake_min_mps2 * rho / 2.0);
  const double hi = std::min(s.road.speed_limit_mps, v + lim.accel_max_mps2 * rho / 2.0);
  const double end_x = s.road.side_lane_end_x_m - s.params.planner.halt_margin_m - s.ego.size.length_m / 2.0;
  for (int n = 0; n < kSpeedSamples; ++n) {
    const double v_star = lo + (hi - lo) * n / (kSpeedSamples - 1);
    const double half = distance_m(v, v_star, lim.accel_max_mps2, lim.brake_min_mps2, rho / 2.0);
    const double full = distance_m(v, v_star, lim.accel_max_mps2, lim.brake_min_mps2, rho);
    if (ego.x_m + half > end_x) continue;
    // The predicted ego positions replace X + v_e* rho/2 and X + v_e* rho in ineq. (1), (2).
    VehicleState at_half = ego, at_full = ego;
    at_half.x_m = ego.x_m + half - v_star * rho / 2.0;
    at_full.x_m = ego.x_m + full - v_star * rho;
    for (std::size_t g = 0; g <= lane.size(); ++g) {
      const bool follower_ok = g == 0 || def1_1_margin_m(s, at_half, lane[g - 1], state_of(step, lane[g - 1]),
                                                          v_star, rho) >= margin;
      // Ineq. (2) must hold over [T_dec, T_dec + rho] (RCPP Def. 1.2): checked at rho/2 and rho.
      const bool leader_ok =
          g == lane.size() ||
          (def1_2_margin_m(s, at_full, lane[g], state_of(step, lane[g]), v_star, rho) >= margin &&
           def1_2_margin_m(s, at_half, lane[g], state_of(step, lane[g]), v_star, rho / 2.0) >= margin);
      if (follower_ok && leader_ok) return true;
    }
  }
  return false;
}

MonitorOutput monitor_progress(const MonitorContext& ctx) {
  const Scenario& s = ctx.scenario;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("progress", steps.size());
  const double grace = ctx.params.progress_grace_s;
  double run_start = -1.0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const TraceStep& st = steps[i];
    const bool halting = st.ego_mode == DecisionMode::kDef1Halt || speed_of(st.ego) < ctx.params.halted_speed_mps;
    if (!halting || st.ego.y_m >= -s.road.lane_width_m / 2.0) {
      run_start = -1.0;
      continue;
    }
    if (!def1_gap_feasible(s, st, s.params.planner.merge_duration_s, ctx.params.progress_gap_margin_m)) {
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
