#include "rules/sigmoid_bounds_monitor.h"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include "core/rss.h"
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

// Where a Def. 2 partner (vehicle k) is `dt` after the ego obtained the right of way from the
// exchange `x` had it followed the profile it accepted: from its speed then linearly to v_o* by
// t_r + rho_c (ineq. (3) and (4) count on its mean speed over rho_c), then v_o* (capped by the
// speed limit for 2.2). Returns {x, v}.
std::pair<double, double> accepted_profile(const MonitorContext& ctx, std::size_t k, const CoopExchange& x,
                                           double decision_time_s, double dt) {
  const ObservedTrace& s = ctx.trace;
  double v_star = x.request->target_speed_mps;
  if (x.request->coop_case == CoopCase::kEgoBehind) v_star = std::min(v_star, s.road.speed_limit_mps);
  ObservedState at_dec = state_of(s.steps[step_at(s, decision_time_s)], k);
  const double ramp_s = x.request_time_s + ctx.params.comm_threshold_s - decision_time_s;
  if (ramp_s <= 0.0) {
    at_dec.vx_mps = v_star;
    return def1_predicted(at_dec, 0.0, 0.0, dt);
  }
  return def1_predicted(at_dec, (v_star - speed_of(at_dec)) / ramp_s, ramp_s, dt);
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
  for (const CoopExchange& x : coop_exchanges(ctx.trace)) {
    if (x.request->to_id != id || x.accept_time_s < 0.0 || x.accept_time_s > time_s) continue;
    const double v_star = x.request->target_speed_mps;
    const auto off = [&](std::size_t i) {
      const double v = speed_of(state_of(steps[i], k));
      return x.request->coop_case == CoopCase::kEgoAhead ? v > v_star + tol : v < v_star - tol;
    };
    const std::size_t last = step_at(ctx.trace, time_s);
    if (off(last)) return party_of(ctx.trace, k);
    for (std::size_t i = step_at(ctx.trace, x.request_time_s + yield_after_s); i < last; ++i)
      if (off(i)) return party_of(ctx.trace, k);
  }
  return Party::nobody();
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
    const ObservedStep& st = steps[i];
    const ObservedState& ego = ego_of(st);
    // Follower and leader in the target (rightmost main) lane at the midpoint.
    const GapIndices around = gap_around_ego(s, i);
    const std::size_t follower = around.follower < 1 ? 0 : static_cast<std::size_t>(around.follower);
    const std::size_t leader = around.leader < 1 ? 0 : static_cast<std::size_t>(around.leader);
    const double T = s.params.rss.response_time_s;
    const double ve = std::max(speed_of(ego), 0.0);
    const MergeAttempt* dec = attempt_with_midpoint(ctx.attempts, e.time_s);
    const bool def1 = dec != nullptr && dec->basis == RowBasis::kDef1;
    const bool def2 = dec != nullptr && dec->basis == RowBasis::kDef2;
    const double dec_time_s = def1 || def2 ? dec->decision_time_s : e.time_s;
    const ObservedStep& at_dec = steps[step_at(ctx.trace, dec_time_s)];
    const double since_dec_s = e.time_s - dec_time_s;
    const double rho_s = def1 ? dec->def1.rho_s : ctx.params.merge_duration_s;
    // The v_e* the prediction takes: Definition 1's reading, or the ego's speed when a Definition 2
    // acceptance gave it the right of way.
    const double ve_star = def1 ? dec->def1.ve_star_mps : speed_of(ego_of(at_dec));
    // Which gap vehicles are predicted: both in a Def. 1 merge; in a Def. 2 merge the one that is
    // not the partner as Definition 1 does (Definition 2 leaves it to ineq. (1) or (2)), and the
    // partner on the profile it accepted (ineq. (3)/(4): to v_o* by t_r + rho_c, then v_o*).
    const auto partner_prediction = [&](std::size_t k) -> std::optional<std::pair<double, double>> {
      if (!def2 || s.vehicles[k].id != dec->exchange->request->to_id) return std::nullopt;
      return accepted_profile(ctx, k, *dec->exchange, dec_time_s, since_dec_s);
    };
    // Margins against the real positions, and against the ones Definition 1 predicted at the
    // decision (the follower accelerating at a_accel^max until rho/2, then holding its speed; the
    // leader holding its speed).
    const double inf = std::numeric_limits<double>::infinity();
    double m_follower = inf, m_follower_pred = -inf, m_leader = inf, m_leader_pred = -inf;
    // An ego braking as the rear vehicle of an RSS-dangerous pair at the midpoint (its proper
    // response to a vehicle ahead) is slower than planned, which grows D_lon to its follower; the
    // predicted margin takes the planned speed v_e* then, so that response does not count against
    // the P_c bound (the follower's own response is rss_longitudinal's).
    const double ve_pred = (def1 || def2) && ego_rear_in_rss_danger(ctx, i) ? std::max(ve, ve_star) : ve;
    if (follower > 0) {
      const Limits& lf = limits_of(s, follower);
      const auto margin = [&](double x_f, double v_f, double v_e) {
        return ego.x_m - x_f -
               rss_longitudinal_m({std::max(v_f, 0.0), v_e, size_of(s, follower).length_m, size_of(s, 0).length_m, T,
                                   lf.accel_max_mps2, lf.brake_min_mps2, limits_of(s, 0).brake_max_mps2});
      };
      const ObservedState& f = state_of(st, follower);
      m_follower = margin(f.x_m, speed_of(f), ve);
      if (const auto p = partner_prediction(follower)) {
        m_follower_pred = margin(p->first, p->second, ve_pred);
      } else if (def1 || def2) {
        const auto [x, v] =
            def1_predicted(state_of(at_dec, follower), lf.accel_max_mps2, 0.5 * rho_s, since_dec_s);
        m_follower_pred = margin(x, v, ve_pred);
      }
    }
    if (leader > 0) {
      const auto margin = [&](double x_l, double v_l) {
        return x_l - ego.x_m -
               rss_longitudinal_m({ve, std::max(v_l, 0.0), size_of(s, 0).length_m, size_of(s, leader).length_m, T,
                                   limits_of(s, 0).accel_max_mps2, limits_of(s, 0).brake_min_mps2,
                                   limits_of(s, leader).brake_max_mps2});
      };
      const ObservedState& l = state_of(st, leader);
      m_leader = margin(l.x_m, speed_of(l));
      if (const auto p = partner_prediction(leader)) {
        m_leader_pred = margin(p->first, p->second);
      } else if (def1 || def2) {
        const auto [x, v] = def1_predicted(state_of(at_dec, leader), 0.0, 0.0, since_dec_s);
        m_leader_pred = margin(x, v);
      }
    }
    if (follower == 0 && leader == 0) continue;
    // A gap vehicle that broke its declared limit (or reneged on an accepted v_o*) is liable for
    // the real margin. Otherwise the ego gets the benefit of the doubt: each vehicle is judged at
    // the better of its real and its predicted position, so a leader that slowed within its b_max
    // or a follower that kept accelerating after rho/2 (both legal, neither what Definition 1
    // assumes) leaves the pair to the RSS rules (docs/rules.md).
    const bool leader_worse = m_leader < m_follower;
    const std::size_t worst = leader_worse ? leader : follower;
    double m = std::min(m_follower, m_leader);
    Party liable = Party::ego();
    if (m < 0.0) {
      const double from_s = def1 || def2 ? dec_time_s : e.time_s - ctx.params.merge_duration_s / 2.0;
      Party breaker = limit_breaker(ctx, follower, leader, from_s, e.time_s);
      // The decision's follower may have raced past the ego beyond its a_accel^max and be the
      // leader at the midpoint: its breach still explains the margin.
      if (breaker == Party::nobody() && def1 && dec->gap.follower > 0)
        breaker = limit_breaker(ctx, static_cast<std::size_t>(dec->gap.follower), 0, from_s, e.time_s);
      // A vehicle that was on the other side of the ego at some step since the decision owes both
      // of its limits: a leader that braked beyond its b_max until it fell back level with the ego
      // explains the margin as much as a follower that raced past beyond its a_accel^max.
      if (breaker == Party::nobody() && worst > 0 && changed_side(ctx, worst, from_s, i))
        breaker = limit_breaker(ctx, worst, worst, from_s, e.time_s);
      if (breaker == Party::nobody() && worst > 0) breaker = reneging_responder(ctx, worst, e.time_s);
      if (breaker != Party::nobody())
        liable = breaker;
      else
        m = std::min(std::max(m_follower, m_follower_pred), std::max(m_leader, m_leader_pred));
    }
    const double required = leader_worse ? ego.x_m + m : ego.x_m - m;  // the P_c bound
    if (acc.record(i, e.time_s, m, liable, required, ego.x_m)) {
      std::ostringstream os;
      os << "at the merge midpoint (t = " << e.time_s << " s, X = " << ego.x_m << " m) the ego was " << -m
         << " m inside the safe distance of " << party_name(party_of(s, worst));
      if (liable != Party::ego()) os << ", after " << party_name(liable) << " broke its declared limit or its accepted v_o*";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
