#include "planner/rcpp_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/fixed_text.h"
#include "planner/definition1_search.h"
#include "planner/rcpp_world.h"
#include "planner/rss_override.h"
#include "planner/sigmoid.h"
#include "planner/world_view.h"

namespace mg {
namespace {

constexpr double kRetryAfterRhoC = 3.0;  // a refused/silent partner may be asked again after 3 rho_c
// Times k dt and t_r + rho_c that are the same instant differ by rounding (~1e-15 s).
constexpr double kDeadlineTieS = 1e-9;
// After an abort the ego holds the side lane this long before it plans a new merge: re-planning
// at once, every cycle, against a leader that keeps braking would weave (docs/planner.md).
constexpr double kMergeRetryAfterAbortS = 1.0;
// Half the judge's default merge start offset (rules.merge_start_offset_m): an ego that moved less
// toward the lane has begun no attempt the judge sees.
constexpr double kUnmovedAbortM = 0.05;
constexpr double kLongerMergeEveryS = 0.5;
// Below this speed a merge is not deferred for the way back to the side lane's centre
// (back_to_centre): the ego hardly moves sideways any more.
constexpr double kBackToCentreMinSpeedMps = 1.0;

// The merge keeps the ego's offset toward the main lane (from_hold) after a hold, and for an ego
// that starts off its lane centre toward the main lane and is not on its way back from an abort:
// steering back to the centre first took it away from the gap it had just chosen, for seconds,
// while the gap stayed open (progress; a campaign finding). On the way back from an abort the
// sigmoid is followed (committed_merge.h).
CommittedMerge commit(const InSideLane& side, const WorldSnapshot& w, const Sigmoid& sig, double speed_mps,
                      RcppDecision d) {
  const bool keep_offset = side.lateral.hold_y_m.has_value() || !side.lateral.return_path;
  return CommittedMerge{sig, speed_mps, std::move(d), std::max(w.ego.y_m, sig.offset_m), keep_offset};
}

// The merge a Definition 1 plan starts. An ego whose lateral speed last pointed toward the main
// lane and whose new path lies below it keeps its offset instead (as after a hold): turning away
// and back toward the lane would reverse its lateral speed twice (smoothness_oscillation; a
// campaign finding), and the occupancy check already took the ego as no farther from the main
// lane than it is.
CommittedMerge start_def1_merge(const InSideLane& side, const WorldSnapshot& w, const Def1Plan& plan,
                                const ReversalLedger& ledger) {
  CommittedMerge m = commit(side, w, plan.sigmoid, plan.ve_star_mps, plan.decision);
  if (ledger.last_moved_out() && turns_away_first(m, w)) m.from_hold = true;
  return m;
}

constexpr double kCentredOffsetM = 0.1;  // keep_main_lane: settled within this of the lane centre
constexpr double kSettleCreepMps = 0.5;  // ... and crawling at least this fast until then

RcppCycle keep_main_lane(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const double lane_w = s.road.lane_width_m;
  const double lane_y = std::max(0.0, std::round(w.ego.y_m / lane_w)) * lane_w;
  RcppCycle out;
  out.path = sample_straight(lane_y, w.ego.x_m - kPathBehindM, w.ego.x_m + tracked_path_ahead_m(w), kPathStepM);
  double target = s.road.speed_limit_mps;
  std::string reason = "lane keeping at the speed limit";
  for (const ObservedVehicle& o : w.others) {  // nearest vehicle ahead in the ego's lane
    if (std::abs(o.state.y_m - lane_y) >= 0.5 * lane_w || o.state.x_m <= w.ego.x_m) continue;
    const double v = rss_follow_speed_mps(w, to_lane_vehicle(o));
    if (v < target) {
      target = v;
      reason = "lane keeping, RSS following of vehicle " + std::to_string(o.id);
    }
  }
  // After a crawl merge the ego is still turned toward its lane and tracked behind its path (the
  // crawl's curvature is beyond what the tracker steers at any speed): it first settles at the
  // lane centre at its crawl speed. Accelerating at once, it overshot the centre by 0.3 m and
  // came back at speed, a third lateral-speed reversal of one approach (smoothness_oscillation;
  // a campaign finding).
  const double v = ego_speed_mps(w);
  const bool settled = std::abs(w.ego.yaw_rad) <= kSettledYawRad && std::abs(w.ego.y_m - lane_y) <= kCentredOffsetM;
  if (v <= crawl_speed_mps(s) && !settled && target > v) {
    target = std::max(v, kSettleCreepMps);
    reason += ", at a crawl until settled at the lane centre";
  }
  out.target_speed_mps = target;
  out.accel_limit_mps2 = accel_limit_toward(s, v, target);
  out.decision.time_s = w.time_s;
  out.decision.mode = DecisionMode::kMerged;
  out.decision.reason = reason;
  return out;
}

// Definition 1.3's halt: where the ego stops, the speed cap that stops it there, and the braking
// it may use: beyond b_min, up to b_max, once b_min no longer stops its front before the end
// (brake_limit_mps2); the halt itself also once b_min no longer stops it at the halt point, with
// kHaltBrakeSlack for the speed controller's lag (halt_brake_mps2). The halt point leaves the
// room a merge from standstill needs; an ego braking at b_min from speed came to rest metres
// past it, too near the end to merge from there, and waited while the gap behind it stayed open
// (`progress`; a campaign finding). An ego waiting for a reply keeps to its request's profile.
constexpr double kHaltBrakeSlack = 1.1;
struct HaltProfile {
  double halt_x_m = 0.0;
  double halt_cap_mps = 0.0;
  double needed_mps2 = 0.0;
  double brake_limit_mps2 = 0.0;
  double halt_brake_mps2 = 0.0;
};

HaltProfile halt_profile(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const double v_e = ego_speed_mps(w);
  HaltProfile h;
  h.halt_x_m = halt_point_x_m(s.road, s.params.planner.halt_margin_m, s.ego.size.length_m, standstill_merge_length_m(s));
  h.halt_cap_mps = halt_speed_cap_mps(w.ego.x_m, h.halt_x_m, 0.5 * s.ego.limits.brake_min_mps2);
  const double room_m = s.road.side_lane_end_x_m - 0.5 * s.ego.size.length_m - w.ego.x_m;
  h.needed_mps2 = room_m > 0.0 ? v_e * v_e / (2.0 * room_m) : s.ego.limits.brake_max_mps2;
  h.brake_limit_mps2 =
      h.needed_mps2 > 0.8 * s.ego.limits.brake_min_mps2 ? s.ego.limits.brake_max_mps2 : s.ego.limits.brake_min_mps2;
  const double to_halt_m = h.halt_x_m - w.ego.x_m;
  const double to_halt_mps2 = to_halt_m > 0.0 ? kHaltBrakeSlack * v_e * v_e / (2.0 * to_halt_m) : 0.0;
  h.halt_brake_mps2 = std::max(h.brake_limit_mps2, std::min(s.ego.limits.brake_max_mps2, to_halt_mps2));
  return h;
}

// Holding the side lane after an abort, until no_merge_before_s.
RcppCycle hold_after_abort(const InSideLane& side, const WorldSnapshot& w, const HaltProfile& h,
                            std::vector<PathPoint> path, const std::string& note) {
  RcppCycle out;
  out.path = std::move(path);
  out.target_speed_mps = std::min(ego_speed_mps(w), h.halt_cap_mps);
  // b_max only when b_min could no longer stop the ego before the side lane's end (an abort at
  // b_max's halt distance, merge_should_abort).
  const Limits& el = w.setup->ego.limits;
  out.accel_limit_mps2 = h.needed_mps2 > el.brake_min_mps2 ? el.brake_max_mps2 : el.brake_min_mps2;
  out.decision.time_s = w.time_s;
  out.decision.mode = DecisionMode::kDef1Halt;
  out.decision.reason = note + "holding the side lane after an aborted merge until t = " +
                        fixed_text(side.no_merge_before_s, 2) + " s, then re-evaluating";
  return out;
}

// A request's P_c assumes Def. 2's speed profile over rho_c (2.1: v_e held; 2.2: b_min down to
// v_e - b_min rho_c). Whether the ego can keep it until deadline_s and still stop before the side
// lane's end at b_min from where it then is (holding v_e, which 2.2's braking only shortens), with
// rho_c of travel in hand.
bool request_profile_can_halt(const WorldSnapshot& w, double deadline_s) {
  const PlannerSetup& s = *w.setup;
  const double v_e = ego_speed_mps(w);
  const double at_deadline_x = w.ego.x_m + v_e * std::max(0.0, deadline_s - w.time_s);
  const double room_after_m = s.road.side_lane_end_x_m - 0.5 * s.ego.size.length_m - at_deadline_x -
                              v_e * s.params.planner.comm_threshold_s;
  return room_after_m > 0.0 && v_e * v_e / (2.0 * s.ego.limits.brake_min_mps2) < room_after_m;
}

// Waiting for the answer to an open request: the speed profile its P_c assumes. The comfortable
// halt profile left a braking ego behind its own P_c, inside the partner's safe distance at the
// midpoint, so it applies only once the profile could no longer be kept (request_profile_can_halt;
// send_request sends no 2.1 request whose profile cannot be kept from the start).
void wait_for_reply(const PendingRequest& pending, const WorldSnapshot& w, const HaltProfile& h, RcppCycle& out) {
  const PlannerSetup& s = *w.setup;
  const double v_e = ego_speed_mps(w);
  const bool profile_can_halt = request_profile_can_halt(w, pending.deadline_s);
  out.target_speed_mps = profile_can_halt ? pending.plan.ego_speed_after_mps
                                          : std::min(pending.plan.ego_speed_after_mps, h.halt_cap_mps);
  // Def. 2.2A: while its request is open the ego brakes at most b_min (ineq. (4) counts on
  // it), so b_max only when b_min could no longer stop it before the side lane's end.
  const bool ego_behind = pending.plan.vo.coop_case == CoopCase::kEgoBehind;
  const double pending_brake =
      ego_behind && h.needed_mps2 <= s.ego.limits.brake_min_mps2 ? s.ego.limits.brake_min_mps2 : h.brake_limit_mps2;
  out.accel_limit_mps2 = std::max(pending_brake, accel_limit_toward(s, v_e, out.target_speed_mps));
  out.decision = pending.plan.decision;
  if (out.outbox.empty())
    out.decision.reason = "waiting for vehicle " + std::to_string(pending.plan.partner.id) + " until t = " +
                          fixed_text(pending.deadline_s, 2) + " s: " + out.decision.reason;
  out.decision.time_s = w.time_s;
}

// Def. 1.3 asks for a halt before the side lane's end, not at once: an ego slower than the
// standstill-merge speed rolls on toward the halt point at that speed (within the halt cap).
// One at rest far from the end stayed there, while the gap ahead of a stopped follower, open
// to anyone under way, was not to an ego that had to merge within rho of standing still
// (progress; a campaign finding).
void halt(const WorldSnapshot& w, const HaltProfile& h, const std::string& why, const std::string& note,
          RcppCycle& out) {
  const double v_e = ego_speed_mps(w);
  out.target_speed_mps = std::min(std::max(v_e, kStandstillMergeSpeedMps), h.halt_cap_mps);
  out.accel_limit_mps2 = std::max(h.halt_brake_mps2, accel_limit_toward(*w.setup, v_e, out.target_speed_mps));
  out.decision.time_s = w.time_s;
  out.decision.mode = DecisionMode::kDef1Halt;
  out.decision.reason = note + "Def. 1.3: no feasible gap (" + why + "); braking to halt by x = " +
                        fixed_text(h.halt_x_m, 1) + " m and re-evaluating";
}

// A merge the smoothness rule could no longer afford to abort (planner/reversal_ledger.h) waits
// while the ego goes back to its side-lane centre, as after an abort, with the halt's speed
// profile; a lateral hold off the centre is given up for the way back. The way back aims
// kDeferredReturnPastCentreM beyond the centre: the rule credits a new approach only once the ego
// was within merge_abort_offset_m of the centre, which a return path ending on the centre crosses
// in its flat tail; the tracker, lagging the path, reached its end a decimetre short, and the
// gentle return planned from there covered the rest at 0.03 m/s: an ego 0.6 m off the centre
// took 4 s to get back while the gap it waited for stayed open (progress; a campaign finding).
// The return path under way is re-planned once toward that point.
RcppCycle back_to_centre(InSideLane& side, const WorldSnapshot& w, const HaltProfile& h, const ReversalLedger& ledger,
                         bool turns_away, const std::string& note) {
  side.lateral.hold_y_m.reset();
  side.lateral.hold_pending = false;
  if (side.lateral.past_centre_m != kDeferredReturnPastCentreM) side.lateral.return_path.reset();
  side.lateral.past_centre_m = kDeferredReturnPastCentreM;
  RcppCycle out;
  out.path = side_lane_path(side.lateral, w);
  halt(w, h, "", note, out);
  out.decision.reason = note + reversal_deferral_reason(ledger, turns_away);
  return out;
}

// Def. 2.2A binds the ego to braking at most b_min for rho_c after a Def. 2.2 request (ineq. (4)
// counts on it), also after it gave up waiting for the answer (a Def. 1 merge decided meanwhile,
// then aborted): the responder may still accept and speed up. A hold or halt in that window
// brakes at b_min unless b_min could no longer stop the ego before the side lane's end
// (can_still_halt): a halt at b_max just before the deadline, with the end still far away, broke
// Def. 2.2A (a campaign finding).
void keep_request_braking(const WorldSnapshot& w, double until_s, RcppCycle& out) {
  const double b_min = w.setup->ego.limits.brake_min_mps2;
  if (w.time_s > until_s + kDeadlineTieS || out.target_speed_mps >= ego_speed_mps(w) ||
      out.accel_limit_mps2 <= b_min)
    return;
  if (can_still_halt(w)) out.accel_limit_mps2 = b_min;
}

}  // namespace

PlanOutput RcppPlanner::plan(const WorldSnapshot& observed) {
  const WorldSnapshot w = braking_.apply(observed);
  reversals_.observe(w);
  const std::string note = advance_phase(w);
  RcppCycle out;
  if (auto* side = std::get_if<InSideLane>(&phase_)) {
    SideLaneStep step = decide_in_side_lane(*side, w);
    if (step.merge) {
      phase_ = Merging{std::move(*step.merge)};
      out = follow_merge(std::get<Merging>(phase_).merge, w);
    } else {
      out = std::move(step.out);
      // While the request is awaited, wait_for_reply keeps Def. 2.2A itself.
      if (!side->pending) keep_request_braking(w, ego_behind_request_until_s_, out);
    }
  } else if (auto* merging = std::get_if<Merging>(&phase_)) {
    take_sooner_merge(*merging, w);
    take_faster_merge(*merging, w);
    out = follow_merge(merging->merge, w);
  } else {
    out = keep_main_lane(w);
  }
  if (!note.empty()) out.decision.reason = note + out.decision.reason;
  apply_proper_response(w, out);
  return to_command(std::move(out));
}

std::string RcppPlanner::advance_phase(const WorldSnapshot& w) {
  // Already in the main lane (a start there); not an ego on its way back after an abort.
  if (const auto* side = std::get_if<InSideLane>(&phase_);
      side && !side->lateral.return_path && w.ego.y_m > -0.5 * w.setup->road.lane_width_m) {
    phase_ = InMainLane{};
    return "";
  }
  auto* merging = std::get_if<Merging>(&phase_);
  if (!merging) return "";
  if (merge_complete(merging->merge, w)) {
    phase_ = InMainLane{};
    return "";
  }
  if (!merge_should_abort(merging->merge, w) || replan_in_place(*merging, w)) return "";
  InSideLane side;
  side.lateral = lateral_after_abort(w);
  // A Definition 1 merge aborted before the ego moved toward the lane leaves nothing to weave: it
  // may plan again at once. (Most such aborts come on the second cycle, when the other vehicles'
  // accelerations are first seen; a hold then let the gap the rule offers go, `progress`.) After
  // a cooperative merge the hold stays: asking a partner that has just broken its acceptance again
  // at once put the ego in its lane without the right of way.
  const CommittedMerge& aborted = merging->merge;
  forget_broken_acceptance(aborted, w);
  const bool unmoved = aborted.decision.mode == DecisionMode::kDef1Merge && w.ego.y_m - aborted.start_y_m <= kUnmovedAbortM;
  side.no_merge_before_s = unmoved ? w.time_s : w.time_s + kMergeRetryAfterAbortS;
  phase_ = std::move(side);
  return "merge aborted (P_c bounds crossed or lane occupied at the predicted positions); ";
}

// A cooperative merge aborted with its partner driving on the wrong side of the v_o* it accepted:
// that partner is not asked again, nor its acceptance merged on again (a reneging partner that
// accepted a second request drove into the ego merging on it; a campaign finding).
void RcppPlanner::forget_broken_acceptance(const CommittedMerge& aborted, const WorldSnapshot& w) {
  if (aborted.decision.mode != DecisionMode::kDef2Merge || !held_ || held_->partner_id != aborted.decision.coop_partner_id)
    return;
  for (const ObservedVehicle& o : w.others) {
    if (o.id != held_->partner_id || !responder_breaks_acceptance(w, *held_, to_lane_vehicle(o))) continue;
    retry_after_s_[o.id] = std::numeric_limits<double>::infinity();
    held_.reset();
    return;
  }
}

std::optional<CommittedMerge> RcppPlanner::read_reply(InSideLane& side, const WorldSnapshot& w, std::string& note) {
  if (!side.pending) return std::nullopt;
  const PendingRequest& pending = *side.pending;
  const int partner = pending.plan.partner.id;
  for (const V2vMessage& m : w.inbox) {
    if (m.to_id != 0 || m.from_id != partner || m.sent_time_s < pending.plan.decision.time_s) continue;
    // Def. 2.3: only an acceptance delivered within rho_c counts (the planner reads its inbox
    // once a cycle, so one delivered after the deadline may still be read before the next).
    const double delivered_s = std::isnan(m.delivered_time_s) ? w.time_s : m.delivered_time_s;
    if (m.type == MessageType::kAccept && delivered_s <= pending.deadline_s + kDeadlineTieS) {
      const Def2Plan& asked = pending.plan;
      const double bound_until_s =
          asked.decision.time_s + w.setup->params.planner.comm_threshold_s + w.setup->params.planner.merge_duration_s;
      const double yield_by_s = yield_deadline_s(*w.setup, asked.decision.time_s);
      held_ = HeldAcceptance{partner,     asked.vo.coop_case, asked.vo.vo_star_mps, asked.vo.d_lon_star_m, asked.vo.pc_m,
                             delivered_s, yield_by_s,         bound_until_s};
      // The partner now cooperates and refuses any new request while bound (a merge aborted on its
      // acceptance is made again on it instead).
      retry_after_s_[partner] = std::max(retry_after_s_[partner], bound_until_s);
      RcppDecision d = pending.plan.decision;
      d.mode = DecisionMode::kDef2Merge;
      d.reason = "vehicle " + std::to_string(partner) + " accepted: " + d.reason;
      const Def2Plan plan = pending.plan;
      side.pending.reset();
      return commit(side, w, plan.sigmoid, plan.ego_speed_after_mps, std::move(d));
    }
    if (m.type == MessageType::kRefuse) {
      note = "Def. 2.3: vehicle " + std::to_string(partner) + " refused; ";
      ego_behind_request_until_s_ = -1.0;  // a refusal ends Def. 2.2A's window
    }
  }
  if (note.empty() && w.time_s > pending.deadline_s)
    note = "Def. 2.3: no acceptance from vehicle " + std::to_string(partner) + " within rho_c; ";
  if (!note.empty()) {
    retry_after_s_[partner] = w.time_s + kRetryAfterRhoC * w.setup->params.planner.comm_threshold_s;
    side.pending.reset();
  }
  return std::nullopt;
}

void RcppPlanner::send_request(InSideLane& side, const WorldSnapshot& w, RcppCycle& out, std::string& note) {
  if (side.pending || !cooperative_ || !w.setup->ego.v2v.capable) return;
  auto plan = plan_definition2(w, retry_after_s_);
  if (!plan) return;
  // A 2.1 request (ego ahead, v_e held) whose profile the ego could not keep and still halt would
  // have it brake while it waits, behind the P_c it asked for: such a merge ended inside the
  // partner's safe distance at the midpoint (sigmoid_pc_bounds; a campaign finding). The ego halts
  // instead. A 2.2 request's profile brakes at b_min from the start, and binds the ego to b_min
  // (Def. 2.2A): none is sent once b_min could no longer stop it before the side lane's end (after
  // an abort at b_max's halt distance, merge_should_abort, the halt braked harder: def2_2a_ego_brake).
  const double deadline_s = w.time_s + w.setup->params.planner.comm_threshold_s;
  if (plan->vo.coop_case == CoopCase::kEgoAhead && !request_profile_can_halt(w, deadline_s)) return;
  if (plan->vo.coop_case == CoopCase::kEgoBehind && !can_still_halt(w)) return;
  V2vMessage req;
  req.type = MessageType::kRequest;
  req.from_id = 0;
  req.to_id = plan->partner.id;
  req.sent_time_s = w.time_s;
  req.coop_case = plan->vo.coop_case;
  req.pc_m = plan->vo.pc_m;
  req.d_lon_star_m = plan->vo.d_lon_star_m;
  req.target_speed_mps = plan->vo.vo_star_mps;
  out.outbox.push_back(req);
  plan->decision.reason = note + plan->decision.reason;
  note.clear();
  side.pending = PendingRequest{std::move(*plan), deadline_s};
  if (side.pending->plan.vo.coop_case == CoopCase::kEgoBehind) ego_behind_request_until_s_ = side.pending->deadline_s;
}

// The weaving budget (planner/reversal_ledger.h) defers a merge, its path first turning away from
// the main lane or not. An open request keeps its own profile (wait_for_reply); its acceptance is
// the merge it asked for. An ego too slow to steer back to its centre is not held: it would wait
// there for ever while the gap stayed open (progress).
bool RcppPlanner::defers_merge(const InSideLane& side, const WorldSnapshot& w, bool turns_away) const {
  return !side.pending && ego_speed_mps(w) >= kBackToCentreMinSpeedMps && !reversals_.can_afford_merge(turns_away);
}

// The paper's order: an answer to an open request, Definition 1 at rho_m, a Definition 2
// request, Definition 1 at the longer durations, and Definition 1.3's halt; before and after each
// Definition 1 search, the weaving budget may send the ego back to its centre first.
RcppPlanner::SideLaneStep RcppPlanner::decide_in_side_lane(InSideLane& side, const WorldSnapshot& w) {
  const HaltProfile h = halt_profile(w);
  std::string note;
  if (auto accepted = read_reply(side, w, note)) return {{}, std::move(accepted)};
  if (w.time_s < side.no_merge_before_s)  // just aborted: back toward the side lane centre first
    return {hold_after_abort(side, w, h, side_lane_path(side.lateral, w), note), std::nullopt};
  if (defers_merge(side, w, false)) return {back_to_centre(side, w, h, reversals_, false, note), std::nullopt};
  // A merge (it supersedes an open request), or the way back to the centre when the weaving
  // budget defers it.
  const auto take = [&](CommittedMerge merge) -> SideLaneStep {
    if (const bool away = turns_away_first(merge, w); defers_merge(side, w, away))
      return {back_to_centre(side, w, h, reversals_, away, note), std::nullopt};
    side.pending.reset();
    merge.decision.reason = note + merge.decision.reason;
    return {{}, std::move(merge)};
  };
  const auto take_def1_plan = [&](const Def1Plan& plan) { return take(start_def1_merge(side, w, plan, reversals_)); };
  std::string why;
  if (auto plan = plan_definition1(w, MergeDurations::kRhoM, &why)) return take_def1_plan(*plan);
  if (held_ && !side.pending) {
    if (auto plan = plan_accepted_definition2(w, *held_))
      return take(commit(side, w, plan->sigmoid, plan->ego_speed_after_mps, std::move(plan->decision)));
  }
  SideLaneStep step;
  step.out.path = side_lane_path(side.lateral, w);
  send_request(side, w, step.out, note);
  // The longer merges and the flat fallback are the costly searches (three and four durations);
  // while no merge exists they are tried every kLongerMergeEveryS (docs/performance.md), Def. 1 at
  // rho_m every cycle.
  if (!side.pending && w.time_s + 1e-9 >= side.next_longer_merge_s) {
    side.next_longer_merge_s = w.time_s + kLongerMergeEveryS;
    if (auto plan = plan_definition1(w, MergeDurations::kLonger, &why)) return take_def1_plan(*plan);
    if (auto plan = plan_definition1(w, MergeDurations::kFlat, nullptr)) return take_def1_plan(*plan);
  }
  if (side.pending)
    wait_for_reply(*side.pending, w, h, step.out);
  else
    halt(w, h, why, note, step.out);
  return step;
}

}  // namespace mg
