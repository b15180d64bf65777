#include "rules/progress_monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "rules/definition1_monitor.h"

namespace mg {
namespace {

constexpr int kBisections = 24;

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
  // The predicted ego (X shifted so that X + v_e* tau is where it really is after tau).
  auto ego_at = [&](double v_star, double tau) {
    VehicleState e = ego;
    e.x_m = ego.x_m + speed_change_distance_m(v, v_star, lim.accel_max_mps2, lim.brake_min_mps2, tau) - v_star * tau;
    return e;
  };
  constexpr double kOpen = std::numeric_limits<double>::infinity();
  for (std::size_t g = 0; g <= lane.size(); ++g) {
    // Ineq. (1) toward the follower: non-decreasing in v_e* (the ego gets farther ahead and
    // D_lon with the ego in front shrinks).
    auto follower_margin = [&](double v_star) {
      return g == 0 ? kOpen
                    : def1_1_margin_m(s, ego_at(v_star, rho / 2.0), lane[g - 1], state_of(step, lane[g - 1]), v_star, rho);
    };
    // Ineq. (2) toward the leader at rho/2 and rho, and the midpoint before the side lane end:
    // non-increasing in v_e*.
    auto leader_margin = [&](double v_star) {
      const VehicleState half = ego_at(v_star, rho / 2.0);
      double m = end_x - (half.x_m + v_star * rho / 2.0);
      if (g < lane.size()) {
        const VehicleState& o = state_of(step, lane[g]);
        m = std::min({m, def1_2_margin_m(s, ego_at(v_star, rho), lane[g], o, v_star, rho),
                      def1_2_margin_m(s, half, lane[g], o, v_star, rho / 2.0)});
      }
      return m;
    };
    if (follower_margin(hi) < margin || leader_margin(lo) < margin) continue;
    // Smallest v_e* that satisfies ineq. (1) (bisection on a monotone margin), then ineq. (2).
    double a = lo, b = hi;
    if (follower_margin(lo) >= margin) b = lo;
    for (int it = 0; it < kBisections && b > a; ++it) {
      const double mid = 0.5 * (a + b);
      (follower_margin(mid) >= margin ? b : a) = mid;
    }
    if (leader_margin(b) >= margin) return true;
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
      feasible = def1_gap_feasible(s, st, s.params.planner.merge_duration_s, ctx.params.progress_gap_margin_m);
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
