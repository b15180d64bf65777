#include "rules/progress_monitor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "core/merge_duration.h"
#include "core/rss.h"
#include "rules/coop_exchange.h"
#include "rules/definition1_gap.h"

namespace mg {
namespace {

// Feasibility is re-evaluated every kProgressEvalS (no planner reacts instantly).
constexpr double kProgressEvalS = 0.1;

// What the ego is doing at a step, as far as progress is concerned.
enum class Activity {
  kWaiting,   // centre in the side lane, no merge under way: the clock runs while a merge is offered
  kPaused,    // in an attempt that has not reached into the main lane, moving toward it
  kMerging,   // in an attempt whose body reached into the main lane, or its centre past the lane line
};

// An attempt is a merge once the ego's body reaches into the main lane (its entry): from its start
// to its end, the ego is merging, and an offer it lets pass after that begins a new run. Before
// the entry, and in an attempt that never enters, the clock pauses while the ego moves toward the
// main lane (v_Y > lat_speed_hysteresis_mps) and runs otherwise: a planner that aborts and tries
// again loses no credit for its outward motion, one that drifts out and back, or stalls off its
// lane centre, keeps the clock running on the way back and while it stalls. The unbroken lateral
// approach that led into a start (v_Y > 0, however slow: a long sigmoid leaves its lane centre
// gently) pauses the clock too: the merge began there.
std::vector<Activity> activities(const ObservedTrace& t, const RuleParams& p, const MergeAttempts& attempts) {
  std::vector<Activity> out(t.steps.size(), Activity::kWaiting);
  const double line_y = -0.5 * t.road.lane_width_m;
  for (const MergeAttempt& a : attempts.attempts) {
    for (std::size_t i = a.start_step; i > 0 && ego_of(t.steps[i - 1]).vy_mps > 0.0; --i)
      if (out[i - 1] == Activity::kWaiting) out[i - 1] = Activity::kPaused;
    const std::size_t end = a.end_time_s ? step_at(t, *a.end_time_s) : t.steps.size() - 1;
    for (std::size_t i = a.start_step; i <= end && i < out.size(); ++i) {
      if (a.entry_step) out[i] = Activity::kMerging;
      else if (ego_of(t.steps[i]).vy_mps > p.lat_speed_hysteresis_mps) out[i] = Activity::kPaused;
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!(ego_of(t.steps[i]).y_m < line_y)) out[i] = Activity::kMerging;
  return out;
}

// A Definition 2 acceptance in force: delivered to the ego within [t_r, t_r + rho_c] (a later one
// grants nothing, Def. 2.3), from [delivery, t_r + rho_c + rho_m] (the cooperation's span,
// def2_1b_responder's window), and only when the gap's other vehicle leaves room for it
// (other_gap_vehicle_clear, as for the right of way).
struct Acceptance {
  int partner_id = 0;
  bool ego_ahead = true;  // Def. 2.1 (the ego merges ahead of the partner) or 2.2
  double from_s = 0.0, to_s = 0.0;
};
std::vector<Acceptance> acceptances(const ObservedTrace& t, const RuleParams& p,
                                    const std::vector<CoopExchange>& exchanges) {
  std::vector<Acceptance> out;
  for (const CoopExchange& x : exchanges) {
    const double d = x.accept_delivered_time_s;
    if (d < 0.0 || d > x.request_time_s + p.comm_threshold_s + kTieS) continue;
    // A request that asks for nothing judgeable, or names the wrong order (def2_request_truthful),
    // grants nothing, as for the right of way (merge_attempts.cpp try_def2).
    if (!x.complete() || x.order_margin_m < 0.0) continue;
    if (!other_gap_vehicle_clear(t, p, x)) continue;
    out.push_back({x.request->to_id, x.request->coop_case == CoopCase::kEgoAhead, d,
                   x.request_time_s + p.comm_threshold_s + p.merge_duration_s});
  }
  return out;
}

// What is offered to the ego at one evaluation.
struct Offer {
  std::vector<FeasibleMerge> gaps;
  int partner_id = -1;  // an acceptance in force, or -1
  bool any() const { return !gaps.empty() || partner_id >= 0; }
};

// An acceptance of Def. 2.1 offers the merge it was asked for only while the vehicle ahead of the
// partner, the gap's other vehicle, holds its speed as for a Definition 1 gap (leader_holds_speed's
// first condition): one seen braking harder than progress_leader_braking_mps2 shrinks the gap the
// request counted on, and an ego that drops the merge then is waiting for a reason. (In 2.2 the
// other vehicle is behind the partner; Def. 1.1 already lets it accelerate.)
bool other_vehicle_holds_speed(const ObservedTrace& t, const RuleParams& p, const Acceptance& a, std::size_t i) {
  if (!a.ego_ahead) return true;
  const int partner = t.index_of(a.partner_id);
  for (const GapIndices& g : lane_gaps(t, i)) {
    if (g.follower != partner || g.leader < 1) continue;
    return !(t.steps[i].vehicles[static_cast<std::size_t>(g.leader)].accel_mps2 < -p.progress_leader_braking_mps2);
  }
  return true;
}

Offer offer_at(const MonitorContext& ctx, const std::vector<Acceptance>& accepted, std::size_t i) {
  Offer o;
  o.gaps = def1_gaps_feasible(ctx.trace, ctx.params, i);
  const double now = ctx.trace.steps[i].time_s;
  for (const Acceptance& a : accepted)
    if (now >= a.from_s - kTieS && now <= a.to_s + kTieS && other_vehicle_holds_speed(ctx.trace, ctx.params, a, i))
      o.partner_id = a.partner_id;
  return o;
}

// A merge into the main lane that the ego did not abort: an attempt whose body entered the main
// lane and that completed or was under way when the trace ended. One that never entered does not
// count, or an ego drifting out and back would always have an attempt under way at the end. The
// gap it entered (by the vehicles' ids, -1 open) and from which step on (its entry) it no longer
// excuses a wait.
struct LaterMerge {
  std::size_t entry_step = 0;
  std::pair<int, int> gap;
};
std::vector<LaterMerge> merges_taken(const ObservedTrace& t, const MergeAttempts& attempts) {
  const auto id = [&](int k) { return k < 1 ? -1 : t.vehicles[static_cast<std::size_t>(k)].id; };
  std::vector<LaterMerge> out;
  for (const MergeAttempt& a : attempts.attempts)
    if (a.entry_step && (a.completed || !a.end_time_s))
      out.push_back({*a.entry_step, {id(a.entered_gap.follower), id(a.entered_gap.leader)}});
  return out;
}

// The offer the ego let pass at step i: the offer less what it used later. A gap it merges into
// after step i (completed, or under way at the end), and an acceptance whose sender bounds that gap, were not let pass but
// taken, however long the ego took to position itself for them (the wait is measured apart).
Offer let_pass(const Offer& offered, const std::vector<LaterMerge>& merges, std::size_t i) {
  Offer o;
  o.partner_id = offered.partner_id;
  for (const FeasibleMerge& g : offered.gaps) {
    const bool taken = std::any_of(merges.begin(), merges.end(), [&](const LaterMerge& m) {
      return m.entry_step >= i && m.gap == std::pair<int, int>{g.follower_id, g.leader_id};
    });
    if (!taken) o.gaps.push_back(g);
  }
  for (const LaterMerge& m : merges)
    if (m.entry_step >= i && o.partner_id >= 0 && (m.gap.first == o.partner_id || m.gap.second == o.partner_id))
      o.partner_id = -1;
  return o;
}

// A merge into a gap begins with the ego changing speed toward the gap's v_e* (dropping back
// behind a vehicle alongside, catching up with a gap ahead): braking while faster than every
// feasible v_e*, or accelerating while slower than every one, deliberately (at least
// kSpeedChangeMps2, beyond drift), is preparing the merge, and the clock pauses.
constexpr double kSpeedChangeMps2 = 0.5;
bool adjusting_speed(const ObservedState& ego, const Offer& o) {
  for (const FeasibleMerge& g : o.gaps) {
    if (ego.vx_mps > g.ve_max_mps && ego.accel_mps2 <= -kSpeedChangeMps2) return true;
    if (ego.vx_mps < g.ve_star_mps && ego.accel_mps2 >= kSpeedChangeMps2) return true;
  }
  return false;
}

std::string side_text(int id) { return id < 0 ? std::string("open") : std::to_string(id); }

// Time offered and unused: in all, and the longest stretch.
struct Unused {
  double total_s = 0.0;
  double longest_s = 0.0;
};

// One run of offered time: it starts at the first step offered and counts the steps at which the
// ego is idle (waiting, not changing speed toward the offer) until the offer lapses, the ego merges
// or responds.
struct Stretch {
  double start_s = -1.0;
  double unused_s = 0.0;
  void end() { start_s = -1.0; }
  void step(bool offered, bool idle, double now_s, double dt_s, Unused& sum) {
    if (!offered) return end();
    if (start_s < 0.0) {
      start_s = now_s;
      unused_s = 0.0;
    } else if (idle) {
      unused_s += dt_s;
      sum.total_s += dt_s;
    }
    sum.longest_s = std::max(sum.longest_s, unused_s);
  }
};

// What the ego let pass over the whole trace (the distinct feasible gaps, by their vehicles, and
// the accepted requests it did not use) and the time it waited for an offer it took later.
struct Tally {
  std::set<std::pair<int, int>> gaps;
  std::set<int> partners;
  Unused passed, taken;
};

void note(Tally& tally, const Offer& o) {
  for (const FeasibleMerge& g : o.gaps) tally.gaps.insert({g.follower_id, g.leader_id});
  if (o.partner_id >= 0) tally.partners.insert(o.partner_id);
}

std::string violation_text(double unused_s, double from_s, const ObservedStep& st, const Offer& o) {
  std::ostringstream os;
  os << "ego in the side lane let the right of way pass for " << unused_s << " s from t = " << from_s
     << " s (at t = " << st.time_s << " s, at " << ego_of(st).vx_mps << " m/s: ";
  if (!o.gaps.empty()) {
    const FeasibleMerge& g = o.gaps.front();
    os << "Def. 1 gap (follower " << side_text(g.follower_id) << ", leader " << side_text(g.leader_id)
       << ") feasible, rho = " << g.merge_duration_s << " s, v_e* >= " << g.ve_star_mps << " m/s";
    if (o.gaps.size() > 1) os << ", and " << o.gaps.size() - 1 << " more";
  }
  if (o.partner_id >= 0) os << (o.gaps.empty() ? "" : "; ") << "vehicle " << o.partner_id << "'s acceptance in force";
  os << ")";
  return os.str();
}

MonitorOutput finish_progress(MarginAccumulator acc, const Tally& tally, double grace_s) {
  if (!std::isfinite(acc.min_margin())) return acc.finish();  // never waiting in the side lane
  std::ostringstream os;
  os << "let " << tally.gaps.size() << " feasible Def. 1 gap(s) and " << tally.partners.size()
     << " Def. 2 acceptance(s) pass; a merge was offered and unused for " << tally.passed.total_s
     << " s in all, at most " << tally.passed.longest_s << " s at a stretch (grace " << grace_s
     << " s); waited " << tally.taken.longest_s << " s at most for a merge taken later";
  acc.append_detail(os.str());
  acc.add_measure("feasible_gaps_let_pass", static_cast<double>(tally.gaps.size()));
  acc.add_measure("acceptances_let_pass", static_cast<double>(tally.partners.size()));
  acc.add_measure("offered_unused_s", tally.passed.total_s);
  acc.add_measure("longest_unused_s", tally.passed.longest_s);
  acc.add_measure("longest_wait_for_taken_s", tally.taken.longest_s);
  return acc.finish();
}

}  // namespace

// Definition 1.2 counts on the gap's leader holding its speed. A leader seen braking harder than
// progress_leader_braking_mps2 does not, nor one closing on the vehicle ahead of it in its lane so
// fast that, holding its speed over rho, it would come within that vehicle's D_lon (RCPP eq. (1);
// RSS Def. 1): it must slow down for it, and the gap behind it shrinks as it does.
bool leader_holds_speed(const ObservedTrace& t, const RuleParams& p, std::size_t step, const GapIndices& gap,
                        const GapIndices& ahead, double rho_s) {
  if (gap.leader < 1) return true;
  const auto& v = t.steps[step].vehicles;
  const ObservedState& l = v[static_cast<std::size_t>(gap.leader)];
  if (l.accel_mps2 < -p.progress_leader_braking_mps2) return false;
  if (ahead.leader < 1) return true;
  const ObservedState& a = v[static_cast<std::size_t>(ahead.leader)];
  const std::size_t li = static_cast<std::size_t>(gap.leader), ai = static_cast<std::size_t>(ahead.leader);
  const double va = std::max(a.vx_mps, 0.0), vl = std::max(l.vx_mps, 0.0);
  const double a_end_m = a.x_m + speed_change_distance_m(va, 0.0, 0.0, std::max(-a.accel_mps2, 0.0), rho_s);
  const double d_lon_m = rss_longitudinal_m({vl, va, t.vehicles[li].size.length_m, t.vehicles[ai].size.length_m,
                                             t.params.rss.response_time_s, t.vehicles[li].limits.accel_max_mps2,
                                             t.vehicles[li].limits.brake_min_mps2, t.vehicles[ai].limits.brake_max_mps2});
  return a_end_m - (l.x_m + vl * rho_s) >= d_lon_m;
}

// The merge a gap's feasibility is shown with, judged along its whole duration, not only at
// rho / 2 and rho: the ego's centre follows the paper's sigmoid (RCPP §IV) in time, from its
// observed Y at the start to the target lane's centre at rho through the midpoint at rho / 2
// (the logistic of steepness c / rho, witness_steepness, cut at 0 and rho and rescaled), while
// its speed changes from the observed one toward v_e* at its declared rates. At every one of
// kWitnessSamples + 1 instants at which the ego is laterally nearer a vehicle than RCPP eq. (2)
// (the judge's lateral RSS distance, with the ego's lateral speed on the path) plus
// progress_lateral_margin_m, it must be RCPP eq. (1)'s D_lon plus progress_gap_margin_m clear of
// it: behind every vehicle ahead of it, in the target lane or the lane beyond, each kept at its
// observed speed (as Def. 1.2 takes the leader), and, until rho / 2 (P_c), ahead of every
// target-lane vehicle behind it, which may accelerate at its a_accel^max (Def. 1.1). A gap that
// ineq. (1)/(2) admit at rho / 2 and rho alone can still have the merge enter the RSS danger the
// distance rules fail on (a leader passing the ego, a vehicle of the lane beyond): the rule
// demands no merge the other rules would then fail. The lateral margin is the tracking slack a
// driven merge needs: no controller follows its reference path to the centimetre.
constexpr int kWitnessSamples = 40;

namespace {

// The paper's sigmoid starts (its heading along the road) at this fraction of the lane change, as
// RCPP's planner draws it (2 % to 98 % of W); shortest_turn_in_m starts it there too.
constexpr double kSigmoidStartFraction = 0.02;
double logit(double f) { return std::log(f / (1.0 - f)); }

// Two witnesses per duration: the logistic cut at kSigmoidStartFraction (c = 2 logit(0.98) = 2 ln 49,
// the paper's sigmoid from its 2 % point, as RCPP draws it) and a steeper one (c = 10) that crosses
// the zone of lateral closeness sooner. A flatter cut starts with a larger jump of lateral speed
// (it begins farther up the logistic) and is no merge a planner draws.
const std::array<double, 2>& witness_steepness() {
  static const std::array<double, 2> c{2.0 * logit(1.0 - kSigmoidStartFraction), 10.0};
  return c;
}

// The logistic of steepness c over u in [0, 1], centred at u = 1/2, and the rise of its cut.
struct CutLogistic {
  double c;
  double at(double u) const { return 1.0 / (1.0 + std::exp(-c * (u - 0.5))); }
  double span() const { return at(1.0) - at(0.0); }
};

// The witness's peak lateral acceleration: y'' = -y0 (c/rho)^2 l(1-l)(1-2l) / span, and
// |l(1-l)(1-2l)| peaks at 1/(6 sqrt 3) (within the cut for c > 2.6). A merge above
// progress_lat_accel_max_mps2 is not offered: a comfortable lane change is what the rule demands.
double witness_peak_lat_accel_mps2(double y0_m, double rho_s, double c) {
  return std::abs(y0_m) * c * c / (6.0 * std::sqrt(3.0) * CutLogistic{c}.span() * rho_s * rho_s);
}

}  // namespace

struct WitnessLateral {
  double y_m, vy_mps;
};
// The witness's Y and lateral speed at tau_s, of the cut logistic `logistic` with its value at
// u = 0 `l0` and its rise `span` (both constant per steepness, computed once per witness).
WitnessLateral witness_lateral(double y0_m, double rho_s, const CutLogistic& logistic, double l0, double span,
                               double tau_s) {
  const double l = logistic.at(tau_s / rho_s);
  const double frac = (l - l0) / span;
  return {y0_m * (1.0 - frac), -y0_m * logistic.c * l * (1.0 - l) / (rho_s * span)};
}

// The lateral half of a witness merge (one duration, one steepness), which does not depend on
// v_e*: the instants at which the ego on the witness path is laterally nearer a vehicle than
// RCPP eq. (2) plus progress_lateral_margin_m, with the vehicle, in instant order.
// witness_merge_clear then judges only these (instant, vehicle) pairs for each v_e*.
struct NearPair {
  int k;          // instant index, tau = rho k / kWitnessSamples
  std::size_t o;  // vehicle index
};
std::vector<NearPair> witness_near_pairs(const ObservedTrace& t, const RuleParams& p, std::size_t step, double rho,
                                         double c) {
  const auto& v = t.steps[step].vehicles;
  const ObservedState& ego = v[0];
  const Limits& el = t.vehicles[0].limits;
  const double T = t.params.rss.response_time_s;
  const CutLogistic logistic{c};
  const double l0 = logistic.at(0.0), span = logistic.span();
  std::vector<NearPair> near;
  for (int k = 0; k <= kWitnessSamples; ++k) {
    const WitnessLateral lat = witness_lateral(ego.y_m, rho, logistic, l0, span, rho * k / kWitnessSamples);
    for (std::size_t o = 1; o < v.size(); ++o) {
      const ObservedState& ov = v[o];
      const bool o_left = ov.y_m >= lat.y_m;
      const double d_lat = rss_lateral_m({o_left ? 0.0 : lat.vy_mps, o_left ? lat.vy_mps : 0.0,
                                          size_of(t, o_left ? o : 0).width_m, size_of(t, o_left ? 0 : o).width_m, T,
                                          el.lat_accel_max_mps2, el.lat_brake_min_mps2,
                                          t.params.rss.fluctuation_margin_m});
      // Written as "not clear" so that a NaN lateral distance counts as near: judged, not skipped.
      if (!(std::abs(ov.y_m - lat.y_m) >= d_lat + p.progress_lateral_margin_m)) near.push_back({k, o});
    }
  }
  return near;
}

// The longitudinal half at v_e*: at every near pair, D_lon plus progress_gap_margin_m behind a
// vehicle ahead (kept at its observed speed), and until rho / 2 ahead of a target-lane vehicle
// behind (accelerating at its a_accel^max).
bool witness_merge_clear(const ObservedTrace& t, const RuleParams& p, std::size_t step, double rho, double ve,
                         const std::vector<NearPair>& near) {
  const auto& v = t.steps[step].vehicles;
  const ObservedState& ego = v[0];
  const Limits& el = t.vehicles[0].limits;
  const double v0 = std::max(ego.vx_mps, 0.0);
  const double T = t.params.rss.response_time_s;
  const double half_lane = 0.5 * t.road.lane_width_m;
  int at_k = -1;
  double tau = 0.0, x = 0.0, ve_now = 0.0;
  for (const NearPair& n : near) {
    if (n.k != at_k) {
      at_k = n.k;
      tau = rho * n.k / kWitnessSamples;
      x = ego.x_m + speed_change_distance_m(v0, ve, el.accel_max_mps2, el.brake_min_mps2, tau);
      const double rate = ve >= v0 ? el.accel_max_mps2 : el.brake_min_mps2;
      ve_now = ve >= v0 ? std::min(ve, v0 + rate * tau) : std::max(ve, v0 - rate * tau);
    }
    const ObservedState& ov = v[n.o];
    const double vo = std::max(ov.vx_mps, 0.0);
    const double xo = ov.x_m + vo * tau;
    if (xo >= x) {  // ahead: the ego is the rear vehicle
      const double d_lon = rss_longitudinal_m({ve_now, vo, size_of(t, 0).length_m, size_of(t, n.o).length_m, T,
                                               el.accel_max_mps2, el.brake_min_mps2, limits_of(t, n.o).brake_max_mps2});
      if (xo - x < d_lon + p.progress_gap_margin_m) return false;
      continue;
    }
    const bool target_lane = std::abs(ov.y_m) < half_lane;
    if (!target_lane || tau > 0.5 * rho + kTieS) continue;  // past P_c the follower keeps D_lon
    const Limits& ol = limits_of(t, n.o);
    const double xf = ov.x_m + vo * tau + 0.5 * ol.accel_max_mps2 * tau * tau;
    const double vf = vo + ol.accel_max_mps2 * tau;
    const double d_lon = rss_longitudinal_m({vf, ve_now, size_of(t, n.o).length_m, size_of(t, 0).length_m, T,
                                             ol.accel_max_mps2, ol.brake_min_mps2, el.brake_max_mps2});
    if (x - xf < d_lon + p.progress_gap_margin_m) return false;
  }
  return true;
}

// RCPP §IV: the merge path is a sigmoid (a logistic across the lanes) driven within the sideslip
// rule, |beta| <= sideslip_max_rad, so its curvature is at most c = tan(beta_max) / l_r
// (kinematic sideslip atan(l_r c)). l_r, the centre of gravity's distance to the rear axle, is not
// declared; half the ego's length bounds it from above, so c is the smallest any car may need. A
// logistic of amplitude A (the ego's Y to the target lane's centre) and steepness kappa has peak
// curvature A kappa^2 / (6 sqrt 3) at small slopes, so the steepest within the bound has kappa =
// sqrt(6 sqrt 3 c / A). The turn-in is the X it takes from a heading along the road (its
// kSigmoidStartFraction point) to the lane line: (logit(f_line) - logit(start)) / kappa, f_line =
// (-W/2 - Y) / A. One arc of the same curvature would reach the line sooner, but it arrives
// turned across the lane and is no merge the paper's planner draws.
double shortest_turn_in_m(const ObservedTrace& t, const RuleParams& p, double y_m) {
  const double line_y = -0.5 * t.road.lane_width_m;
  const double amplitude_m = std::abs(y_m);
  if (y_m >= line_y || amplitude_m <= 0.0) return 0.0;
  const double c = std::tan(p.sideslip_max_rad) / (0.5 * t.vehicles[0].size.length_m);
  const double kappa = std::sqrt(6.0 * std::sqrt(3.0) * c / amplitude_m);
  const double f_line = (line_y - y_m) / amplitude_m;
  if (f_line <= kSigmoidStartFraction) return 0.0;
  return (logit(f_line) - logit(kSigmoidStartFraction)) / kappa;
}

// Some v_e* of the interval, its midpoint within the turn-in and the room, whose witness merge
// (witness_merge_clear, either steepness within progress_lat_accel_max_mps2) is clear along its
// whole duration.
constexpr int kWitnessSpeeds = 8;
template <class ToMid>
bool witness_exists(const ObservedTrace& t, const RuleParams& p, std::size_t step, double rho, const Def1Interval& in, const ToMid& to_mid_m, double turn_in_m, double room_m) {
  // The steepnesses within the bound depend on the duration and the ego's Y only, not on v_e*.
  std::array<bool, 2> comfortable{};
  for (std::size_t k = 0; k < comfortable.size(); ++k)
    comfortable[k] = witness_peak_lat_accel_mps2(t.steps[step].vehicles[0].y_m, rho, witness_steepness()[k]) <=
                     p.progress_lat_accel_max_mps2;
  if (!comfortable[0] && !comfortable[1]) return false;
  std::array<std::optional<std::vector<NearPair>>, 2> near;  // built when first needed
  for (int j = 0; j <= kWitnessSpeeds; ++j) {
    const double ve = in.ve_lo_mps + (in.ve_hi_mps - in.ve_lo_mps) * j / kWitnessSpeeds;
    const double mid = to_mid_m(ve);
    if (mid < turn_in_m || mid > room_m) continue;
    for (std::size_t k = 0; k < comfortable.size(); ++k) {
      if (!comfortable[k]) continue;
      if (!near[k]) near[k] = witness_near_pairs(t, p, step, rho, witness_steepness()[k]);
      if (witness_merge_clear(t, p, step, rho, ve, *near[k])) return true;
    }
  }
  return false;
}

std::vector<FeasibleMerge> def1_gaps_feasible(const ObservedTrace& t, const RuleParams& p, std::size_t step) {
  const auto& v = t.steps[step].vehicles;
  const double margin = p.progress_gap_margin_m;
  const Limits& ego = t.vehicles[0].limits;
  const double v0 = std::max(v[0].vx_mps, 0.0);
  // The midpoint (the centre on the lane line) at least the turn-in ahead, and the front still
  // `margin` short of the side lane's end there (side_lane_end).
  const double turn_in_m = shortest_turn_in_m(t, p, v[0].y_m);
  const double room_m = t.road.side_lane_end_x_m - margin - (v[0].x_m + 0.5 * t.vehicles[0].size.length_m);
  const auto id = [&](int k) { return k < 1 ? -1 : t.vehicles[static_cast<std::size_t>(k)].id; };
  std::vector<FeasibleMerge> out;
  if (room_m < turn_in_m) return out;
  const std::vector<GapIndices> gaps = lane_gaps(t, step);
  const double base_rho_s = merge_duration_base_s(p.merge_duration_s, t.road.lane_width_m, p.progress_lat_accel_max_mps2);
  for (std::size_t g = 0; g < gaps.size(); ++g) {
    const GapIndices& gap = gaps[g];
    const GapIndices ahead = g + 1 < gaps.size() ? gaps[g + 1] : GapIndices{};
    // rho_m, or longer: a merge that observably takes longer holds the right of way on a reading
    // over its own duration (rules/merge_attempts.h), and from low speed only a longer one
    // reaches a midpoint the turn-in allows. A declared rho_m shorter than the shortest
    // comfortable lane change is raised to it, as RCPP's planner raises it (core/merge_duration.h).
    for (const double rho : {base_rho_s, 1.5 * base_rho_s, 2.0 * base_rho_s}) {
      if (!leader_holds_speed(t, p, step, gap, ahead, rho)) continue;
      // def1_feasible is def1_interval's feasibility exactly, at a fraction of its bisections;
      // raising ve_lo below can only narrow the interval.
      if (!def1_feasible(t, step, gap, rho, margin)) continue;
      Def1Interval in = def1_interval(t, step, gap, rho, margin);
      in.ve_lo_mps = std::max(in.ve_lo_mps, p.progress_min_merge_speed_mps);
      if (!in.feasible()) continue;
      // Changing speed from the observed one toward v_e* (the bounded-rate model): the distance to
      // the midpoint grows with v_e*, so some v_e* of the interval fits iff its ends bracket it.
      const auto to_mid_m = [&](double ve) {
        return speed_change_distance_m(v0, ve, ego.accel_max_mps2, ego.brake_min_mps2, 0.5 * rho);
      };
      if (to_mid_m(in.ve_hi_mps) < turn_in_m || to_mid_m(in.ve_lo_mps) > room_m) continue;
      if (!witness_exists(t, p, step, rho, in, to_mid_m, turn_in_m, room_m)) continue;
      out.push_back({id(gap.follower), id(gap.leader), rho, in.ve_lo_mps, in.ve_hi_mps});
      break;
    }
  }
  return out;
}

MonitorOutput monitor_progress(const MonitorContext& ctx) {
  const ObservedTrace& t = ctx.trace;
  MarginAccumulator acc("progress", t.steps.size());
  const double grace = ctx.params.progress_grace_s;
  const std::vector<Activity> doing = activities(t, ctx.params, ctx.attempts);
  const std::vector<Acceptance> accepted = acceptances(t, ctx.params, ctx.exchanges);
  const std::vector<LaterMerge> merges = merges_taken(t, ctx.attempts);
  Tally tally;
  Stretch passing, taking;  // offers let pass; offers waited for and taken later
  double last_eval_s = -1.0;
  Offer offered, offer;
  for (std::size_t i = 0; i < t.steps.size(); ++i) {
    const ObservedStep& st = t.steps[i];
    if (doing[i] == Activity::kMerging) {
      passing.end(), taking.end();
      last_eval_s = -1.0;
      continue;
    }
    if (last_eval_s < 0.0 || st.time_s - last_eval_s >= kProgressEvalS - kTieS) {
      offered = offer_at(ctx, accepted, i);
      offer = let_pass(offered, merges, i);
      last_eval_s = st.time_s;
    }
    // Busy with the RSS proper response: waiting is what the ego should do.
    const bool responding = ego_rear_in_rss_danger(ctx, i);
    const bool idle = doing[i] == Activity::kWaiting && !adjusting_speed(ego_of(st), offered);
    const double dt = i > 0 ? st.time_s - t.steps[i - 1].time_s : 0.0;
    taking.step(offered.any() && !offer.any() && !responding, idle, st.time_s, dt, tally.taken);
    if (!offer.any() || responding) {
      passing.end();
      acc.record(i, st.time_s, grace, Party::ego(), grace, 0.0);
      continue;
    }
    passing.step(true, idle, st.time_s, dt, tally.passed);
    note(tally, offer);
    if (acc.record(i, st.time_s, grace - passing.unused_s, Party::ego(), grace, passing.unused_s))
      acc.set_detail(violation_text(passing.unused_s, passing.start_s, st, offer));
  }
  return finish_progress(std::move(acc), tally, grace);
}

}  // namespace mg
