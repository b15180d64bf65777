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

bool is_merge(DecisionMode m) { return m == DecisionMode::kDef1Merge || m == DecisionMode::kDef2Merge; }

// The decision that started the merge in force at time_s, or nullptr.
const Decision* merge_decision_before(const Trace& t, double time_s) {
  const Decision* start = nullptr;
  bool in_merge = false;
  for (const Decision& d : t.decisions) {
    if (d.time_s > time_s) break;
    if (is_merge(d.mode)) {
      if (!in_merge) start = &d;
      in_merge = true;
    } else if (d.mode != DecisionMode::kProperResponse) {
      in_merge = false;
    }
  }
  return start;
}

// Where Definition 1 predicted a gap vehicle at `dt` after the decision, from its state then: the
// follower accelerating at a_accel^max until rho/2 and then holding its speed (Def. 1.1), the
// leader holding its speed (Def. 1.2). Returns {x, v}.
std::pair<double, double> def1_predicted(const VehicleState& at_decision, double accel_mps2, double accel_for_s,
                                         double dt) {
  const double v0 = std::max(speed_of(at_decision), 0.0);
  const double tau = std::min(dt, accel_for_s);
  return {at_decision.x_m + v0 * tau + 0.5 * accel_mps2 * tau * tau + (v0 + accel_mps2 * tau) * (dt - tau),
          v0 + accel_mps2 * tau};
}

// Where a Def. 2 partner (vehicle k) is `dt` after the merge decision `dec` had it followed the
// profile it accepted: from its speed at the decision linearly to v_o* by t_r + rho_c (ineq. (3)
// and (4) count on its mean speed over rho_c), then v_o* (capped by the speed limit for 2.2).
// Returns {x, v}, or nullopt when no accepted request to k precedes the decision.
std::optional<std::pair<double, double>> accepted_profile(const MonitorContext& ctx, std::size_t k,
                                                          const Decision& dec, double dt) {
  const Scenario& s = ctx.scenario;
  const std::vector<CoopExchange> exchanges = coop_exchanges(ctx.trace);
  const CoopExchange* accepted = nullptr;
  for (const CoopExchange& x : exchanges)
    if (x.request->to_id == party_of(s, k) && x.accept_time_s >= 0.0 && x.accept_time_s <= dec.time_s + 1e-9)
      accepted = &x;
  if (accepted == nullptr) return std::nullopt;
  double v_star = accepted->request->target_speed_mps;
  if (accepted->request->coop_case == CoopCase::kEgoBehind) v_star = std::min(v_star, s.road.speed_limit_mps);
  VehicleState at_dec = state_of(ctx.trace.steps[step_at(ctx.trace, dec.time_s)], k);
  const double ramp_s = accepted->request_time_s + s.params.planner.comm_threshold_s - dec.time_s;
  if (ramp_s <= 0.0) {
    at_dec.vx_mps = v_star;
    at_dec.vy_mps = 0.0;
    at_dec.yaw_rad = 0.0;
    return def1_predicted(at_dec, 0.0, 0.0, dt);
  }
  return def1_predicted(at_dec, (v_star - speed_of(at_dec)) / ramp_s, ramp_s, dt);
}

// The main-lane vehicle that broke a declared limit in [from, to] (a follower accelerating
// beyond a_accel^max, a leader braking beyond a_brake^max), or kNobody.
int limit_breaker(const MonitorContext& ctx, std::size_t follower, std::size_t leader, double from, double to) {
  const double tol = ctx.params.accel_tolerance_mps2;
  for (std::size_t i = step_at(ctx.trace, from); i < ctx.trace.steps.size() && ctx.trace.steps[i].time_s <= to; ++i) {
    const TraceStep& st = ctx.trace.steps[i];
    if (follower > 0 && state_of(st, follower).accel_mps2 > limits_of(ctx.scenario, follower).accel_max_mps2 + tol)
      return party_of(ctx.scenario, follower);
    if (leader > 0 && state_of(st, leader).accel_mps2 < -(limits_of(ctx.scenario, leader).brake_max_mps2 + tol))
      return party_of(ctx.scenario, leader);
  }
  return kNobody;
}

