#include "planner/definition2_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/fixed_text.h"
#include "core/merge_duration.h"
#include "core/rss.h"
#include "planner/field_timeline.h"
#include "planner/merge_path.h"
#include "planner/rcpp_params.h"
#include "planner/rcpp_world.h"
#include "planner/world_view.h"

namespace mg {
namespace {

std::optional<MainLaneVehicle> neighbour(const std::vector<MainLaneVehicle>& lane, std::size_t i, int dir) {
  const long j = static_cast<long>(i) + dir;
  if (j < 0 || j >= static_cast<long>(lane.size())) return std::nullopt;
  return lane[static_cast<std::size_t>(j)];
}

// One candidate request: responder lane[i], case k, v_o* solved.
struct CoopCandidate {
  const WorldSnapshot& w;
  const std::vector<MainLaneVehicle>& lane;
  std::size_t i = 0;
  CoopCase k = CoopCase::kEgoAhead;
  CoopContext c;
  VoStar vo;
  double v_after_mps = 0.0;
  double t_c_s = 0.0;  // decision to P_c
  const MainLaneVehicle& responder() const { return lane[i]; }
};

struct CoopBounds {
  Gap gap;
  double pc_min_m = 0.0;
  double pc_max_m = 0.0;
};

// The request's gap and P_c bounds: ineq. (3) or (4) in P_c form toward the responder, and the
// gap's other vehicle as in Definition 1. nullopt when that vehicle rules the merge out.
std::optional<CoopBounds> coop_bounds(const CoopCandidate& x) {
  const PlannerSetup& s = *x.w.setup;
  const CoopContext& c = x.c;
  const MainLaneVehicle& o = x.responder();
  const double responder_at_pc_m = o.x_m + 0.5 * (o.speed_mps + x.vo.vo_star_mps) * c.comm_threshold_s +
                                   x.vo.vo_star_mps * 0.5 * c.merge_duration_s +
                                   c.request_latency_s * (o.speed_mps - x.vo.vo_star_mps);
  CoopBounds b{Gap{}, c.ego_x_m + coop_ego_travel_m(c, x.k), side_exit_limit_x_m(s)};
  if (x.k == CoopCase::kEgoAhead) {
    b.pc_min_m = std::max(b.pc_min_m, responder_at_pc_m + x.vo.d_lon_star_m);  // ineq. (3) in P_c form
    b.gap = Gap{o.id, -1};
    if (const auto l = neighbour(x.lane, x.i, +1)) {  // the gap's leader: ineq. (1.2) over rho_c + rho_m
      b.gap.leader_id = l->id;
      const Def1Context d1 = def1_context(x.w, c.comm_threshold_s + c.merge_duration_s);
      if (def1_2_margin_m(d1, *l, c.ego_speed_mps) < 0.0) return std::nullopt;
      const double d = rss_longitudinal_m({x.v_after_mps, l->speed_mps, c.ego_length_m, l->length_m,
                                           c.response_time_s, c.ego_limits.accel_max_mps2,
                                           c.ego_limits.brake_min_mps2, l->limits.brake_max_mps2});
      b.pc_max_m = std::min(b.pc_max_m, l->x_m + l->speed_mps * x.t_c_s - d);
    }
  } else {
    b.pc_max_m = std::min(b.pc_max_m, responder_at_pc_m - x.vo.d_lon_star_m);
    b.gap = Gap{-1, o.id};
    if (const auto f = neighbour(x.lane, x.i, -1)) {  // the gap's follower: ineq. (1.1) at P_c
      b.gap.follower_id = f->id;
      const Def1Context d1 = def1_context(x.w, 2.0 * x.t_c_s);
      const double margin = def1_1_margin_m(d1, *f, x.v_after_mps);  // = P_c - (X_f + D_lon) at P_c
      if (margin < 0.0) return std::nullopt;
      b.pc_min_m = std::max(b.pc_min_m, coop_pc_m(c, x.k) - margin);
    }
  }
  return b;
}

// The vehicles the occupancy check follows: the responder on its cooperative profile, the gap's
// other vehicle as in Definition 1, every vehicle ahead of the responder (a responder asked to
// speed up cannot drive through a vehicle stopped ahead of it, and the ego merging behind it
// merged onto that vehicle: rcpp-coop sigmoid_pc_bounds; docs/planner.md), the other lanes.
GapTracks coop_tracks(const CoopCandidate& x, const SpeedRamp& responder_ramp) {
  const MainLaneVehicle& o = x.responder();
  const Track responder{o.x_m, responder_ramp, o.length_m, o.width_m, o.limits, 0.0, {}};
  GapTracks tracks;
  tracks.beside = beside_tracks(x.w);
  if (x.k == CoopCase::kEgoAhead) {
    tracks.followers.push_back(responder);
  } else {
    tracks.leaders.push_back(responder);
    if (const auto f = neighbour(x.lane, x.i, -1))
      tracks.followers.push_back(follower_track(*f, 2.0 * x.t_c_s, observed_accel_mps2(x.w, f->id)));
  }
  for (std::size_t j = x.i + 1; j < x.lane.size(); ++j)
    tracks.leaders.push_back(predicted_leader(x.w, x.lane, x.lane[j], 2.0 * x.t_c_s));
  return tracks;
}

Def2Plan coop_plan(const CoopCandidate& x, const CoopBounds& b, double pc_m, double kappa_per_m) {
  const PlannerSetup& s = *x.w.setup;
  const MainLaneVehicle& o = x.responder();
  Def2Plan plan;
  plan.sigmoid = merge_sigmoid(s.road.lane_width_m, x.w.ego.y_m, kappa_per_m, pc_m);
  plan.vo = x.vo;
  plan.partner = o;
  plan.ego_speed_after_mps = x.v_after_mps;
  RcppDecision& d = plan.decision;
  d.time_s = x.w.time_s;
  d.mode = DecisionMode::kDef2Request;
  d.gap = b.gap;
  d.pc_min_m = b.pc_min_m;
  d.pc_max_m = b.pc_max_m;
  d.pc_m = pc_m;
  d.kappa_per_m = kappa_per_m;
  d.merge_duration_s = x.c.merge_duration_s;
  d.coop_partner_id = o.id;
  d.vo_star_mps = x.vo.vo_star_mps;
  d.d_lon_star_m = x.vo.d_lon_star_m;
  d.ve_star_mps = x.v_after_mps;
  d.reason = std::string(x.k == CoopCase::kEgoAhead ? "Def. 2.1 (ego ahead)" : "Def. 2.2 (ego behind)") +
             ": no Def. 1 gap; asking vehicle " + std::to_string(o.id) + " for v_o* = " +
             fixed_text(x.vo.vo_star_mps, 2) + " m/s (now " + fixed_text(o.speed_mps, 2) + "), P_c = " +
             fixed_text(pc_m, 1) + " m, D*_lon = " + fixed_text(x.vo.d_lon_star_m, 1) + " m" +
             (x.k == CoopCase::kEgoBehind ? "; ego brakes at b_min to " + fixed_text(x.v_after_mps, 2) + " m/s" : "");
  return plan;
}

// The cheapest sigmoid of candidate x through pc_m, its responder on responder_ramp (whose
// RSS distance is checked over the exchange and the merge, rho_c + rho_m), base_cost its cost
// besides the sigmoid's; its cost in *cost_out.
std::optional<Def2Plan> coop_sigmoid(const CoopCandidate& x, const CoopBounds& b, double pc_m,
                                     const SpeedRamp& responder_ramp, double base_cost, double* cost_out) {
  const WorldSnapshot& w = x.w;
  const PlannerSetup& s = *w.setup;
  const RcppParams p = rcpp_params(s);
  const CoopContext& c = x.c;
  const MainLaneVehicle& o = x.responder();
  const double start_x = c.ego_x_m + coop_ego_travel_m(c, x.k);
  const double complete_by_x = pc_m + x.v_after_mps * 0.5 * c.merge_duration_s;
  const SpeedRamp ramp{c.ego_speed_mps, x.v_after_mps, c.ego_limits.accel_max_mps2, c.ego_limits.brake_min_mps2};
  const auto kappa_range = [&](double pc) { return kappa_range_for(s, pc, start_x, complete_by_x, ramp, c.ego_x_m); };
  const GapTracks tracks = coop_tracks(x, responder_ramp);
  const auto partner_x = [&](const ObservedVehicle& v, double t) {
    return v.id == o.id ? o.x_m + responder_ramp.distance_at_m(t) : constant_speed_x(v, t);
  };
  std::optional<FieldTimeline> field;  // built when the first candidate needs it
  const double kappa_cap = kappa_cap_per_m(s, ramp);
  const auto cost = [&](double pc, double kappa) {
    const Sigmoid sig = merge_sigmoid(s.road.lane_width_m, w.ego.y_m, kappa, pc);
    // No planning buffer: the responder's cooperative profile is built to leave exactly D*_lon.
    if (!occupancy_clear(s, c.ego_x_m, w.ego.y_m, sig, ramp,
                         OccupancyInstants::over(c.comm_threshold_s + c.merge_duration_s), tracks, 0.0))
      return std::numeric_limits<double>::infinity();
    if (!field) field = field_timeline(w, 2.0 * x.t_c_s, partner_x);
    return base_cost + sharp_sigmoid_penalty(kappa, kappa_cap) +
           field_cost(p, *field, sig, [&](double t) { return c.ego_x_m + ramp.distance_at_m(t); });
  };
  const auto choice = choose_sigmoid({pc_m}, kappa_range, p.kappa_candidates, cost);
  if (!choice) return std::nullopt;
  *cost_out = choice->cost;
  return coop_plan(x, b, pc_m, choice->kappa_per_m);
}

// One Definition 2 candidate: responder lane[i], case k; its cost in *cost_out.
std::optional<Def2Plan> coop_candidate(const WorldSnapshot& w, const std::vector<MainLaneVehicle>& lane,
                                       std::size_t i, CoopCase k, double* cost_out) {
  const RcppParams p = rcpp_params(*w.setup);
  const CoopContext c = coop_context(w);
  const MainLaneVehicle& o = lane[i];
  const VoStar vo = solve_vo_star(c, o, k);
  if (!vo.feasible) return std::nullopt;
  const CoopCandidate x{w, lane, i, k, c, vo, coop_ego_speed_after_mps(c, k),
                        c.comm_threshold_s + 0.5 * c.merge_duration_s};
  const auto b = coop_bounds(x);
  const double pc = coop_pc_m(c, k);
  if (!b || pc < b->pc_min_m || pc > b->pc_max_m) return std::nullopt;  // P_c bounds cross (RCPP §II-C)
  const double base =
      p.cost_time_weight * x.t_c_s +
      p.cost_speed_change_weight * (std::abs(vo.vo_star_mps - o.speed_mps) + std::abs(x.v_after_mps - c.ego_speed_mps));
  const double rate = std::abs(vo.vo_star_mps - o.speed_mps) / c.comm_threshold_s + 1e-9;
  return coop_sigmoid(x, *b, pc, SpeedRamp{o.speed_mps, vo.vo_star_mps, rate, rate}, base, cost_out);
}

// The clauses of Definition 2 the order at the request allows: 2.1 (c_e ahead of c_o^i) for a
// responder whose body is wholly behind the ego's, 2.2 for one wholly ahead, either while the
// two bodies overlap along the road (alongside, neither is ahead: the inequality decides). Asking
// a vehicle behind to speed past, or one ahead to fall back, is neither clause:
// def2_request_truthful holds the request's case to the order observed at its send.
std::vector<CoopCase> cases_by_order(const WorldSnapshot& w, const MainLaneVehicle& o) {
  const double alongside_m = 0.5 * (w.setup->ego.size.length_m + o.length_m);
  if (w.ego.x_m - o.x_m >= alongside_m) return {CoopCase::kEgoAhead};
  if (o.x_m - w.ego.x_m >= alongside_m) return {CoopCase::kEgoBehind};
  return {CoopCase::kEgoAhead, CoopCase::kEgoBehind};
}

}  // namespace

std::optional<Def2Plan> plan_definition2(const WorldSnapshot& w, const std::map<int, double>& retry_after_s) {
  const std::vector<MainLaneVehicle> lane = target_lane_vehicles(w);
  std::optional<Def2Plan> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < lane.size(); ++i) {
    const auto obs = std::find_if(w.others.begin(), w.others.end(),
                                  [&](const ObservedVehicle& o) { return o.id == lane[i].id; });
    if (obs == w.others.end() || !obs->v2v_capable) continue;
    // Ineq. (3) and (4) rest on the partner's declared limits: a vehicle seen beyond them is not
    // asked (asked while it braked at 1.25 times its b_max, a partner accepted, went on braking,
    // and the merge on its acceptance was aborted, the ego's third lateral reversal of one
    // approach: smoothness_oscillation, a campaign finding).
    if (beyond_declared_limits(w, lane[i].id)) continue;
    const auto retry = retry_after_s.find(lane[i].id);
    if (retry != retry_after_s.end() && w.time_s < retry->second) continue;
    for (const CoopCase k : cases_by_order(w, lane[i])) {
      double cost = 0.0;
      auto plan = coop_candidate(w, lane, i, k, &cost);
      if (plan && cost < best_cost) {
        best_cost = cost;
        best = std::move(plan);
      }
    }
  }
  return best;
}

