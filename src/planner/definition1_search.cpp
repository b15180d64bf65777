#include "planner/definition1_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/fixed_text.h"
#include "core/rss.h"
#include "planner/field_timeline.h"
#include "planner/merge_path.h"
#include "planner/rcpp_params.h"
#include "planner/rcpp_world.h"
#include "planner/world_view.h"

namespace mg {
namespace {

// When no Definition 1 merge of any duration is clear, the search tries the flatter sigmoids
// below kappa_min_per_m, down to this slope, before the ego halts. At speed the merge's own
// length asks for less than the floor (ln 49 / kappa before P_c is 130 m at 0.03/m), and a
// steeper sigmoid moves the ego sideways faster, its D_lat larger, so that it stays inside D_lat
// of a vehicle it is overtaking or of one in the lane beyond for longer: the search let pass gaps
// whose flatter merge `progress`'s witness found clear. Only as a last resort: the floor shapes
// every merge at speed (with a floor of 0.03/m throughout, reproduce-paper's variant table moved).
constexpr double kFlatKappaFloorPerM = 0.03;

constexpr double kPcMarginM = 1.0;          // P_c candidates keep this far inside their bounds ...
constexpr double kNearPcBoundPenalty = 1e4;  // ... or pay this (far above any candidate's cost)

// A merge whose sigmoid starts (its 2 % point) more than kPromptStartS of the ego's ramp ahead
// pays kLateStartPenalty, so it is chosen only when no merge into any gap starts sooner. The cost
// prefers keeping the ego's speed, and a long merge decided at speed drew its sigmoid from a
// point seconds ahead while a slower merge into the same gap could begin at once: the ego drove
// on in its side lane past the grace `progress` allows an offered merge (a campaign finding).
// Below kNearPcBoundPenalty: a candidate near its P_c bounds is the worse risk.
constexpr double kPromptStartS = 2.0;
constexpr double kLateStartPenalty = 1e3;
constexpr double kLatePlanSearchMaxFactor = 2.0;  // plan_definition1: the longest rho a late plan looks on to

// Where the ego's ramp takes it in kPromptStartS: a sigmoid whose 2 % point lies beyond starts late.
double late_start_x_m(const Def1Context& ctx, const SpeedRamp& ramp) {
  return ctx.ego_x_m + ramp.distance_at_m(kPromptStartS);
}

// Whether a sigmoid with midpoint pc_m and slope kappa_per_m starts beyond late_x_m: its 2 %
// point as Sigmoid::x_at_fraction_m computes it, with the logarithm taken once.
bool starts_late(double pc_m, double kappa_per_m, double late_x_m) {
  static const double kEndLogit = std::log(kSigmoidEndFraction / (1.0 - kSigmoidEndFraction));
  return pc_m + kEndLogit / kappa_per_m > late_x_m;
}

std::string gap_name(const Gap& g) {
  const auto id = [](int i) { return i < 0 ? std::string("open") : std::to_string(i); };
  return "gap (follower " + id(g.follower_id) + ", leader " + id(g.leader_id) + ")";
}

double gap_traffic_speed_mps(const LaneGap& g, double fallback_mps) {
  if (g.follower && g.leader) return 0.5 * (g.follower->speed_mps + g.leader->speed_mps);
  if (g.follower) return g.follower->speed_mps;
  if (g.leader) return g.leader->speed_mps;
  return fallback_mps;
}

// What the search at one merge duration shares between the gaps it tries.
struct Def1Search {
  const WorldSnapshot& w;
  const PlannerSetup& s;
  Def1Context ctx;
  double rho_s = 0.0;
  double half_s = 0.0;
  std::vector<MainLaneVehicle> lane;
  std::vector<BesideTrack> beside;
  std::optional<FieldTimeline> field_at_rho;  // built when the first candidate needs it
  bool flat = false;  // the flat fallback: slopes below kappa_min_per_m only (kFlatKappaFloorPerM)

