#include "rules/definition2_monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mg {

double merge_midpoint_after(const MergePhases& phases, double time_s) {
  const std::optional<MergePhaseEvent> e = phases.first(MergePhaseKind::kMidpoint, time_s);
  return e ? e->time_s : std::numeric_limits<double>::infinity();
}

namespace {

// Def. 2.1B / 2.2B: the responder of an accepted request changes speed toward v_o* at most at
// its b_max (2.1: braking harder than b_min is a legal RSS response, and b_min only bounds what
// the ego may ask, spec §5) or a_acc (2.2), and has reached v_o* once rho_c (+T) has passed.
MonitorOutput monitor_responder(const MonitorContext& ctx, CoopCase which) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  const bool ahead = which == CoopCase::kEgoAhead;
  MarginAccumulator acc(ahead ? "def2_1b_responder" : "def2_2b_responder", steps.size());
  const double rho_c = ctx.params.comm_threshold_s;
  const double tol = ctx.params.speed_tolerance_mps;
  for (const CoopExchange& x : ctx.exchanges) {
    // A request without v_o* asks for no speed: it binds no responder (def2_request_sound fails
    // the ego for it, and its acceptance grants nothing).
    if (x.request->coop_case != which || x.accept_time_s < 0.0 || steps.empty() || !x.complete()) continue;
    const Party partner = Party::from_vehicle_id(x.request->to_id);
    const int k = index_of_party(s, partner);
    if (k < 1) continue;
    const Limits& lim = limits_of(s, k);
    double v_star = x.request->target_speed_mps;
    if (!ahead) v_star = std::min(v_star, s.road.speed_limit_mps);
    const std::size_t first = step_at(ctx.trace, x.accept_time_s);
    const double v0 = speed_of(state_of(steps[first], k));
    const double deadline = x.sent_time_s + rho_c + s.params.rss.response_time_s;
    const double end = std::min(merge_midpoint_after(ctx.phases, x.accept_time_s),
                                x.sent_time_s + rho_c + ctx.params.merge_duration_s);
    bool reached = false;
    for (std::size_t i = first; i < steps.size() && steps[i].time_s <= end + kTieS; ++i) {
      const double t = steps[i].time_s;
      const double v = speed_of(state_of(steps[i], k));
      reached = reached || (ahead ? v <= v_star + tol : v >= v_star - tol);
      // Rate bound: not below v0 - b_max (t - t_a) (2.1B), not above v0 + a_acc (t - t_a) (2.2B).
      double m = std::numeric_limits<double>::infinity();
      double required = v_star;
      if (!reached) {
        m = ahead ? v - (v0 - lim.brake_max_mps2 * (t - x.accept_time_s)) + tol
                  : (v0 + lim.accel_max_mps2 * (t - x.accept_time_s)) + tol - v;
        required = ahead ? v0 - lim.brake_max_mps2 * (t - x.accept_time_s) : v0 + lim.accel_max_mps2 * (t - x.accept_time_s);
      }
      if (t >= deadline - kTieS) {
        const double yield = ahead ? v_star + ctx.params.yield_speed_tolerance_mps - v
                                   : v - (v_star - ctx.params.yield_speed_tolerance_mps);
        if (yield < m) {
          m = yield;
          required = v_star;
        }
      }
      if (!std::isfinite(m)) continue;
      if (acc.record(i, t, m, partner, required, v)) {
        std::ostringstream os;
        os << party_name(partner) << " accepted the Def. 2." << (ahead ? "1" : "2") << " request of t = "
           << x.sent_time_s << " s (v_o* = " << v_star << " m/s) but drove at " << v << " m/s at t = " << t
           << " s (" << (t >= deadline - kTieS && m < 0.0 && (ahead ? v > v_star : v < v_star) ? "did not yield"
                         : ahead ? "braked harder than b_max" : "accelerated harder than a_acc")
           << ")";
        acc.set_detail(os.str());
      }
    }
  }
  return acc.finish();
}

}  // namespace

