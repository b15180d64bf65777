#include "rules/definition2_inequalities.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "core/rss.h"
#include "rules/coop_exchange.h"
#include "rules/definition2_monitor.h"

namespace mg {

double ramp_distance_m(double v0_mps, double v_star_mps, double ramp_s, double tau_s) {
  if (ramp_s <= 0.0) return v_star_mps * tau_s;
  const double t = std::min(tau_s, ramp_s);
  const double v_t = v0_mps + (v_star_mps - v0_mps) * t / ramp_s;
  return 0.5 * (v0_mps + v_t) * t + v_star_mps * std::max(0.0, tau_s - ramp_s);
}

ProfileBound accepted_profile_bound(const MonitorContext& ctx, const CoopExchange& x, std::size_t k, double time_s) {
  return accepted_profile_bound(ctx.trace, ctx.params, x, k, time_s);
}

bool responder_broke_acceptance(const ObservedTrace& t, const RuleParams& p, const CoopExchange& x, std::size_t k,
                                double until_s) {
  if (x.accept_time_s < 0.0 || t.steps.empty()) return false;
  const bool ahead = x.request->coop_case == CoopCase::kEgoAhead;
  for (std::size_t i = step_at(t, x.accept_time_s); i < t.steps.size() && t.steps[i].time_s <= until_s + kTieS; ++i) {
    const ProfileBound b = accepted_profile_bound(t, p, x, k, t.steps[i].time_s);
    if (!b.valid) break;
    const double pos = state_of(t.steps[i], k).x_m;
    if (ahead ? pos > b.bound_x_m : pos < b.bound_x_m) return true;
  }
  return false;
}

ProfileBound accepted_profile_bound(const ObservedTrace& s, const RuleParams& p, const CoopExchange& x, std::size_t k,
                                    double time_s) {
  ProfileBound b;
  if (x.accept_time_s < 0.0 || !x.complete() || s.steps.empty() ||
      time_s > x.sent_time_s + p.comm_threshold_s + p.merge_duration_s + kTieS)
    return b;
  const bool ahead = x.request->coop_case == CoopCase::kEgoAhead;
  const double v_star = ahead ? x.request->target_speed_mps : std::min(x.request->target_speed_mps, s.road.speed_limit_mps);
  const ObservedState& at_accept = state_of(s.steps[step_at(s, x.accept_time_s)], k);
  const double v_a = std::max(0.0, speed_of(at_accept));
  const double tau = std::max(0.0, time_s - x.accept_time_s);
  const double tol_mps = p.yield_speed_tolerance_mps;
  const auto on_ramp = [&](double ramp_s) {
    return std::pair{at_accept.x_m + ramp_distance_m(v_a, v_star, ramp_s, tau),
                     ramp_s <= 0.0 || tau >= ramp_s ? v_star : v_a + (v_star - v_a) * tau / ramp_s};
  };
  // Ineq. (3)/(4): v_o* by t_r + rho_c. def2_positions: its response time T on top.
  const double t_paper_s = x.sent_time_s + p.comm_threshold_s;
  const auto [x_paper, v_paper] = on_ramp(t_paper_s - x.accept_time_s);
  const auto [x_late, v_late] = on_ramp(t_paper_s + s.params.rss.response_time_s - x.accept_time_s);
  b.valid = true;
  b.profile_x_m = x_paper;
  b.profile_v_mps = v_paper;
  b.bound_x_m = ahead ? x_late + tol_mps * tau : x_late - tol_mps * tau;
  b.bound_v_mps = ahead ? v_late + tol_mps : std::max(0.0, v_late - tol_mps);
  return b;
}

double d_lon_m(const ObservedTrace& s, std::size_t rear, double v_rear, std::size_t front, double v_front) {
  const Limits& r = limits_of(s, rear);
  return rss_longitudinal_m({std::max(0.0, v_rear), std::max(0.0, v_front), size_of(s, rear).length_m,
                             size_of(s, front).length_m, s.params.rss.response_time_s, r.accel_max_mps2,
                             r.brake_min_mps2, limits_of(s, front).brake_max_mps2});
}

namespace {

struct RequestView {
  const V2vMessage& m;
  int k = 0;                  // the responder's index
  const ObservedState& ego;   // at the send
  const ObservedState& resp;  // at the send
};

// RCPP ineq. (3), eq. (1) for D*_lon, and the reach of v_o* at b_min,o within rho_c (expressed as
// the distance the deeper slowdown would need over rho_c: half the speed shortfall times rho_c).
double soundness_2_1_m(const MonitorContext& ctx, const RequestView& r, std::string& what) {
  const ObservedTrace& s = ctx.trace;
  const double rho_c = ctx.params.comm_threshold_s, rho_m = ctx.params.merge_duration_s;
  const double v_o = std::max(0.0, speed_of(r.resp)), v_star = r.m.target_speed_mps;
  const double lhs = r.resp.x_m + 0.5 * (v_o + v_star) * rho_c + v_star * 0.5 * rho_m;
  const double m3 = (r.m.pc_m - r.m.d_lon_star_m) - lhs;
  const double m_d = r.m.d_lon_star_m - d_lon_m(s, static_cast<std::size_t>(r.k), v_star, 0, speed_of(r.ego));
  const double m_reach = 0.5 * rho_c * (v_star - (v_o - limits_of(s, r.k).brake_min_mps2 * rho_c));
  const double m = std::min({m3, m_d, m_reach});
  what = m == m3 ? "ineq. (3) fails" : m == m_d ? "D*_lon is below eq. (1) at v_o*" : "v_o* is beyond b_min,o within rho_c";
  return m;
}

// RCPP ineq. (4) with the ego braking at b_min for rho_c, and the reach of v_o* at a_acc,o within
// rho_c and under the speed limit (as for 2.1, in metres).
double soundness_2_2_m(const MonitorContext& ctx, const RequestView& r, std::string& what) {
  const ObservedTrace& s = ctx.trace;
  const double rho_c = ctx.params.comm_threshold_s;
  const double v_e = std::max(0.0, speed_of(r.ego)), b_min = limits_of(s, 0).brake_min_mps2;
  const double v_o = std::max(0.0, speed_of(r.resp)), v_star = r.m.target_speed_mps;
  const double v_e_after = std::max(0.0, v_e - b_min * rho_c);
  const double ego_travel = speed_change_distance_m(v_e, v_e_after, 1.0, b_min, rho_c);
  const double rhs = r.resp.x_m + 0.5 * (v_star + v_o) * rho_c -
                     d_lon_m(s, 0, v_e_after, static_cast<std::size_t>(r.k), v_star);
  const double m4 = rhs - (r.ego.x_m + ego_travel);
  // The domain of spec §5: [v_o, max(v_o, min(v_o + a_acc,o rho_c, speed limit))] (asking a
  // responder already above the limit to hold its speed is sound).
  const double v_reach =
      std::max(v_o, std::min(v_o + limits_of(s, r.k).accel_max_mps2 * rho_c, s.road.speed_limit_mps));
  const double m_reach = 0.5 * rho_c * (v_reach - v_star);
  what = m4 <= m_reach ? "ineq. (4) fails" : "v_o* is beyond a_acc,o within rho_c or the speed limit";
  return std::min(m4, m_reach);
}

// The responder after it accepted: no farther along (2.1: ineq. (3) counts on it being behind
// P_c - D*_lon) / no less far (2.2: ineq. (4) counts on it being ahead) than its accepted profile
// and its tolerance allow (accepted_profile_bound).
void responder_positions(const MonitorContext& ctx, const CoopExchange& x, MarginAccumulator& acc) {
  const ObservedTrace& s = ctx.trace;
  const Party partner = Party::from_vehicle_id(x.request->to_id);
  const int k = index_of_party(s, partner);
  if (k < 1) return;
  const bool ahead = x.request->coop_case == CoopCase::kEgoAhead;
  const double end = std::min(merge_midpoint_after(ctx.phases, x.accept_time_s),
                              x.sent_time_s + ctx.params.comm_threshold_s + ctx.params.merge_duration_s);
  for (std::size_t i = step_at(s, x.accept_time_s); i < s.steps.size() && s.steps[i].time_s <= end + kTieS; ++i) {
    const ProfileBound b = accepted_profile_bound(ctx, x, static_cast<std::size_t>(k), s.steps[i].time_s);
    if (!b.valid) continue;
    const double pos = state_of(s.steps[i], static_cast<std::size_t>(k)).x_m;
    if (acc.record(i, s.steps[i].time_s, ahead ? b.bound_x_m - pos : pos - b.bound_x_m, partner, b.bound_x_m, pos)) {
      std::ostringstream os;
      os << party_name(partner) << " accepted the Def. 2." << (ahead ? "1" : "2") << " request of t = "
         << x.sent_time_s << " s (v_o* = " << x.request->target_speed_mps << " m/s) but was at x = " << pos
         << " m at t = " << s.steps[i].time_s << " s, " << (ahead ? "ahead of" : "behind")
         << " its accepted profile (x = " << b.bound_x_m << " m with its tolerance): ineq. (" << (ahead ? "3" : "4")
         << ") counted on it";
      acc.set_detail(os.str());
    }
  }
}

// A request that lacks P_c, D*_lon or v_o* asks for a cooperation nobody can check: it fails
// (a missing number is never skipped), with -1 m, the margin def2_1a_request gives one too.
void missing_numbers(const CoopExchange& x, std::size_t step, MarginAccumulator& acc) {
  const V2vMessage& m = *x.request;
  std::string missing;
  for (const auto& [name, v] : {std::pair{"P_c", m.pc_m}, std::pair{"D*_lon", m.d_lon_star_m},
                                std::pair{"v_o*", m.target_speed_mps}})
    if (!std::isfinite(v)) missing += std::string(missing.empty() ? "" : ", ") + name;
  if (acc.record(step, x.sent_time_s, -1.0, Party::ego(), 0.0, -1.0))
    acc.set_detail("the request to " + party_name(Party::from_vehicle_id(m.to_id)) + " at t = " + std::to_string(x.sent_time_s) +
                   " s carries no " + missing + ": nothing can be checked of it");
}

}  // namespace

MonitorOutput monitor_def2_positions(const MonitorContext& ctx) {
  MarginAccumulator acc("def2_positions", ctx.trace.steps.size());
  if (ctx.trace.steps.empty()) return acc.finish();
  for (const CoopExchange& x : ctx.exchanges) {
    // A request without v_o* binds no responder (def2_request_sound fails the ego for it).
    if (x.accept_time_s >= 0.0 && x.complete()) responder_positions(ctx, x, acc);
  }
  return acc.finish();
}

MonitorOutput monitor_def2_request_sound(const MonitorContext& ctx) {
  const ObservedTrace& s = ctx.trace;
  MarginAccumulator acc("def2_request_sound", s.steps.size());
  if (s.steps.empty()) return acc.finish();
  for (const CoopExchange& x : ctx.exchanges) {
    const V2vMessage& m = *x.request;
    const int k = s.index_of(m.to_id);
    if (k < 1) continue;
    const std::size_t i = step_at(s, x.sent_time_s);
    if (!x.complete()) {
      missing_numbers(x, i, acc);
      continue;
    }
    const RequestView r{m, k, ego_of(s.steps[i]), state_of(s.steps[i], static_cast<std::size_t>(k))};
    std::string what;
    const bool ahead = m.coop_case == CoopCase::kEgoAhead;
    const double margin = ahead ? soundness_2_1_m(ctx, r, what) : soundness_2_2_m(ctx, r, what);
    if (acc.record(i, x.sent_time_s, margin, Party::ego(), 0.0, margin)) {
      std::ostringstream os;
      os << "the Def. 2." << (ahead ? "1" : "2") << " request to " << party_name(Party::from_vehicle_id(m.to_id)) << " at t = "
         << x.sent_time_s << " s (v_o* = " << m.target_speed_mps << " m/s) was unsound when sent: " << what
         << " by " << -margin << " m";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