  // P_c of a merge at v_e* = v: where the ego is at rho/2 on its ramp to v.
  double pc_of(double v) const { return ctx.ego_x_m + ctx.ramp_to(v).distance_at_m(half_s); }
};

// A gap's P_c interval and the highest v_e* whose P_c lies in it.
struct PcBounds {
  double v_hi_mps = 0.0;
  double pc_min_m = 0.0;
  double pc_max_m = 0.0;
  // P_c(v) is monotone in v, but only up to rounding: a candidate at v_hi must not land a
  // rounding error outside [pc_min, pc_max] (a campaign finding: P_c "outside" by 1e-13 m).
  double pc_at(const Def1Search& f, double v) const { return std::clamp(f.pc_of(v), pc_min_m, pc_max_m); }
};

// nullopt when the bounds cross (RCPP §II-C).
std::optional<PcBounds> def1_pc_bounds(const Def1Search& f, const LaneGap& gap, const SpeedInterval& iv) {
  // Sigmoid upper bound (RCPP §II-C): P_c <= X_o - D_lon at the leader's predicted position.
  double v_hi = iv.hi_mps;
  if (gap.leader) {
    // The leader as the commit re-check predicts it (leader_track): a bound from the constant
    // speed of Def. 1.2 alone let a merge be decided that the next cycle aborted.
    const MainLaneVehicle& l = *gap.leader;
    const Track lt = predicted_leader(f.w, f.lane, l, f.rho_s);
    const Def1Context& ctx = f.ctx;
    const auto margin = [&](double v) {
      const double d = rss_longitudinal_m({ctx.ramp_to(v).speed_at_mps(f.half_s), lt.v_at(f.half_s), ctx.ego_length_m,
                                           l.length_m, ctx.response_time_s, ctx.ego_limits.accel_max_mps2,
                                           ctx.ego_limits.brake_min_mps2, l.limits.brake_max_mps2});
      return (lt.x_at(f.half_s) - d) - f.pc_of(v);
    };
    const auto bound = highest_satisfying(margin, iv.lo_mps, iv.hi_mps);
    if (!bound) return std::nullopt;
    v_hi = *bound;
  }
  // Lower bound X_o^i + D*_lon <= P_c coincides with ineq. (1.1) at v_e* = lo.
  const double pc_min = f.pc_of(iv.lo_mps);
  const double pc_max = std::min(f.pc_of(v_hi), side_exit_limit_x_m(f.s));
  if (pc_min > pc_max) return std::nullopt;
  return PcBounds{v_hi, pc_min, pc_max};
}

// The v_e* candidates: pc_candidates values evenly over [lo, v_hi], the speed grid shared with
// the progress rule within it, and the crawl speed (merge_path.h) when it lies in [lo, v_hi]: the
// grid's steps (speed limit / 48) may hold none between half the crawl speed and the crawl
// speed, where an ego at rest near the side lane's end can still turn in. The grid is over v_e*,
// not P_c: an ego that cannot reach v_e* by rho/2 has the same P_c for a range of v_e*, which
// differ after P_c.
std::vector<double> def1_candidate_speeds(const Def1Search& f, double lo_mps, double v_hi_mps) {
  std::vector<double> speeds = even_grid(lo_mps, v_hi_mps, rcpp_params(f.s).pc_candidates);
  if (const double crawl_mps = crawl_speed_mps(f.s); crawl_mps >= lo_mps && crawl_mps <= v_hi_mps)
    speeds.push_back(crawl_mps);
  const double grid_step_mps = f.ctx.speed_limit_mps / kDef1SpeedGridSteps;
  for (int i = static_cast<int>(std::ceil(lo_mps / grid_step_mps)); i * grid_step_mps <= v_hi_mps; ++i)
    speeds.push_back(i * grid_step_mps);
  std::sort(speeds.begin(), speeds.end());
  speeds.erase(std::unique(speeds.begin(), speeds.end()), speeds.end());
  return speeds;
}

// What the candidates of one v_e* share (def1_choose).
struct Def1Speed {
  SpeedRamp ramp;
  double pc_m = 0.0;
  double kappa_cap_per_m = 0.0;
  double late_x_m = 0.0;   // late_start_x_m of the ramp
  double base_cost = 0.0;  // the Definition 1 cost before the penalties that depend on kappa
  OccupancyMemo memo;      // shared by the kappa candidates
};

// The candidates of v_e* = v. They keep pc_margin_m (kPcMarginM, or less in a narrow interval) from
// both P_c bounds when they can (path-tracking error): one
// nearer a bound pays kNearPcBoundPenalty, so it wins only when nothing else is admissible.
Def1Speed def1_speed(const Def1Search& f, const PcBounds& b, double pc_margin_m, double v_traffic_mps, double v) {
  const RcppParams p = rcpp_params(f.s);
  const Def1Context& ctx = f.ctx;
  const double pc = b.pc_at(f, v);
  const bool near_bound = pc < b.pc_min_m + pc_margin_m || pc > b.pc_max_m - pc_margin_m;
  const SpeedRamp ramp = ctx.ramp_to(v);
  const double base = p.cost_time_weight * f.half_s + p.cost_speed_change_weight * std::abs(v - ctx.ego_speed_mps) +
                      p.cost_traffic_speed_weight * std::abs(v - v_traffic_mps) + (near_bound ? kNearPcBoundPenalty : 0.0);
  return Def1Speed{ramp, pc, kappa_cap_per_m(f.s, ramp), late_start_x_m(ctx, ramp), base, {}};
}

// RCPP's Definition 1 cost of a candidate (docs/planner.md), without the potential field.
double def1_cost(const Def1Speed& a, double kappa_per_m) {
  return a.base_cost + (starts_late(a.pc_m, kappa_per_m, a.late_x_m) ? kLateStartPenalty : 0.0) +
         sharp_sigmoid_penalty(kappa_per_m, a.kappa_cap_per_m);
}

// The cheapest comfortable sigmoid into `gap` whose merge stays clear of the lane's vehicles;
// nullopt when none is, or none costs less than `incumbent` (the cheapest plan into another gap).
std::optional<SigmoidChoice> def1_choose(Def1Search& f, const LaneGap& gap, const SpeedInterval& iv,
                                         const PcBounds& b, double incumbent) {
  const PlannerSetup& s = f.s;
  const RcppParams p = rcpp_params(s);
  const Def1Context& ctx = f.ctx;
  const double v_e = ctx.ego_speed_mps;
  const double v_traffic = gap_traffic_speed_mps(gap, v_e);
  GapTracks tracks = gap_tracks(f.lane, gap, f.rho_s, [&](int id) { return observed_accel_mps2(f.w, id); },
                                leader_horizon(f.w, f.rho_s));
  tracks.beside = f.beside;
  // The ego's own lateral progress toward the main lane, where a merge from a crawl may start its
  // sigmoid (kappa_range_for).
  const double start_fraction = (f.w.ego.y_m - s.road.side_lane_y_m()) / s.road.lane_width_m;
  const std::vector<double> speeds = def1_candidate_speeds(f, iv.lo_mps, b.v_hi_mps);
  const double pc_margin = std::min(kPcMarginM, 0.25 * (b.pc_max_m - b.pc_min_m));
  std::vector<std::optional<Def1Speed>> at_speed(speeds.size());  // made when the search first reaches each
  int last_blocked_k = -1;  // the instant that blocked the last occupancy check, at any speed
  const auto speed = [&](std::size_t i) -> Def1Speed& {
    if (!at_speed[i]) at_speed[i].emplace(def1_speed(f, b, pc_margin, v_traffic, speeds[i]));
    return *at_speed[i];
  };
  const double field_floor = field_cost_floor(p);
  // Every term the kappa adds to the Definition 1 cost is >= 0 and the field is never below its
  // floor (PotentialField.TheFloorIsNeverAboveTheField), so both bounds hold in floating point.
  const auto floor_of = [&](std::size_t i) { return speed(i).base_cost + field_floor; };
  const auto bound = [&](std::size_t i, double kappa) { return def1_cost(speed(i), kappa) + field_floor; };
  const auto cost = [&](std::size_t i, double kappa) {
    Def1Speed& a = speed(i);
    const Sigmoid sig = merge_sigmoid(s.road.lane_width_m, f.w.ego.y_m, kappa, a.pc_m);
    a.memo.last_blocked_k = last_blocked_k;
    const bool clear = occupancy_clear(s, ctx.ego_x_m, f.w.ego.y_m, sig, a.ramp, OccupancyInstants::over(f.rho_s),
                                       tracks, kOccupancyPlanningBufferM, &a.memo);
    last_blocked_k = a.memo.last_blocked_k;
    if (!clear) return std::numeric_limits<double>::infinity();
    if (!f.field_at_rho) f.field_at_rho = field_timeline(f.w, f.rho_s, constant_speed_x);
    return def1_cost(a, kappa) + field_cost(p, *f.field_at_rho, sig,
                                            [&](double t) { return ctx.ego_x_m + a.ramp.distance_at_m(t); });
  };
  const auto range_from = [&](std::size_t i, double floor_per_m) {
    const Def1Speed& a = speed(i);
    return kappa_range_for(s, a.pc_m, ctx.ego_x_m, ctx.ego_x_m + a.ramp.distance_at_m(f.rho_s), a.ramp, ctx.ego_x_m,
                           floor_per_m, start_fraction);
  };
  const auto kappa_range = [&](std::size_t i) { return range_from(i, 0.0); };
  // The flat fallback: the slopes below the configured floor, down to kFlatKappaFloorPerM, of a
  // v_e* whose range starts at that floor.
  const auto flatter_range = [&](std::size_t i) -> KappaRange {
    const KappaRange r = range_from(i, kFlatKappaFloorPerM);
    if (!r || r->first >= p.kappa_min_per_m) return std::nullopt;
    return std::make_pair(r->first, std::min(r->second, p.kappa_min_per_m));
  };
  if (f.flat) return choose_sigmoid_best_first(speeds, floor_of, flatter_range, p.kappa_candidates, bound, cost, incumbent);
  return choose_sigmoid_best_first(speeds, floor_of, kappa_range, p.kappa_candidates, bound, cost, incumbent);
}

Def1Plan def1_plan(const Def1Search& f, const Gap& gid, const SpeedInterval& iv, const PcBounds& b,
                   const SigmoidChoice& choice) {
  Def1Plan plan;
  plan.ve_star_mps = choice.param;
  const double pc = b.pc_at(f, choice.param);
  plan.sigmoid = merge_sigmoid(f.s.road.lane_width_m, f.w.ego.y_m, choice.kappa_per_m, pc);
  RcppDecision& d = plan.decision;
  d.time_s = f.w.time_s;
  d.mode = DecisionMode::kDef1Merge;
  d.gap = gid;
  d.ve_min_mps = iv.lo_mps;
  d.ve_max_mps = iv.hi_mps;
  d.ve_star_mps = plan.ve_star_mps;
  d.pc_min_m = b.pc_min_m;
  d.pc_max_m = b.pc_max_m;
  d.pc_m = pc;
  d.kappa_per_m = choice.kappa_per_m;
  d.merge_duration_s = f.rho_s;
  plan.late_start = starts_late(pc, choice.kappa_per_m, late_start_x_m(f.ctx, f.ctx.ramp_to(plan.ve_star_mps)));
  d.reason = "Def. 1: " + gap_name(gid) + " feasible for v_e* in [" + fixed_text(iv.lo_mps, 2) + ", " +
             fixed_text(iv.hi_mps, 2) + "] m/s; merging at v_e* = " + fixed_text(plan.ve_star_mps, 2) +
             " m/s, P_c = " + fixed_text(pc, 1) + " m, kappa = " + fixed_text(choice.kappa_per_m, 3) +
             "/m, rho = " + fixed_text(f.rho_s, 1) + " s (cost " + fixed_text(choice.cost, 2) + ")";
  return plan;
}

// Definition 1 for one merge duration rho_s: the cheapest gap's plan.
std::optional<Def1Plan> plan_definition1_rho(const WorldSnapshot& w, double rho_s, bool flat, std::string* why) {
  Def1Search f{w, *w.setup, def1_context(w, rho_s), rho_s, 0.5 * rho_s, target_lane_vehicles(w), beside_tracks(w), {},
               flat};
  std::optional<Def1Plan> best;
  double best_cost = std::numeric_limits<double>::infinity();
  int n_def1 = 0, n_cross = 0, n_sigmoid = 0, n_breach = 0;
  // A gap whose follower is seen accelerating beyond its declared a_accel^max, or whose leader is
  // seen braking beyond its b_max, is no gap while the ego can still halt: Definition 1 rests on those
  // limits, the prediction of that vehicle at the rate seen is one it need not keep, and a merge
  // decided on it was aborted the next cycle, again and again, until smoothness_oscillation failed
  // (a campaign finding: a follower racing at 2.5 times its a_accel^max). The progress rule offers
  // no such gap either. A breach that does not close the gap (a leader racing away) leaves it.
  const bool can_halt = can_still_halt(w);
  const auto closing = [&](const LaneGap& g) {
    return (g.follower && accelerating_beyond_limit(w, g.follower->id)) || (g.leader && braking_beyond_limit(w, g.leader->id));
  };
  for (const LaneGap& gap : enumerate_gaps(f.lane)) {
    if (can_halt && closing(gap)) { ++n_breach; continue; }
    const SpeedInterval iv = solve_def1_interval(f.ctx, gap);
    if (!iv.feasible) { ++n_def1; continue; }
    const auto bounds = def1_pc_bounds(f, gap, iv);
    if (!bounds) { ++n_cross; continue; }
    const auto choice = def1_choose(f, gap, iv, *bounds, best_cost);
    if (!choice) { ++n_sigmoid; continue; }
    best_cost = choice->cost;
    const Gap gid{gap.follower ? gap.follower->id : -1, gap.leader ? gap.leader->id : -1};
    best = def1_plan(f, gid, iv, *bounds, *choice);
  }
  if (!best && why)
    *why = std::to_string(n_def1) + " gap(s) violate ineq. 1.1/1.2, " + std::to_string(n_cross) +
           " with crossing P_c bounds, " + std::to_string(n_sigmoid) + " without a comfortable sigmoid" +
           (n_breach > 0 ? ", " + std::to_string(n_breach) + " closing beyond a vehicle's declared limits" : "");
  return best;
}

}  // namespace

std::optional<Def1Plan> plan_definition1(const WorldSnapshot& w, MergeDurations durations, std::string* why) {
  const PlannerSetup& s = *w.setup;
  const double rho_base_s =
      merge_duration_base_s(planned_rho_m_s(s), s.road.lane_width_m, rcpp_params(s).lat_accel_comfort_mps2);
  const bool flat = durations == MergeDurations::kFlat;
  if (flat && rcpp_params(s).kappa_min_per_m <= kFlatKappaFloorPerM) return std::nullopt;
  // A longer merge that starts now before a shorter one whose sigmoid starts seconds ahead: the
  // ego drives on straight toward a late start, which `progress` cannot tell from waiting, while
  // the longer merge moves it toward the lane at once (the first late plan of 1.5 rho ended the
  // search, and an ego waiting for a passing vehicle let the gap behind it go; a campaign
  // finding). Not one of 3 rho: its sigmoid, at least as flat as the floor allows, leaves the
  // side lane so slowly (0.05 m/s of lateral speed at 8 m/s) that its first seconds look no
  // different from driving straight, and once begun no sooner merge replaces it.
  std::optional<Def1Plan> late;
  for (const double factor : kMergeDurationFactors) {
    if (!flat && (factor == 1.0) != (durations == MergeDurations::kRhoM)) continue;
    if (late && factor > kLatePlanSearchMaxFactor) break;
    std::string this_why;
    if (auto plan = plan_definition1_rho(w, factor * rho_base_s, flat, &this_why)) {
      if (!plan->late_start) return plan;
      if (!late) late = std::move(plan);
      continue;
    }
    if (why) *why += (why->empty() ? "" : "; ") + ("rho = " + fixed_text(factor * rho_base_s, 1) + " s: ") + this_why;
  }
  return late;
}

}  // namespace mg
