#include "rules/definition1_monitor.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "rules/declared_limits_monitor.h"
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

// The vehicles bounding the gaps feasible at step i at rho_s (ineq. (1.1)/(1.2)); empty when
// none is.
std::vector<std::size_t> def1_feasible_gap_vehicles(const ObservedTrace& t, std::size_t step, double rho_s) {
  std::vector<std::size_t> out;
  for (const GapIndices& gap : lane_gaps(t, step)) {
    if (!def1_feasible(t, step, gap, rho_s)) continue;
    for (const int k : {gap.follower, gap.leader})
      if (k >= 1) out.push_back(static_cast<std::size_t>(k));
    if (gap.follower < 1 && gap.leader < 1) out.push_back(0);  // an empty lane: feasible, bounded by none
  }
  return out;
}

// Of the vehicles bounding the gaps the ego went on toward, the first seen beyond its declared
// limits at a step of [from, to].
std::optional<std::size_t> breach_among(const MonitorContext& ctx, const std::vector<std::size_t>& vehicles,
                                        std::size_t from, std::size_t to) {
  for (std::size_t i = from; i <= to; ++i)
    for (const std::size_t k : vehicles)
      if (k >= 1 && beyond_declared_limits(ctx.trace, ctx.params, i, k)) return k;
  return std::nullopt;
}

// The latest step within the RSS response time before step i at which the ego, in the side lane
// and still able to halt, had a feasible gap (Def. 1.3 did not bind), with the vehicles bounding
// the gaps feasible then; nullopt when there is none.
struct GapsAt {
  std::size_t step;
  std::vector<std::size_t> vehicles;
};
std::optional<GapsAt> last_gap_within_response(const MonitorContext& ctx, std::size_t i) {
  const ObservedTrace& t = ctx.trace;
  const double from_s = t.steps[i].time_s - t.params.rss.response_time_s - kTieS;
  for (std::size_t j = i; j > 0 && t.steps[j - 1].time_s >= from_s;) {
    --j;
    if (ego_of(t.steps[j]).y_m >= -0.5 * t.road.lane_width_m) return std::nullopt;
    if (std::vector<std::size_t> v = def1_feasible_gap_vehicles(t, j, ctx.params.merge_duration_s); !v.empty())
      return GapsAt{j, std::move(v)};
  }
  return std::nullopt;
}

}  // namespace

MonitorOutput monitor_def1_1_gap(const MonitorContext& ctx) { return monitor_gap_inequality(ctx, GapSide::kFollower); }
MonitorOutput monitor_def1_2_gap(const MonitorContext& ctx) { return monitor_gap_inequality(ctx, GapSide::kLeader); }
MonitorOutput monitor_def1_1_follower(const MonitorContext& ctx) { return monitor_window_limit(ctx, LimitKind::kAccel); }
MonitorOutput monitor_def1_2_leader(const MonitorContext& ctx) { return monitor_window_limit(ctx, LimitKind::kBrake); }

// RCPP Def. 1.3: without the right of way, the ego in the side lane must stay able to halt
// before the side lane ends (braking at its a_brake^max). It binds only while no gap satisfies
// ineq. (1.1)/(1.2): with one, the ego may go on toward it (whether it then enters with the right
// of way is the gap rules' question). When the gaps it went on toward, no longer able to halt,
// are lost while one of their vehicles is seen beyond its declared limits, the ego could not
// have foreseen it: that vehicle is liable (docs/spec_rules.md, Definition 1.3). Such steps are
// recorded after the ego's own, so that a breach never hides a violation the ego is liable for.
MonitorOutput monitor_def1_3_halt(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("def1_3_halt", steps.size());
  const double boundary_y = -s.road.lane_width_m / 2.0;
  std::vector<std::size_t> relied_on;  // the vehicles of the gaps that last relieved the ego
  std::size_t breach = 0;              // one of them seen beyond its limits since they did (0: none)
  std::size_t unscanned = 0;           // the first step not yet looked at for that
  bool looked_back = false;            // for a gap within the response time, since the halt was lost
  struct Excused {
    std::size_t step;
    double margin_m, stop_x_m;
    std::size_t vehicle;
  };
  std::vector<Excused> excused;
  const auto detail = [&](double stop_x) {
    std::ostringstream os;
    os << "ego in the side lane without a gap can no longer halt before its end at x = " << s.road.side_lane_end_x_m
       << " m (front would stop at x = " << stop_x << " m)";
    return os.str();
  };
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const ObservedState& e = ego_of(steps[i]);
    if (e.y_m >= boundary_y || ctx.row.ego_holds_at(steps[i].time_s)) continue;
    const double v = std::max(speed_of(e), 0.0);
    const double stop_x = e.x_m + size_of(s, 0).length_m / 2.0 + v * v / (2.0 * limits_of(s, 0).brake_max_mps2);
    const double m = s.road.side_lane_end_x_m - stop_x;
    if (!(m < 0.0)) {
      relied_on.clear();
      breach = 0;
      looked_back = false;
    } else if (std::vector<std::size_t> gaps = def1_feasible_gap_vehicles(s, i, ctx.params.merge_duration_s);
               !gaps.empty()) {
      relied_on = std::move(gaps);
      breach = 0;
      unscanned = i;
      continue;
    } else {
      // The halt ability lost within the response time of the last gap: the ego could not have
      // answered that gap's loss, and went on toward it as if unable to halt.
      if (relied_on.empty() && !looked_back)
        if (std::optional<GapsAt> last = last_gap_within_response(ctx, i)) {
          relied_on = std::move(last->vehicles);
          unscanned = last->step;
        }
      looked_back = true;
      if (breach == 0) breach = breach_among(ctx, relied_on, unscanned, i).value_or(0);
      unscanned = i + 1;
      if (breach != 0) {
        excused.push_back({i, m, stop_x, breach});
        continue;
      }
    }
    if (acc.record(i, steps[i].time_s, m, Party::ego(), s.road.side_lane_end_x_m, stop_x)) acc.set_detail(detail(stop_x));
  }
  for (const Excused& x : excused) {
    const Party party = party_of(s, x.vehicle);
    if (acc.record(x.step, steps[x.step].time_s, x.margin_m, party, s.road.side_lane_end_x_m, x.stop_x_m))
      acc.set_detail(detail(x.stop_x_m) + "; the gaps it went on toward were lost while " + party_name(party) +
                     " was beyond its declared limits");
  }
  return acc.finish();
}

}  // namespace mg