// Def. 2.1A: the request carries P_c ahead of the ego and D*_lon covering at least contact.
MonitorOutput monitor_def2_1a_request(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  MarginAccumulator acc("def2_1a_request", ctx.trace.steps.size());
  if (ctx.trace.steps.empty()) return acc.finish();
  for (const CoopExchange& x : ctx.exchanges) {
    const V2vMessage& m = *x.request;
    if (m.coop_case != CoopCase::kEgoAhead) continue;
    const std::size_t i = step_at(ctx.trace, x.sent_time_s);
    const int k = s.index_of(m.to_id);
    const double contact = (size_of(s, 0).length_m + (k > 0 ? size_of(s, static_cast<std::size_t>(k)).length_m : 0.0)) / 2.0;
    const double pc_ahead = std::isfinite(m.pc_m) ? m.pc_m - ego_of(ctx.trace.steps[i]).x_m : -1.0;
    const double d_star = std::isfinite(m.d_lon_star_m) ? m.d_lon_star_m - contact : -1.0;
    const double margin = std::min(pc_ahead, d_star);
    if (acc.record(i, x.sent_time_s, margin, Party::ego(), contact, m.d_lon_star_m)) {
      std::ostringstream os;
      os << "request to " << party_name(Party::from_vehicle_id(m.to_id)) << " at t = " << x.sent_time_s << " s carries P_c = " << m.pc_m
         << " m (ego at x = " << ego_of(ctx.trace.steps[i]).x_m << " m) and D*_lon = " << m.d_lon_star_m << " m";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

MonitorOutput monitor_def2_1b_responder(const MonitorContext& ctx) { return monitor_responder(ctx, CoopCase::kEgoAhead); }
MonitorOutput monitor_def2_2b_responder(const MonitorContext& ctx) { return monitor_responder(ctx, CoopCase::kEgoBehind); }

double def2_2a_window_end_s(const MonitorContext& ctx, const CoopExchange& x) {
  const double rho_c = ctx.params.comm_threshold_s;
  double end = x.sent_time_s + rho_c;
  for (const ChannelEvent& e : ctx.trace.channel) {
    if (e.time_s > end + kTieS) break;
    if (e.kind == ChannelEventKind::kDelivered && e.message.type == MessageType::kRefuse &&
        e.message.from_id == x.request->to_id && Party::from_vehicle_id(e.message.to_id).is_ego() && e.time_s >= x.sent_time_s) {
      end = e.time_s;
      break;
    }
  }
  for (std::size_t i = step_at(ctx.trace, x.sent_time_s); i < ctx.trace.steps.size(); ++i) {
    if (ctx.trace.steps[i].time_s > end + kTieS) break;
    if (ego_rear_in_rss_danger(ctx, i)) return ctx.trace.steps[i].time_s;
  }
  return end;
}

// Def. 2.2A: after its request the ego brakes at most b_min during rho_c (ineq. (4) counts on it),
// unless the partner refused or an RSS danger with the ego behind came first.
MonitorOutput monitor_def2_2a_ego_brake(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  const auto& steps = ctx.trace.steps;
  MarginAccumulator acc("def2_2a_ego_brake", steps.size());
  const double b_min = limits_of(s, 0).brake_min_mps2;
  for (const CoopExchange& x : ctx.exchanges) {
    if (x.request->coop_case != CoopCase::kEgoBehind || steps.empty()) continue;
    const std::size_t first = step_at(ctx.trace, x.sent_time_s);
    const double v0 = speed_of(ego_of(steps[first]));
    const double end = def2_2a_window_end_s(ctx, x) + kTieS;
    for (std::size_t i = first; i < steps.size() && steps[i].time_s <= end; ++i) {
      const double floor_v = v0 - b_min * (steps[i].time_s - x.sent_time_s);
      const double v = speed_of(ego_of(steps[i]));
      if (acc.record(i, steps[i].time_s, v - floor_v + ctx.params.speed_tolerance_mps, Party::ego(), floor_v, v)) {
        std::ostringstream os;
        os << "after its Def. 2.2 request at t = " << x.sent_time_s << " s the ego braked harder than b_min = "
           << b_min << " m/s2 (speed " << v << " m/s < " << floor_v << " m/s)";
        acc.set_detail(os.str());
      }
    }
  }
  return acc.finish();
}

// Def. 2.3: a cooperative merge needs the partner's acceptance, delivered within rho_c of t_r, the
// first request of its series (rules/coop_exchange.h). An attempt that entered the main lane
// without the right of way on an acceptance that came later breaks it (one with no acceptance at
// all is Definition 1's: the def1 gap rules; one that stayed in the side lane took nobody's room,
// as for those rules).
MonitorOutput monitor_def2_3_fallback(const MonitorContext& ctx) {
  MarginAccumulator acc("def2_3_fallback", ctx.trace.steps.size());
  const double rho_c = ctx.params.comm_threshold_s;
  for (const MergeAttempt& a : ctx.attempts.attempts) {
    if (!a.exchange || a.fault == AcceptanceFault::kUntruthful) continue;
    if (a.basis != RowBasis::kDef2 && !a.entry_step) continue;
    const CoopExchange& x = *a.exchange;
    double m = x.request_time_s + rho_c - x.accept_delivered_time_s;
    if (m < 0.0 && m >= -kTieS) m = 0.0;  // the window is closed: delivered at t_r + rho_c is in time
    const double at_s = a.basis == RowBasis::kDef2 ? a.decision_time_s : a.start_time_s;
    if (acc.record(step_at(ctx.trace, at_s), at_s, m, Party::ego(), x.request_time_s + rho_c, x.accept_delivered_time_s)) {
      std::ostringstream os;
      os << "ego entered the main lane in a merge with " << party_name(Party::from_vehicle_id(x.request->to_id)) << " started at t = "
         << a.start_time_s << " s on an acceptance delivered at t = " << x.accept_delivered_time_s
         << " s, after rho_c from its first request of t = " << x.request_time_s << " s";
      if (x.sent_time_s > x.request_time_s) os << " (re-sent at t = " << x.sent_time_s << " s)";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