// Whether vehicle k was on the other side of the ego (ahead or not) at some step in [from_s,
// step i) than at step i.
bool changed_side(const MonitorContext& ctx, std::size_t k, double from_s, std::size_t i) {
  const auto ahead = [&](std::size_t j) { return state_of(ctx.trace.steps[j], k).x_m > ctx.trace.steps[j].ego.x_m; };
  const bool ahead_now = ahead(i);
  for (std::size_t j = step_at(ctx.trace, from_s); j < i; ++j)
    if (ahead(j) != ahead_now) return true;
  return false;
}

// The responder k if it accepted a Def. 2 request before time_s and was farther than the yield
// tolerance from the v_o* it accepted at time_s, or at any step from the yield deadline t_r +
// rho_c + T to time_s (Def. 2.1B / 2.2B: a responder that did not yield in time and slowed only
// later still explains the margin), else kNobody.
int reneging_responder(const MonitorContext& ctx, std::size_t k, double time_s) {
  const int id = party_of(ctx.scenario, k);
  const auto& steps = ctx.trace.steps;
  const double tol = ctx.params.yield_speed_tolerance_mps;
  const double yield_after_s = ctx.scenario.params.planner.comm_threshold_s + ctx.scenario.params.rss.response_time_s;
  for (const CoopExchange& x : coop_exchanges(ctx.trace)) {
    if (x.request->to_id != id || x.accept_time_s < 0.0 || x.accept_time_s > time_s) continue;
    const double v_star = x.request->target_speed_mps;
    const auto off = [&](std::size_t i) {
      const double v = speed_of(state_of(steps[i], k));
      return x.request->coop_case == CoopCase::kEgoAhead ? v > v_star + tol : v < v_star - tol;
    };
    const std::size_t last = step_at(ctx.trace, time_s);
    if (off(last)) return id;
    for (std::size_t i = step_at(ctx.trace, x.request_time_s + yield_after_s); i < last; ++i)
      if (off(i)) return id;
  }
  return kNobody;
}

}  // namespace

