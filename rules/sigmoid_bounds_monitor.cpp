#include "rules/sigmoid_bounds_monitor.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/rss.h"
#include "rules/definition2_monitor.h"

namespace mg {
namespace {

bool is_merge(DecisionMode m) { return m == DecisionMode::kDef1Merge || m == DecisionMode::kDef2Merge; }

// Time of the decision that started the merge in force at time_s, or time_s - rho_m/2.
double decision_time_before(const Scenario& s, const Trace& t, double time_s) {
  double start = time_s - s.params.planner.merge_duration_s / 2.0;
  bool in_merge = false;
  for (const Decision& d : t.decisions) {
    if (d.time_s > time_s) break;
    if (is_merge(d.mode)) {
      if (!in_merge) start = d.time_s;
      in_merge = true;
    } else if (d.mode != DecisionMode::kProperResponse) {
      in_merge = false;
    }
  }
  return start;
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

// The responder k if it accepted a Def. 2 request before time_s and is, at time_s, still
// farther than the yield tolerance from the v_o* it accepted (Def. 2.1B / 2.2B), else kNobody.
int reneging_responder(const MonitorContext& ctx, std::size_t k, double time_s) {
  const int id = party_of(ctx.scenario, k);
  const double v = speed_of(state_of(ctx.trace.steps[step_at(ctx.trace, time_s)], k));
  for (const CoopExchange& x : coop_exchanges(ctx.trace)) {
    if (x.request->to_id != id || x.accept_time_s < 0.0 || x.accept_time_s > time_s) continue;
    const double v_star = x.request->target_speed_mps;
    const double tol = ctx.params.yield_speed_tolerance_mps;
    if (x.request->coop_case == CoopCase::kEgoAhead ? v > v_star + tol : v < v_star - tol) return id;
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
  for (const TraceEvent& e : ctx.trace.events) {
    if (e.kind != EventKind::kMergeMidpoint || e.vehicle_id != kEgoId) continue;
    const std::size_t i = step_at(ctx.trace, e.time_s);
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
    double m = std::numeric_limits<double>::infinity();
    double required = 0.0, actual = 0.0;
    std::size_t worst = 0;
    if (follower > 0) {
      const VehicleState& f = state_of(st, follower);
      const Limits& lf = limits_of(s, follower);
      const double d_lon = rss_longitudinal_m({std::max(speed_of(f), 0.0), ve, size_of(s, follower).length_m,
                                               s.ego.size.length_m, T, lf.accel_max_mps2, lf.brake_min_mps2,
                                               s.ego.limits.brake_max_mps2});
      m = st.ego.x_m - f.x_m - d_lon;
      required = f.x_m + d_lon;  // P_c lower bound
      actual = st.ego.x_m;
      worst = follower;
    }
    if (leader > 0) {
      const VehicleState& l = state_of(st, leader);
      const double d_lon = rss_longitudinal_m({ve, std::max(speed_of(l), 0.0), s.ego.size.length_m,
                                               size_of(s, leader).length_m, T, s.ego.limits.accel_max_mps2,
                                               s.ego.limits.brake_min_mps2, limits_of(s, leader).brake_max_mps2});
      if (l.x_m - st.ego.x_m - d_lon < m) {
        m = l.x_m - st.ego.x_m - d_lon;
        required = l.x_m - d_lon;  // P_c upper bound
        actual = st.ego.x_m;
        worst = leader;
      }
    }
    if (!std::isfinite(m)) continue;
    int liable = kEgoId;
    if (m < 0.0) {
      int breaker = limit_breaker(ctx, follower, leader, decision_time_before(s, ctx.trace, e.time_s), e.time_s);
      if (breaker == kNobody && worst > 0) breaker = reneging_responder(ctx, worst, e.time_s);
      if (breaker != kNobody) liable = breaker;
    }
    if (acc.record(i, e.time_s, m, liable, required, actual)) {
      std::ostringstream os;
      os << "at the merge midpoint (t = " << e.time_s << " s, X = " << st.ego.x_m << " m) the ego was " << -m
         << " m inside the safe distance of "
         << party_name(party_of(s, worst));
      if (liable != kEgoId) os << ", after " << party_name(liable) << " broke its declared limit or its accepted v_o*";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
