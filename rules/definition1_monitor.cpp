#include "rules/definition1_monitor.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rules/definition1_gap.h"

namespace mg {
namespace {

enum class GapSide { kFollower, kLeader };

// An attempt judged by Definition 1 (neither granted by Definition 2 nor made on a late acceptance,
// which is def2_3's): its margin toward the side's gap vehicle, >= 0 when the ego held the right
// of way by Definition 1.
MonitorOutput monitor_gap_inequality(const MonitorContext& ctx, GapSide side) {
  const ObservedTrace& t = ctx.trace;
  MarginAccumulator acc(side == GapSide::kFollower ? "def1_1_gap" : "def1_2_gap", t.steps.size());
  for (const MergeAttempt& a : ctx.attempts.attempts) {
    // An attempt that stayed in the side lane took nobody's room.
    if (a.basis == RowBasis::kDef2 || a.exchange || !a.def1_read || !a.entry_step) continue;
    const int k = side == GapSide::kFollower ? a.gap.follower : a.gap.leader;
    if (k < 1) continue;  // open side of the gap: nothing to satisfy
    const Def1Reading& r = a.def1;
    const double m = side == GapSide::kFollower ? r.margin_11_m : r.margin_12_m;
    if (acc.record(*a.entry_step, *a.entry_time_s, m, Party::ego(), 0.0, m)) {
      std::ostringstream os;
      os << "ego entered the main lane at t = " << *a.entry_time_s << " s (merge started at t = " << a.start_time_s
         << " s) without the right of way: at the best instant "
         << "of its decision window (t = " << r.time_s << " s, v_e* = " << r.ve_star_mps << " m/s, rho = " << r.rho_s
         << " s) " << (side == GapSide::kFollower ? "ineq. (1) toward follower " : "ineq. (2) toward leader ")
         << party_name(party_of(t, static_cast<std::size_t>(k))) << " fails by " << -m << " m";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

enum class LimitKind { kAccel, kBrake };

// Margin of a main-lane vehicle's declared limit over [T_dec, T_dec + window].
MonitorOutput monitor_window_limit(const MonitorContext& ctx, LimitKind kind) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc(kind == LimitKind::kAccel ? "def1_1_follower" : "def1_2_leader", steps.size());
  const double tol = ctx.params.accel_tolerance_mps2;
  for (const MergeAttempt& a : ctx.attempts.attempts) {
    if (a.basis != RowBasis::kDef1) continue;
    const int k = kind == LimitKind::kAccel ? a.gap.follower : a.gap.leader;
    if (k < 1) continue;
    const Party other = party_of(s, static_cast<std::size_t>(k));
    const Limits& lim = limits_of(s, static_cast<std::size_t>(k));
    const double from_s = a.decision_time_s;
    // The paper's windows, [T_dec, T_dec + rho/2] and [T_dec, T_dec + rho], stretched to the
    // observed midpoint and completion when the merge took longer than rho says.
    double until_s = from_s + (kind == LimitKind::kAccel ? a.def1.rho_s / 2.0 : a.def1.rho_s);
    if (kind == LimitKind::kAccel && a.midpoint_time_s) until_s = std::max(until_s, *a.midpoint_time_s);
    if (kind == LimitKind::kBrake && a.completed) until_s = std::max(until_s, *a.end_time_s);
    for (std::size_t i = a.def1.step; i < steps.size() && steps[i].time_s <= until_s + 1e-9; ++i) {
      const double a = state_of(steps[i], static_cast<std::size_t>(k)).accel_mps2;
      const double limit = kind == LimitKind::kAccel ? lim.accel_max_mps2 : lim.brake_max_mps2;
      const double m = kind == LimitKind::kAccel ? limit + tol - a : limit + tol + a;
      if (acc.record(i, steps[i].time_s, m, other, limit, kind == LimitKind::kAccel ? a : -a)) {
        std::ostringstream os;
        os << party_name(other) << (kind == LimitKind::kAccel ? " accelerated at " : " braked at ")
           << std::abs(a) << " m/s2, beyond its declared "
           << (kind == LimitKind::kAccel ? "a_accel^max " : "a_brake^max ") << limit << " m/s2, in the Def. 1."
           << (kind == LimitKind::kAccel ? "1" : "2") << " window of the merge the ego had the right of way for from t = "
           << from_s << " s";
        acc.set_detail(os.str());
      }
    }
  }
  return acc.finish();
}

bool any_def1_gap_feasible(const ObservedTrace& t, std::size_t step, double rho_s) {
  for (const GapIndices& gap : lane_gaps(t, step))
    if (def1_feasible(t, step, gap, rho_s)) return true;
  return false;
}

}  // namespace

MonitorOutput monitor_def1_1_gap(const MonitorContext& ctx) { return monitor_gap_inequality(ctx, GapSide::kFollower); }
MonitorOutput monitor_def1_2_gap(const MonitorContext& ctx) { return monitor_gap_inequality(ctx, GapSide::kLeader); }
MonitorOutput monitor_def1_1_follower(const MonitorContext& ctx) { return monitor_window_limit(ctx, LimitKind::kAccel); }
MonitorOutput monitor_def1_2_leader(const MonitorContext& ctx) { return monitor_window_limit(ctx, LimitKind::kBrake); }

// RCPP Def. 1.3: without the right of way, the ego in the side lane must stay able to halt
// before the side lane ends (braking at its a_brake^max).
MonitorOutput monitor_def1_3_halt(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("def1_3_halt", steps.size());
  const double boundary_y = -s.road.lane_width_m / 2.0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const ObservedState& e = ego_of(steps[i]);
    if (e.y_m >= boundary_y || ctx.row.ego_holds_at(steps[i].time_s)) continue;
    const double v = std::max(speed_of(e), 0.0);
    const double stop_x = e.x_m + size_of(s, 0).length_m / 2.0 + v * v / (2.0 * limits_of(s, 0).brake_max_mps2);
    const double m = s.road.side_lane_end_x_m - stop_x;
    // Def. 1.3 binds only while no gap satisfies ineq. (1.1)/(1.2): with one, the ego may go on
    // toward it (whether it then enters with the right of way is the gap rules' question).
    if (m < 0.0 && any_def1_gap_feasible(s, i, ctx.params.merge_duration_s)) continue;
    if (acc.record(i, steps[i].time_s, m, Party::ego(), s.road.side_lane_end_x_m, stop_x)) {
      std::ostringstream os;
      os << "ego in the side lane without a gap can no longer halt before its end at x = "
         << s.road.side_lane_end_x_m << " m (front would stop at x = " << stop_x << " m)";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