MonitorOutput monitor_sigmoid_pc_bounds(const MonitorContext& ctx) {
  const Scenario& s = ctx.scenario;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("sigmoid_pc_bounds", steps.size());
  if (steps.empty()) return acc.finish();
  for (const Decision& d : ctx.trace.decisions) {
    if (!is_merge(d.mode) || !std::isfinite(d.pc_m) || !std::isfinite(d.pc_min_m) || !std::isfinite(d.pc_max_m)) continue;
    const double m = std::min(d.pc_m - d.pc_min_m, d.pc_max_m - d.pc_m);
    if (acc.record(step_at(ctx.trace, d.time_s), d.time_s, m, kEgoId, d.pc_min_m, d.pc_m)) {
      std::ostringstream os;
      os << "decision at t = " << d.time_s << " s chose P_c = " << d.pc_m << " m outside its bounds [" << d.pc_min_m
         << ", " << d.pc_max_m << "] m";
      acc.set_detail(os.str());
    }
  }
  for (const MergePhaseEvent& e : ctx.phases.events) {
    if (e.kind != MergePhaseKind::kMidpoint) continue;
    const std::size_t i = e.step;
    const TraceStep& st = steps[i];
    // Follower and leader in the target (rightmost main) lane at the midpoint.
    std::size_t follower = 0, leader = 0;
    for (std::size_t k = 1; k <= s.vehicles.size(); ++k) {
      if (s.vehicles[k - 1].lane != 0) continue;
      const double x = state_of(st, k).x_m;
      if (x <= st.ego.x_m && (follower == 0 || x > state_of(st, follower).x_m)) follower = k;
      if (x > st.ego.x_m && (leader == 0 || x < state_of(st, leader).x_m)) leader = k;
    }
    const double T = s.params.rss.response_time_s;
    const double ve = std::max(speed_of(st.ego), 0.0);
    const Decision* dec = merge_decision_before(ctx.trace, e.time_s);
    const bool def1 = dec != nullptr && dec->mode == DecisionMode::kDef1Merge;
    const bool def2 = dec != nullptr && dec->mode == DecisionMode::kDef2Merge;
    const TraceStep& at_dec = steps[step_at(ctx.trace, def1 || def2 ? dec->time_s : e.time_s)];
    const double since_dec_s = def1 || def2 ? e.time_s - dec->time_s : 0.0;
    // Which gap vehicles are predicted: both in a Def. 1 merge; in a Def. 2 merge the one that is
    // not the partner as Definition 1 does (the planner holds it to ineq. (1) or (2)), and the
    // partner on the profile it accepted (ineq. (3)/(4): to v_o* by t_r + rho_c, then v_o*).
    const auto partner_prediction = [&](std::size_t k) -> std::optional<std::pair<double, double>> {
      if (!def2 || party_of(s, k) != dec->coop_partner_id) return std::nullopt;
      return accepted_profile(ctx, k, *dec, since_dec_s);
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
    const double ve_pred = (def1 || def2) && ego_rear_in_rss_danger(ctx, i) && std::isfinite(dec->ve_star_mps)
                               ? std::max(ve, dec->ve_star_mps)
                               : ve;
    if (follower > 0) {
      const Limits& lf = limits_of(s, follower);
      const auto margin = [&](double x_f, double v_f, double v_e) {
        return st.ego.x_m - x_f -
               rss_longitudinal_m({std::max(v_f, 0.0), v_e, size_of(s, follower).length_m, s.ego.size.length_m, T,
                                   lf.accel_max_mps2, lf.brake_min_mps2, s.ego.limits.brake_max_mps2});
      };
      const VehicleState& f = state_of(st, follower);
      m_follower = margin(f.x_m, speed_of(f), ve);
      if (const auto p = partner_prediction(follower)) {
        m_follower_pred = margin(p->first, p->second, ve_pred);
      } else if (def1 || def2) {
        const auto [x, v] =
            def1_predicted(state_of(at_dec, follower), lf.accel_max_mps2, 0.5 * dec->merge_duration_s, since_dec_s);
        m_follower_pred = margin(x, v, ve_pred);
      }
    }
    if (leader > 0) {
      const auto margin = [&](double x_l, double v_l) {
        return x_l - st.ego.x_m -
               rss_longitudinal_m({ve, std::max(v_l, 0.0), s.ego.size.length_m, size_of(s, leader).length_m, T,
                                   s.ego.limits.accel_max_mps2, s.ego.limits.brake_min_mps2,
                                   limits_of(s, leader).brake_max_mps2});
      };
      const VehicleState& l = state_of(st, leader);
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
    int liable = kEgoId;
    if (m < 0.0) {
      const double from_s = dec ? dec->time_s : e.time_s - s.params.planner.merge_duration_s / 2.0;
      int breaker = limit_breaker(ctx, follower, leader, from_s, e.time_s);
      // The decision's follower may have raced past the ego beyond its a_accel^max and be the
      // leader at the midpoint: its breach still explains the margin.
      if (breaker == kNobody && def1 && dec->gap && dec->gap->follower_id >= 0)
        if (const int k = index_of_party(s, dec->gap->follower_id); k > 0)
          breaker = limit_breaker(ctx, static_cast<std::size_t>(k), 0, from_s, e.time_s);
      // A vehicle that was on the other side of the ego at some step since the decision owes both
      // of its limits: a leader that braked beyond its b_max until it fell back level with the ego
      // explains the margin as much as a follower that raced past beyond its a_accel^max.
      if (breaker == kNobody && worst > 0 && changed_side(ctx, worst, from_s, i))
        breaker = limit_breaker(ctx, worst, worst, from_s, e.time_s);
      if (breaker == kNobody && worst > 0) breaker = reneging_responder(ctx, worst, e.time_s);
      if (breaker != kNobody)
        liable = breaker;
      else
        m = std::min(std::max(m_follower, m_follower_pred), std::max(m_leader, m_leader_pred));
    }
    const double required = leader_worse ? st.ego.x_m + m : st.ego.x_m - m;  // the P_c bound
    if (acc.record(i, e.time_s, m, liable, required, st.ego.x_m)) {
      std::ostringstream os;
      os << "at the merge midpoint (t = " << e.time_s << " s, X = " << st.ego.x_m << " m) the ego was " << -m
         << " m inside the safe distance of " << party_name(party_of(s, worst));
      if (liable != kEgoId) os << ", after " << party_name(liable) << " broke its declared limit or its accepted v_o*";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
