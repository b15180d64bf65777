#include "rules/sigmoid_bounds_monitor.h"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include "core/rss.h"
#include "rules/definition2_inequalities.h"
#include "rules/definition2_monitor.h"

namespace mg {
namespace {

// The observed merge attempt whose midpoint is at time_s, or nullptr.
const MergeAttempt* attempt_with_midpoint(const MergeAttempts& attempts, double time_s) {
  for (const MergeAttempt& a : attempts.attempts)
    if (a.midpoint_time_s && *a.midpoint_time_s == time_s) return &a;
  return nullptr;
}

// Where Definition 1 predicted a gap vehicle at `dt` after the decision, from its state then: the
// follower accelerating at a_accel^max until rho/2 and then holding its speed (Def. 1.1), the
// leader holding its speed (Def. 1.2). Returns {x, v}.
std::pair<double, double> def1_predicted(const ObservedState& at_decision, double accel_mps2, double accel_for_s,
                                         double dt) {
  const double v0 = std::max(speed_of(at_decision), 0.0);
  const double tau = std::min(dt, accel_for_s);
  return {at_decision.x_m + v0 * tau + 0.5 * accel_mps2 * tau * tau + (v0 + accel_mps2 * tau) * (dt - tau),
          v0 + accel_mps2 * tau};
}

// Where what covered a vehicle of the gap entered lets it be at the midpoint t_mid, as {x, v}; the
// ego is judged at the better of that and the real position (rules/merge_attempts.h covers):
//   - its own acceptance (Def. 2): the profile ineq. (3)/(4) count on (accepted_profile_bound:
//     to v_o* by t_r + rho_c); after its duties end, nothing (real position). A partner nearer
//     the ego than that profile, when the profile would have left the margin, answers for the
//     real one (explaining_breach), within def2_positions' allowances or not: the ego's plan
//     held against what the partner accepted;
//   - Definition 1 for the pair at the request of the other vehicle's acceptance: from its state
//     at the request, a follower at a_accel^max for rho_c + rho_m/2 (ineq. (1.1) over 2 rho_c +
//     rho_m), a leader at constant speed;
//   - the Definition 1 reading: from its state at the reading, a follower at a_accel^max for rho/2
//     (to the observed midpoint, rules/merge_attempts.h), a leader at constant speed;
//   - nothing: no prediction.
std::optional<std::pair<double, double>> covered_state(const MonitorContext& ctx, const MergeAttempt& a,
                                                       const PairCover& c, bool follower, double t_mid) {
  const ObservedTrace& s = ctx.trace;
  const std::size_t k = static_cast<std::size_t>(c.vehicle);
  const double accel = follower ? limits_of(s, k).accel_max_mps2 : 0.0;
  switch (c.by) {
    case Cover::kNone: return std::nullopt;
    case Cover::kDef2: {
      const ProfileBound b = accepted_profile_bound(ctx, ctx.exchanges[*c.exchange], k, t_mid);
      if (!b.valid) return std::nullopt;
      return std::pair{b.profile_x_m, b.profile_v_mps};
    }
    case Cover::kDef2Pair: {
      const double t_r = ctx.exchanges[*c.exchange].sent_time_s;
      const double accel_for_s = ctx.params.comm_threshold_s + 0.5 * ctx.params.merge_duration_s;
      return def1_predicted(state_of(s.steps[step_at(s, t_r)], k), accel, accel_for_s, t_mid - t_r);
    }
    case Cover::kDef1:
    case Cover::kDef1Pair:
      return def1_predicted(state_of(s.steps[a.def1.step], k), accel, 0.5 * a.def1.rho_s, t_mid - a.def1.time_s);
  }
  return std::nullopt;
}

// The main-lane vehicle that broke a declared limit in [from, to] (a follower accelerating
// beyond a_accel^max, a leader braking beyond a_brake^max), or Party::nobody().
Party limit_breaker(const MonitorContext& ctx, std::size_t follower, std::size_t leader, double from, double to) {
  const double tol = ctx.params.accel_tolerance_mps2;
  for (std::size_t i = step_at(ctx.trace, from); i < ctx.trace.steps.size() && ctx.trace.steps[i].time_s <= to; ++i) {
    const ObservedStep& st = ctx.trace.steps[i];
    if (follower > 0 && state_of(st, follower).accel_mps2 > limits_of(ctx.trace, follower).accel_max_mps2 + tol)
      return party_of(ctx.trace, follower);
    if (leader > 0 && state_of(st, leader).accel_mps2 < -(limits_of(ctx.trace, leader).brake_max_mps2 + tol))
      return party_of(ctx.trace, leader);
  }
  return Party::nobody();
}

// Whether vehicle k was on the other side of the ego (ahead or not) at some step in [from_s,
// step i) than at step i.
bool changed_side(const MonitorContext& ctx, std::size_t k, double from_s, std::size_t i) {
  const auto ahead = [&](std::size_t j) { return state_of(ctx.trace.steps[j], k).x_m > ego_of(ctx.trace.steps[j]).x_m; };
  const bool ahead_now = ahead(i);
  for (std::size_t j = step_at(ctx.trace, from_s); j < i; ++j)
    if (ahead(j) != ahead_now) return true;
  return false;
}

// The responder k if it accepted a Def. 2 request before time_s and was farther than the yield
// tolerance from the v_o* it accepted at time_s, or at any step from the yield deadline t_r +
// rho_c + T to time_s (Def. 2.1B / 2.2B: a responder that did not yield in time and slowed only
// later still explains the margin), else Party::nobody().
Party reneging_responder(const MonitorContext& ctx, std::size_t k, double time_s) {
  const int id = ctx.trace.vehicles[k].id;
  const auto& steps = ctx.trace.steps;
  const double tol = ctx.params.yield_speed_tolerance_mps;
  const double yield_after_s = ctx.params.comm_threshold_s + ctx.trace.params.rss.response_time_s;
  for (const CoopExchange& x : ctx.exchanges) {
    if (!x.complete() || x.request->to_id != id || x.accept_time_s < 0.0 || x.accept_time_s > time_s) continue;
    const double v_star = x.request->target_speed_mps;
    const auto off = [&](std::size_t i) {
      const double v = speed_of(state_of(steps[i], k));
      return x.request->coop_case == CoopCase::kEgoAhead ? v > v_star + tol : v < v_star - tol;
    };
    const std::size_t last = step_at(ctx.trace, time_s);
    if (off(last)) return party_of(ctx.trace, k);
    for (std::size_t i = step_at(ctx.trace, x.sent_time_s + yield_after_s); i < last; ++i)
      if (off(i)) return party_of(ctx.trace, k);
  }
  return Party::nobody();
}

}  // namespace

namespace {

// The P_c bound's margin toward one side's vehicle at the midpoint: real, and predicted from what
// covered it (-inf when nothing did).
struct SideMargins {
  std::size_t k = 0;  // 0: open side
  double real_m = std::numeric_limits<double>::infinity();
  double predicted_m = -std::numeric_limits<double>::infinity();
  bool partner = false;  // covered by its own acceptance: predicted on the profile it accepted ...
  // ... and the margin there with the ego as it really was: what the partner's deviation from its
  // profile alone changed
  double profile_m = -std::numeric_limits<double>::infinity();
};

SideMargins side_margins(const MonitorContext& ctx, const MergeAttempt* a, std::size_t i, int vehicle, bool follower,
                         double ve_pred_mps) {
  const ObservedTrace& s = ctx.trace;
  SideMargins out;
  if (vehicle < 1) return out;
  out.k = static_cast<std::size_t>(vehicle);
  const ObservedState& ego = ego_of(s.steps[i]);
  const double T = s.params.rss.response_time_s, ve = std::max(speed_of(ego), 0.0);
  const auto margin = [&](double x_o, double v_o, double v_e) {
    const Limits& rear = follower ? limits_of(s, out.k) : limits_of(s, 0);
    const double d = rss_longitudinal_m({follower ? std::max(v_o, 0.0) : v_e, follower ? v_e : std::max(v_o, 0.0),
                                         size_of(s, follower ? out.k : 0).length_m, size_of(s, follower ? 0 : out.k).length_m,
                                         T, rear.accel_max_mps2, rear.brake_min_mps2,
                                         limits_of(s, follower ? 0 : out.k).brake_max_mps2});
    return follower ? ego.x_m - x_o - d : x_o - ego.x_m - d;
  };
  const ObservedState& o = state_of(s.steps[i], out.k);
  out.real_m = margin(o.x_m, speed_of(o), ve);
  const PairCover* c = a == nullptr ? nullptr : follower ? &a->follower : &a->leader;
  if (c != nullptr && c->vehicle == vehicle)
    if (const auto p = covered_state(ctx, *a, *c, follower, s.steps[i].time_s)) {
      out.predicted_m = margin(p->first, p->second, follower ? ve_pred_mps : ve);
      out.partner = c->by == Cover::kDef2;
      out.profile_m = margin(p->first, p->second, ve);
    }
  return out;
}

// Who broke a limit or an accepted profile that explains a negative margin at the midpoint, or
// nobody (then the ego).
Party explaining_breach(const MonitorContext& ctx, const MergeAttempt* a, const SideMargins& f, const SideMargins& l,
                      std::size_t i) {
  const double t_mid = ctx.trace.steps[i].time_s;
  const bool held = a != nullptr && a->basis != RowBasis::kNone;
  const double from_s = held ? a->decision_time_s : t_mid - ctx.params.merge_duration_s / 2.0;
  const std::size_t worst = l.real_m < f.real_m ? l.k : f.k;
  Party breaker = limit_breaker(ctx, f.k, l.k, from_s, t_mid);
  // The decision's follower may have raced past the ego beyond its a_accel^max and be the
  // leader at the midpoint: its breach still explains the margin.
  if (breaker.is_nobody() && held && a->basis == RowBasis::kDef1 && a->gap.follower > 0)
    breaker = limit_breaker(ctx, static_cast<std::size_t>(a->gap.follower), 0, from_s, t_mid);
  // A vehicle that was on the other side of the ego at some step since the decision owes both
  // of its limits: a leader that braked beyond its b_max until it fell back level with the ego
  // explains the margin as much as a follower that raced past beyond its a_accel^max.
  if (breaker.is_nobody() && worst > 0 && changed_side(ctx, worst, from_s, i))
    breaker = limit_breaker(ctx, worst, worst, from_s, t_mid);
  if (breaker.is_nobody() && worst > 0) breaker = reneging_responder(ctx, worst, t_mid);
  // A partner whose profile would have left the margin, nearer than that profile: its deviation
  // explains the shortfall, within def2_positions' tolerance or not (between the two the margin
  // was otherwise nobody's).
  const SideMargins& w = l.real_m < f.real_m ? l : f;
  if (breaker.is_nobody() && w.partner && w.profile_m >= 0.0) breaker = party_of(ctx.trace, w.k);
  return breaker;
}

}  // namespace

MonitorOutput monitor_sigmoid_pc_bounds(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("sigmoid_pc_bounds", steps.size());
  if (steps.empty()) return acc.finish();
  for (const MergePhaseEvent& e : ctx.phases.events) {
    if (e.kind != MergePhaseKind::kMidpoint) continue;
    const std::size_t i = e.step;
    const ObservedState& ego = ego_of(steps[i]);
    // Follower and leader in the target (rightmost main) lane at the midpoint: the gap entered.
    const GapIndices around = gap_around_ego(s, i);
    const MergeAttempt* dec = attempt_with_midpoint(ctx.attempts, e.time_s);
    // The v_e* the prediction takes: Definition 1's reading, or the ego's speed when a
    // Definition 2 acceptance gave it the right of way. An ego braking as the rear vehicle of an
    // RSS-dangerous pair at the midpoint (its proper response to a vehicle ahead) is slower than
    // planned, which grows D_lon to its follower; the predicted margin takes the planned speed
    // then, so that response does not count against the P_c bound (the follower's own response
    // is rss_longitudinal's).
    double ve_pred = std::max(speed_of(ego), 0.0);
    if (dec != nullptr && dec->basis != RowBasis::kNone && ego_rear_in_rss_danger(ctx, i)) {
      const double ve_star = dec->basis == RowBasis::kDef1 ? dec->def1.ve_star_mps
                                                            : speed_of(ego_of(steps[step_at(s, dec->decision_time_s)]));
      ve_pred = std::max(ve_pred, ve_star);
    }
    const SideMargins f = side_margins(ctx, dec, i, around.follower, true, ve_pred);
    const SideMargins l = side_margins(ctx, dec, i, around.leader, false, ve_pred);
    if (f.k == 0 && l.k == 0) continue;
    // A gap vehicle that broke its declared limit (or reneged on an accepted v_o*) is liable for
    // the real margin. Otherwise each covered vehicle is judged at the better of its real and
    // its predicted position (covered_state), so a leader that slowed within its b_max or a
    // follower that kept accelerating after rho/2 (both legal, neither what Definition 1
    // assumes) leaves the pair to the RSS rules (docs/rules.md); an uncovered one at its real
    // position.
    const bool leader_worse = l.real_m < f.real_m;
    double m = std::min(f.real_m, l.real_m);
    Party liable = Party::ego();
    if (m < 0.0) {
      const Party breaker = explaining_breach(ctx, dec, f, l, i);
      if (!breaker.is_nobody())
        liable = breaker;
      else
        m = std::min(std::max(f.real_m, f.predicted_m), std::max(l.real_m, l.predicted_m));
    }
    const double required = leader_worse ? ego.x_m + m : ego.x_m - m;  // the P_c bound
    if (acc.record(i, e.time_s, m, liable, required, ego.x_m)) {
      std::ostringstream os;
      os << "at the merge midpoint (t = " << e.time_s << " s, X = " << ego.x_m << " m) the ego was " << -m
         << " m inside the safe distance of " << party_name(party_of(s, leader_worse ? l.k : f.k));
      if (!liable.is_ego()) os << ", after " << party_name(liable) << " broke its declared limit or its accepted v_o*";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
