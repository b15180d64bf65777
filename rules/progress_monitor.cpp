#include "rules/progress_monitor.h"

#include <algorithm>
#include <optional>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "core/merge_duration.h"
#include "rules/acceptance_cover.h"
#include "rules/declared_limits_monitor.h"
#include "rules/coop_exchange.h"
#include "rules/definition2_inequalities.h"
#include "rules/definition1_gap.h"
#include "rules/feasible_gaps.h"

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

// The first step of the last rho_b of an approach toward the main lane (v_Y > 0 at every step)
// still under way at the trace's last step, outside any attempt, past the side lane's centre or
// below it still moving toward the main lane faster than lat_speed_hysteresis_mps: the clock
// pauses from there. Whether the approach leads into a start the trace does not show,
// and the rule does not accuse the ego of letting a gap pass on what the trace does not hold: a
// merge of any duration the rule offers (up to 3 rho_b) begun within the last rho_b would not yet
// have reached its midpoint (at rho / 2), and an unbroken approach cannot tell a drift from the
// merge that follows it. Before the last rho_b the clock runs: an ego that drifts toward the lane
// without ever merging is judged on all but the last rho_b of the trace.
std::optional<std::size_t> censored_approach_start(const ObservedTrace& t, const RuleParams& p,
                                                   const MergeAttempts& attempts) {
  if (t.steps.empty()) return std::nullopt;
  const std::size_t last = t.steps.size() - 1;
  for (const MergeAttempt& a : attempts.attempts)
    if (!a.end_time_s) return std::nullopt;  // in an attempt at the end: judged as such
  // Past the side lane's centre at the end, or below it and moving toward the main lane beyond
  // drift: an ego settling on its centre from below moves toward the main lane too, and would
  // otherwise always have an approach under way, but it slows as it nears the centre. A merge
  // from below the centre (an ego halted off it) crosses it on its way, and a slow one may not
  // have reached it when the trace ends.
  const ObservedState& end = ego_of(t.steps[last]);
  if (!(end.y_m > t.road.side_lane_y_m()) && !(end.vy_mps > p.lat_speed_hysteresis_mps)) return std::nullopt;
  std::size_t first = last + 1;
  while (first > 0 && ego_of(t.steps[first - 1]).vy_mps > 0.0) --first;
  if (!attempts.attempts.empty()) first = std::max(first, step_at(t, *attempts.attempts.back().end_time_s) + 1);
  const double rho_b_s = merge_duration_base_s(p.merge_duration_s, t.road.lane_width_m, p.progress_lat_accel_max_mps2);
  while (first <= last && t.steps[last].time_s - t.steps[first].time_s > rho_b_s + kTieS) ++first;
  if (first > last) return std::nullopt;
  return first;
}

// Whether a vehicle other than the ego is seen beyond its declared limits at step i.
bool other_beyond_limits(const ObservedTrace& t, const RuleParams& p, std::size_t i) {
  for (std::size_t k = 1; k < t.vehicles.size(); ++k)
    if (beyond_declared_limits(t, p, i, k)) return true;
  return false;
}

