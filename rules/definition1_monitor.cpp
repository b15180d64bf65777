#include "rules/definition1_monitor.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "rules/definition1_gap.h"

namespace mg {
namespace {

enum class GapSide { kFollower, kLeader };

// The margin and the vehicle a def1 gap rule judges for an attempt that entered the main lane:
// for an attempt that reached its midpoint, Definition 1 toward the gap entered's vehicle of that
// side unless that vehicle's own acceptance covers it (rules/merge_attempts.h); for one that did
// not, the Definition 1 reading's gap. Nothing for an attempt made on a late acceptance
// (def2_3_fallback's) or on one from a lying request (def2_request_truthful's).
struct GapJudgement {
  int vehicle = -1;
  double margin_m = 0.0;
  bool pair = false;  // Definition 1 for the pair alone (the vehicle is not of the reading's gap)
};

std::optional<GapJudgement> gap_judgement(const MergeAttempt& a, GapSide side) {
  if (!a.entry_step || a.fault != AcceptanceFault::kNone) return std::nullopt;
  const bool follower = side == GapSide::kFollower;
  if (a.midpoint_time_s) {
    const PairCover& c = follower ? a.follower : a.leader;
    if (c.vehicle < 1 || c.by == Cover::kDef2 || !std::isfinite(c.margin_m)) return std::nullopt;
    const bool member = a.basis != RowBasis::kDef2 && (c.vehicle == a.gap.follower || c.vehicle == a.gap.leader);
    return GapJudgement{c.vehicle, c.margin_m, !member};
  }
  if (a.basis == RowBasis::kDef2 || !a.def1_read) return std::nullopt;
  const int k = follower ? a.gap.follower : a.gap.leader;
  if (k < 1) return std::nullopt;  // open side of the gap: nothing to satisfy
  return GapJudgement{k, follower ? a.def1.margin_11_m : a.def1.margin_12_m, false};
}

// Definition 1's margin toward the side's vehicle of each attempt, >= 0 when the ego held the
// right of way toward it by Definition 1 (a Definition 2 acceptance of the other vehicle's
// included, whose gap's other vehicle Definition 1 judges for the pair at the request).
MonitorOutput monitor_gap_inequality(const MonitorContext& ctx, GapSide side) {
  const ObservedTrace& t = ctx.trace;
  const bool follower = side == GapSide::kFollower;
  MarginAccumulator acc(follower ? "def1_1_gap" : "def1_2_gap", t.steps.size());
  for (const MergeAttempt& a : ctx.attempts.attempts) {
    const std::optional<GapJudgement> g = gap_judgement(a, side);
    if (!g) continue;
    if (acc.record(*a.entry_step, *a.entry_time_s, g->margin_m, Party::ego(), 0.0, g->margin_m)) {
      const Def1Reading& r = a.def1;
      std::ostringstream os;
      os << "ego entered the main lane at t = " << *a.entry_time_s << " s (merge started at t = " << a.start_time_s
         << " s) without the right of way toward " << (follower ? "follower " : "leader ")
         << party_name(party_of(t, static_cast<std::size_t>(g->vehicle))) << ": ";
      if (a.basis == RowBasis::kDef2 || (g->pair && !a.def1_read)) {
        os << "Def. 1 for the pair at the request of the other vehicle's acceptance fails by " << -g->margin_m << " m";
      } else {
        os << "at the best instant of its decision window (t = " << r.time_s << " s, v_e* = " << r.ve_star_mps
           << " m/s, rho = " << r.rho_s << " s) " << (follower ? "ineq. (1)" : "ineq. (2)")
           << (g->pair ? " for the pair (it is no vehicle of the gap read)" : "") << " fails by " << -g->margin_m
           << " m";
      }
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

enum class LimitKind { kAccel, kBrake };

// The vehicles whose limit Definition 1 counted on for an attempt it granted: the reading's
// gap vehicle of that side, and the gap entered's vehicle of that side when Definition 1 covered
// it for the pair at the reading.
std::vector<int> def1_counted_on(const MergeAttempt& a, LimitKind kind) {
  const bool accel = kind == LimitKind::kAccel;
  std::vector<int> out;
  if (const int k = accel ? a.gap.follower : a.gap.leader; k >= 1) out.push_back(k);
  const PairCover& c = accel ? a.follower : a.leader;
  if (c.by == Cover::kDef1Pair && c.vehicle >= 1 && (out.empty() || out.front() != c.vehicle)) out.push_back(c.vehicle);
  return out;
}

// Margin of main-lane vehicle k's declared limit over [T_dec, T_dec + window].
void window_limit(const MonitorContext& ctx, const MergeAttempt& a, LimitKind kind, int k, MarginAccumulator& acc) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  const double tol = ctx.params.accel_tolerance_mps2;
  const Party other = party_of(s, static_cast<std::size_t>(k));
  const Limits& lim = limits_of(s, static_cast<std::size_t>(k));
  const double from_s = a.decision_time_s;
  // The paper's windows, [T_dec, T_dec + rho/2] and [T_dec, T_dec + rho], stretched to the
  // observed midpoint and completion when the merge took longer than rho says.
  double until_s = from_s + (kind == LimitKind::kAccel ? a.def1.rho_s / 2.0 : a.def1.rho_s);
  if (kind == LimitKind::kAccel && a.midpoint_time_s) until_s = std::max(until_s, *a.midpoint_time_s);
  if (kind == LimitKind::kBrake && a.completed) until_s = std::max(until_s, *a.end_time_s);
  for (std::size_t i = a.def1.step; i < steps.size() && steps[i].time_s <= until_s + 1e-9; ++i) {
    const double accel = state_of(steps[i], static_cast<std::size_t>(k)).accel_mps2;
    const double limit = kind == LimitKind::kAccel ? lim.accel_max_mps2 : lim.brake_max_mps2;
    const double m = kind == LimitKind::kAccel ? limit + tol - accel : limit + tol + accel;
    if (acc.record(i, steps[i].time_s, m, other, limit, kind == LimitKind::kAccel ? accel : -accel)) {
      std::ostringstream os;
      os << party_name(other) << (kind == LimitKind::kAccel ? " accelerated at " : " braked at ") << std::abs(accel)
         << " m/s2, beyond its declared " << (kind == LimitKind::kAccel ? "a_accel^max " : "a_brake^max ") << limit
         << " m/s2, in the Def. 1." << (kind == LimitKind::kAccel ? "1" : "2")
         << " window of the merge the ego had the right of way for from t = " << from_s << " s";
      acc.set_detail(os.str());
    }
  }
}

// Definition 1.1 / 1.2's bounds on the vehicles Definition 1 counted on.
MonitorOutput monitor_window_limit(const MonitorContext& ctx, LimitKind kind) {
  MarginAccumulator acc(kind == LimitKind::kAccel ? "def1_1_follower" : "def1_2_leader", ctx.trace.steps.size());
  for (const MergeAttempt& a : ctx.attempts.attempts) {
    if (a.basis != RowBasis::kDef1) continue;
    for (const int k : def1_counted_on(a, kind)) window_limit(ctx, a, kind, k, acc);
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