bool responder_breaks_acceptance(const WorldSnapshot& w, const HeldAcceptance& a, const MainLaneVehicle& o) {
  if (w.time_s < a.yield_by_s) return false;
  const double over_mps = o.speed_mps - a.vo_star_mps;
  return (a.coop_case == CoopCase::kEgoAhead ? over_mps : -over_mps) > kBrokenPromiseMps;
}

std::optional<Def2Plan> plan_accepted_definition2(const WorldSnapshot& w, const HeldAcceptance& a) {
  if (w.time_s < a.yield_by_s) return std::nullopt;
  CoopContext c = coop_context(w);
  // The answer is in hand: no exchange window, no request in flight.
  c.comm_threshold_s = 0.0;
  c.request_latency_s = 0.0;
  // The midpoint while the acceptance binds the partner: at rho_m, or sooner on a shorter merge,
  // down to the shortest comfortable lane change, when less of the binding is left (an acceptance
  // taken up again after an abort and the hold that follows it).
  const double left_s = a.bound_until_s + kHeldAcceptanceTieS - w.time_s;
  if (left_s < 0.5 * c.merge_duration_s) {
    const PlannerSetup& s = *w.setup;
    const double shortest_s = kShortestMergeFactor * shortest_comfortable_merge_s(
                                                         s.road.lane_width_m, rcpp_params(s).lat_accel_comfort_mps2);
    if (2.0 * left_s < shortest_s) return std::nullopt;
    c.merge_duration_s = 2.0 * left_s;
  }
  const std::vector<MainLaneVehicle> lane = target_lane_vehicles(w);
  const auto it = std::find_if(lane.begin(), lane.end(), [&](const MainLaneVehicle& v) { return v.id == a.partner_id; });
  if (it == lane.end()) return std::nullopt;
  const std::size_t i = static_cast<std::size_t>(it - lane.begin());
  const MainLaneVehicle& o = *it;
  if (responder_breaks_acceptance(w, a, o)) return std::nullopt;
  const std::vector<CoopCase> cases = cases_by_order(w, o);
  if (std::find(cases.begin(), cases.end(), a.coop_case) == cases.end()) return std::nullopt;
  // The responder as it may still drive: toward v_o* from its speed now, never on the ego's side
  // of it (2.1: no slower than it is; 2.2: no faster), at v_o* from the merge's start.
  const bool ahead = a.coop_case == CoopCase::kEgoAhead;
  const double v_o = ahead ? std::max(o.speed_mps, a.vo_star_mps) : std::min(o.speed_mps, a.vo_star_mps);
  VoStar vo;
  vo.feasible = true;
  vo.coop_case = a.coop_case;
  vo.vo_star_mps = v_o;
  vo.d_lon_star_m = std::max(a.d_lon_star_m, ahead ? d_lon_star_m(c, o, v_o) : d_lon_ego_rear_m(c, o, v_o));
  const CoopCandidate x{w, lane, i, a.coop_case, c, vo, coop_ego_speed_after_mps(c, a.coop_case), 0.5 * c.merge_duration_s};
  auto b = coop_bounds(x);
  if (!b) return std::nullopt;
  // Where the request said the ego would cross (def2_request_truthful: 2.1 no sooner, 2.2 no later).
  if (ahead) b->pc_min_m = std::max(b->pc_min_m, a.pc_m);
  else b->pc_max_m = std::min(b->pc_max_m, a.pc_m);
  const double pc = coop_pc_m(c, a.coop_case);
  if (pc < b->pc_min_m || pc > b->pc_max_m) return std::nullopt;
  double cost = 0.0;
  auto plan = coop_sigmoid(x, *b, pc, SpeedRamp{v_o, v_o, 1.0, 1.0}, 0.0, &cost);
  if (!plan) return std::nullopt;
  plan->decision.mode = DecisionMode::kDef2Merge;
  plan->decision.reason = std::string(ahead ? "Def. 2.1 (ego ahead)" : "Def. 2.2 (ego behind)") + ": vehicle " +
                          std::to_string(o.id) + "'s acceptance of t = " + fixed_text(a.delivered_time_s, 2) +
                          " s binds it until t = " + fixed_text(a.bound_until_s, 2) + " s; merging again at P_c = " +
                          fixed_text(pc, 1) + " m (asked: " + fixed_text(a.pc_m, 1) + " m)";
  return plan;
}

}  // namespace mg