// An attempt is a merge once the ego's body reaches into the main lane (its entry): from its start
// to its end, the ego is merging (until the attempt is overdue: 1.5 rho_b after its start, where
// the longest merge offered has its midpoint, it is judged as one that never entered), and an
// offer it lets pass after that begins a new run. Before
// the entry, and in an attempt that never enters, the clock pauses while the ego moves toward the
// main lane (v_Y > lat_speed_hysteresis_mps) and runs otherwise: a planner that aborts and tries
// again loses no credit for its outward motion, one that drifts out and back, or stalls off its
// lane centre, keeps the clock running on the way back and while it stalls. The unbroken lateral
// approach that led into a start (v_Y > 0, however slow: a long sigmoid leaves its lane centre
// gently) pauses the clock too: the merge began there. An approach still unbroken at the trace's
// last step, outside an attempt, may lead into a start the trace ended before: its last rho_b
// pauses the clock (censored_approach_start). So does the part past the side lane's centre of an
// approach under way when another vehicle is seen beyond its declared limits, up to that step:
// the merge it may have led into rested on those limits, and the ego that drops it then is
// responding to the breach (declared_limits holds that vehicle liable), not letting a gap pass.
// (Past the centre, as for the censored approach: an ego settling on its centre from below moves
// toward the main lane too, for as long as it likes.)
std::vector<Activity> activities(const ObservedTrace& t, const RuleParams& p, const MergeAttempts& attempts) {
  std::vector<Activity> out(t.steps.size(), Activity::kWaiting);
  const double line_y = -0.5 * t.road.lane_width_m;
  // The longest merge the rule offers (3 rho_b) reaches its midpoint 1.5 rho_b after it begins: an
  // attempt whose centre is still in the side lane later than that is overdue, and from then on
  // its entry no longer makes it a merge (an ego straddling the lane line with a corner of its
  // body, never going on, would otherwise be merging for ever).
  const double overdue_after_s =
      1.5 * merge_duration_base_s(p.merge_duration_s, t.road.lane_width_m, p.progress_lat_accel_max_mps2);
  if (const auto from = censored_approach_start(t, p, attempts))
    for (std::size_t i = *from; i < out.size(); ++i) out[i] = Activity::kPaused;
  for (const MergeAttempt& a : attempts.attempts) {
    for (std::size_t i = a.start_step; i > 0 && ego_of(t.steps[i - 1]).vy_mps > 0.0; --i)
      if (out[i - 1] == Activity::kWaiting) out[i - 1] = Activity::kPaused;
    const std::size_t end = a.end_time_s ? step_at(t, *a.end_time_s) : t.steps.size() - 1;
    for (std::size_t i = a.start_step; i <= end && i < out.size(); ++i) {
      const bool overdue = t.steps[i].time_s > a.start_time_s + overdue_after_s + kTieS;
      if (a.entry_step && !overdue) out[i] = Activity::kMerging;
      else if (ego_of(t.steps[i]).vy_mps > p.lat_speed_hysteresis_mps) out[i] = Activity::kPaused;
    }
  }
  const auto approaching = [&](std::size_t i) {
    return ego_of(t.steps[i]).vy_mps > 0.0 && ego_of(t.steps[i]).y_m > t.road.side_lane_y_m();
  };
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!approaching(i) || !other_beyond_limits(t, p, i)) continue;
    for (std::size_t j = i + 1; j > 0 && approaching(j - 1); --j)
      if (out[j - 1] == Activity::kWaiting) out[j - 1] = Activity::kPaused;
  }
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!(ego_of(t.steps[i]).y_m < line_y)) out[i] = Activity::kMerging;
  return out;
}

// A Definition 2 acceptance in force: delivered to the ego within [t_r, t_r + rho_c] (a later one
// grants nothing, Def. 2.3), from [delivery, t_r + rho_c + rho_m] (the cooperation's span,
// def2_1b_responder's window), and only when the gap's other vehicle leaves room for it
// (other_gap_vehicle_clear, as for the right of way). An acceptance its sender does not keep
// (beyond def2_positions' bound at some step of that span: responder_broke_acceptance) offers
// nothing: the merge it promised never existed, and an ego that drops it, or never takes it up,
// is waiting for a reason (the responder rules hold the sender liable).
struct Acceptance {
  const CoopExchange* exchange = nullptr;
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
    const double to_s = x.request_time_s + p.comm_threshold_s + p.merge_duration_s;
    const int k = t.index_of(x.request->to_id);
    if (k >= 1 && responder_broke_acceptance(t, p, x, static_cast<std::size_t>(k), to_s)) continue;
    out.push_back({&x, x.request->to_id, x.request->coop_case == CoopCase::kEgoAhead, d, to_s});
  }
  return out;
}

// What is offered to the ego at one evaluation.
struct Offer {
  std::vector<FeasibleMerge> gaps;
  int partner_id = -1;  // an acceptance in force, or -1
  bool any() const { return !gaps.empty() || partner_id >= 0; }
};

// An acceptance offers the merge it was asked for only while the gap's other vehicle (2.1: the
// one ahead of the partner; 2.2: the one behind it) still leaves room for it: Definition 1 for
// that pair (ineq. (1.2), resp. (1.1)) holds for a merge of rho begun now at the ego's observed
// speed (Def. 2.1 and 2.2 keep the ego's speed once the request is answered), and, in 2.1, that
// vehicle holds its speed as a Definition 1 gap's leader must (leader_holds_speed: braking no
// harder than progress_leader_braking_mps2, and not closing on the vehicle ahead of it so fast
// that it must slow down for it). The check at the request (other_gap_vehicle_clear) says the
// merge was possible then; a vehicle ahead that braked since, or that must brake for a vehicle
// stopped ahead of it, has shrunk the gap the request counted on, and an ego that drops the merge
// is waiting for a reason.
bool other_vehicle_leaves_room(const ObservedTrace& t, const RuleParams& p, const Acceptance& a, std::size_t i,
                               double rho_s) {
  const int partner = t.index_of(a.partner_id);
  const double v_e = std::max(0.0, ego_of(t.steps[i]).vx_mps);
  const std::vector<GapIndices> gaps = lane_gaps(t, i);
  for (std::size_t k = 0; k < gaps.size(); ++k) {
    const GapIndices& g = gaps[k];
    if (a.ego_ahead && g.follower == partner) {
      if (g.leader < 1) return true;
      if (!leader_holds_speed(t, p, i, gaps, k, rho_s)) return false;
      return def1_2_margin_m(t, i, g.leader, v_e, rho_s) >= 0.0;
    }
    if (!a.ego_ahead && g.leader == partner) return def1_1_margin_m(t, i, g.follower, v_e, rho_s) >= 0.0;
  }
  return true;
}

// ... and only while the sender itself still leaves room for it: a merge begun now at the ego's
// observed speed (held, as Def. 2 holds it) reaches its midpoint rho / 2 later outside the sender's
// RSS distance (RCPP eq. (1); 2.1: the sender behind, 2.2: ahead), the sender on the profile it
// accepted (toward v_o* by t_r + rho_c, as def2_positions and sigmoid_pc_bounds predict it), at v_o*
// past the acceptance's span. An ego that slowed, or let the sender close in, until a merge would
// end inside its safe distance (sigmoid_pc_bounds, the ego's) has no merge left on it.
bool partner_leaves_room(const ObservedTrace& t, const RuleParams& p, const Acceptance& a, std::size_t i, double rho_s) {
  const int k = t.index_of(a.partner_id);
  if (k < 1) return false;
  const std::size_t ko = static_cast<std::size_t>(k);
  const double t_mid = t.steps[i].time_s + 0.5 * rho_s;
  const double t_profile = std::min(t_mid, a.to_s);
  const ProfileBound b = accepted_profile_bound(t, p, *a.exchange, ko, t_profile);
  if (!b.valid) return false;
  const double v_o = std::max(0.0, b.profile_v_mps);
  const double x_o = b.profile_x_m + v_o * (t_mid - t_profile);
  const ObservedState& ego = ego_of(t.steps[i]);
  const double v_e = std::max(0.0, ego.vx_mps);
  const double x_e = ego.x_m + v_e * 0.5 * rho_s;
  return a.ego_ahead ? x_e - x_o >= d_lon_m(t, ko, v_o, 0, v_e) : x_o - x_e >= d_lon_m(t, 0, v_e, ko, v_o);
}

Offer offer_at(const MonitorContext& ctx, const std::vector<Acceptance>& accepted, std::size_t i) {
  Offer o;
  o.gaps = def1_gaps_feasible(ctx.trace, ctx.params, i);
  const double now = ctx.trace.steps[i].time_s;
  // The shortest comfortable lane change, as for a Definition 1 gap (feasible_gaps.cpp).
  const double rho_s = merge_duration_base_s(ctx.params.merge_duration_s, ctx.trace.road.lane_width_m,
                                             ctx.params.progress_lat_accel_max_mps2);
  for (const Acceptance& a : accepted)
    if (now >= a.from_s - kTieS && now <= a.to_s + kTieS && other_vehicle_leaves_room(ctx.trace, ctx.params, a, i, rho_s) &&
        partner_leaves_room(ctx.trace, ctx.params, a, i, rho_s))
      o.partner_id = a.partner_id;
  return o;
}

// An approach toward the main lane (v_Y > 0 at every step, outside any attempt) that reached past
// merge_start_offset_m off the side lane's centre and then stopped short of a start, at a step at
// which nothing was offered any more, pauses the clock over its length: a long merge leaves its
// lane centre more slowly than lat_speed_hysteresis_mps at first, and one dropped because its gap
// closed (a leader braking harder than Def. 1.2 assumes) was a merge under way, not a wait. One
// dropped while a merge is still offered is not: the clock runs over it, so that an ego that
// drifts out and back never merging gains nothing from the drift.
void pause_dropped_approaches(const MonitorContext& ctx, const std::vector<Acceptance>& accepted,
                              std::vector<Activity>& doing) {
  const ObservedTrace& t = ctx.trace;
  const double past_y = t.road.side_lane_y_m() + ctx.params.merge_start_offset_m;
  std::size_t from = 0;  // the first step of the approach under way
  for (std::size_t i = 0; i < t.steps.size(); ++i) {
    const ObservedState& e = ego_of(t.steps[i]);
    if (e.vy_mps > 0.0 && doing[i] == Activity::kWaiting) continue;
    const bool dropped = i > from && doing[i] == Activity::kWaiting && ego_of(t.steps[i - 1]).y_m > past_y;
    if (dropped && !offer_at(ctx, accepted, i).any())
      for (std::size_t j = from; j < i; ++j) doing[j] = Activity::kPaused;
    from = i + 1;
  }
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

MonitorOutput monitor_progress(const MonitorContext& ctx) {
  const ObservedTrace& t = ctx.trace;
  MarginAccumulator acc("progress", t.steps.size());
  const double grace = ctx.params.progress_grace_s;
  std::vector<Activity> doing = activities(t, ctx.params, ctx.attempts);
  const std::vector<Acceptance> accepted = acceptances(t, ctx.params, ctx.exchanges);
  pause_dropped_approaches(ctx, accepted, doing);
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
