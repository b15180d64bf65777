#include "planner/committed_merge.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/fixed_text.h"
#include "core/merge_phase_detector.h"
#include "core/rss.h"
#include "planner/definition2_search.h"
#include "planner/merge_path.h"
#include "planner/rcpp_world.h"
#include "planner/world_view.h"

namespace mg {
namespace {

constexpr double kMaxMergeHorizonS = 60.0;  // longest remaining merge a committed-merge check looks at

// The rest of the merge: until the ego reaches the sigmoid's end at the speed it aims for. The
// ego's speed as planned (v_e*), as the candidate was checked: checking the capped target speed
// instead made a merge fail its re-check right after it passed the planner's.
double rest_of_merge_s(const CommittedMerge& m, const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const SpeedRamp ramp{ego_speed_mps(w), m.target_speed_mps, s.ego.limits.accel_max_mps2, s.ego.limits.brake_min_mps2};
  const double to_end_m = m.sigmoid.x_at_fraction_m(1.0 - kSigmoidEndFraction) - w.ego.x_m;
  return lowest_satisfying([&](double t) { return ramp.distance_at_m(t) - to_end_m; }, 0.0, kMaxMergeHorizonS, 1e-3)
      .value_or(kMaxMergeHorizonS);
}

std::pair<double, double> gap_vehicle_at(const CommittedMerge& m, const WorldSnapshot& w,
                                         const std::vector<MainLaneVehicle>& lane, const MainLaneVehicle& o,
                                         double t_s);

// Before P_c behind a braking leader: the fastest speed up to target_mps at which the ego reaches
// P_c at D_lon behind the leader as predicted. A Def. 2 partner is predicted on the profile it
// accepted (gap_vehicle_at): its braking toward v_o* is the yield it promised, not a threat to
// extrapolate (so extrapolated, a 2.2 partner slowing to v_o* capped the ego's speed to 0, and
// the merge it had just accepted was aborted on the next cycle).
double pc_bound_speed_mps(const CommittedMerge& m, const WorldSnapshot& w, const std::vector<MainLaneVehicle>& lane,
                          const MainLaneVehicle& leader, double target_mps) {
  const PlannerSetup& s = *w.setup;
  const double pc_m = lane_line_x_m(m.sigmoid, s.road.lane_width_m);
  const Track ahead = predicted_leader(w, lane, leader, rest_of_merge_s(m, w));
  const bool partner = m.decision.mode == DecisionMode::kDef2Merge && leader.id == m.decision.coop_partner_id;
  const auto leader_at = [&](double t_s) {
    return partner ? gap_vehicle_at(m, w, lane, leader, t_s) : std::pair<double, double>{ahead.x_at(t_s), ahead.v_at(t_s)};
  };
  const auto holds = [&](double v) {
    const SpeedRamp ramp{ego_speed_mps(w), v, s.ego.limits.accel_max_mps2, s.ego.limits.brake_min_mps2};
    const auto t = time_to_reach_s(w, ramp, pc_m);
    if (!t) return false;
    const auto [x_m, v_mps] = leader_at(*t);
    return leader_bound_margin_m(s, leader, x_m, v_mps, ramp.speed_at_mps(*t), pc_m) >= 0.0;
  };
  if (holds(target_mps)) return target_mps;
  // The bound's margin falls as the speed rises (later at P_c: the leader farther on, D_lon
  // shorter), so the fastest speed that holds is found by bisection.
  double lo = kStandstillMergeSpeedMps, hi = target_mps;
  if (hi <= lo || !holds(lo)) return rss_follow_speed_mps(w, leader);  // none: the re-check aborts
  while (hi - lo > 1e-3) {
    const double mid = 0.5 * (lo + hi);
    (holds(mid) ? lo : hi) = mid;
  }
  return lo;
}

// The speed cap behind the vehicle ahead once the ego is in the lane (or committed to it):
// rss_follow_speed_mps, its RSS distance plus kFollowBufferM. A leader no slower than the ego,
// with the ego outside its RSS distance, opens that buffer by itself: the ego keeps its speed
// rather than brake for it in mid-merge. A Definition 2.1 merge committed 0.5 m beyond D_lon
// behind the gap's leader braked at b_min to open the buffer at once, and the partner behind
// closed in to 0.37 m inside its safe distance by the midpoint (sigmoid_pc_bounds; a campaign
// finding).
double merging_follow_speed_mps(const WorldSnapshot& w, const MainLaneVehicle& leader) {
  const double cap = rss_follow_speed_mps(w, leader);
  const double v = ego_speed_mps(w);
  if (cap >= v || leader.speed_mps < v) return cap;
  const PlannerSetup& s = *w.setup;
  const double d_lon_m = rss_longitudinal_m({v, leader.speed_mps, s.ego.size.length_m, leader.length_m,
                                             s.params.rss.response_time_s, s.ego.limits.accel_max_mps2,
                                             s.ego.limits.brake_min_mps2, leader.limits.brake_max_mps2});
  return leader.x_m - w.ego.x_m >= d_lon_m ? v : cap;
}

// v_e*, capped behind the vehicle ahead. Past P_c the ego is in the main lane: it also keeps its
// RSS distance to the vehicle ahead. Before P_c, once that vehicle brakes, it slows enough to
// reach P_c at D_lon behind it as predicted (pc_bound_speed_mps): Def. 1.2 predicted it at
// constant speed, and a compliant leader may brake (e.g. for a slow vehicle ahead of it) up to
// its b_max (RCPP §II-C, spec §6). (D_lon behind it at once was asked of an ego still alongside a
// long leader it meant to drop behind: speed 0, P_c never reached, an abort a cycle after each
// decision.) And once the merge can no longer be aborted (kAbortLateralFraction): a leader that
// has braked to a stop is not braking any more, and the ego must not speed up toward it on the
// way in. Before P_c neither the gap's follower nor a vehicle behind it is that vehicle even while
// it is still ahead: the ego is passing them (a Def. 2.1 partner 2.5 m ahead, braking to yield,
// was taken for a braking leader, and the cap behind it aborted the cooperative merge it had just
// accepted; so was a vehicle braking behind a stopped follower the ego meant to overtake).
double merge_target_speed_mps(const CommittedMerge& m, const WorldSnapshot& w) {
  double target = m.target_speed_mps;
  const bool before_pc = w.ego.x_m < lane_line_x_m(m.sigmoid, w.setup->road.lane_width_m);
  const std::optional<Gap>& gap = m.decision.gap;
  const std::vector<MainLaneVehicle> lane = target_lane_vehicles(w);
  const auto follower = std::find_if(lane.begin(), lane.end(), [&](const MainLaneVehicle& v) {
    return gap && v.id == gap->follower_id;
  });
  for (const MainLaneVehicle& leader : lane) {  // by X
    const bool passing = before_pc && follower != lane.end() && !lane_order_before(*follower, leader);
    if (leader.x_m <= w.ego.x_m || passing) continue;
    const bool braking = observed_accel_mps2(w, leader.id) < -kLeaderBrakingMps2;
    if (!before_pc || m.committed(w.ego.y_m)) {
      target = std::min(target, merging_follow_speed_mps(w, leader));
    } else if (braking) {
      target = std::min(target, pc_bound_speed_mps(m, w, lane, leader, target));
    }
    break;
  }
  return target;
}

// Where gap vehicle `o` is predicted (X, speed) t_s from now, when the ego reaches P_c. A Def. 2
// partner on the profile it accepted (ineq. (3)/(4) count on it; an ego slowed behind a braking
// leader reaches P_c later, and the partner closes in); the gap's other vehicle as in Definition
// 1: the follower accelerating at its a_max, the leader at constant speed unless it is seen
// braking (leader_track, as the occupancy check predicts it: a leader braking for a stopped
// vehicle left a weak-braked ego that merged behind it unable to stop).
std::pair<double, double> gap_vehicle_at(const CommittedMerge& m, const WorldSnapshot& w,
                                         const std::vector<MainLaneVehicle>& lane, const MainLaneVehicle& o,
                                         double t_s) {
  const RcppDecision& d = m.decision;
  const PlannerSetup& s = *w.setup;
  if (d.mode == DecisionMode::kDef2Merge && o.id == d.coop_partner_id) {
    // From its speed now linearly to v_o* by the yield deadline of the plan's responder model
    // (coop_candidate: rho_c after the request arrives), then v_o*. A partner slower to yield
    // is predicted farther along (2.1) or behind (2.2): a reneging one is seen early.
    const double to_deadline_s = std::max(0.0, yield_deadline_s(s, d.time_s) - w.time_s);
    const double rate = to_deadline_s > 0.0 ? std::abs(d.vo_star_mps - o.speed_mps) / to_deadline_s + 1e-9
                                            : 1e9;  // past the deadline: at v_o* from now
    const SpeedRamp accepted{o.speed_mps, d.vo_star_mps, rate, rate};
    return {o.x_m + accepted.distance_at_m(t_s), accepted.speed_at_mps(t_s)};
  }
  if (o.id == d.gap->follower_id) {
    const double a = std::max(o.limits.accel_max_mps2, observed_accel_mps2(w, o.id));  // follower_track
    return {o.x_m + o.speed_mps * t_s + 0.5 * a * t_s * t_s, o.speed_mps + a * t_s};
  }
  const Track ahead = predicted_leader(w, lane, o, rest_of_merge_s(m, w));
  return {ahead.x_at(t_s), ahead.v_at(t_s)};
}

// spec §6: abort when the P_c bounds cross at the gap vehicles' predicted positions.
bool committed_bounds_crossed(const CommittedMerge& m, const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const RcppDecision& d = m.decision;
  if (!d.gap) return false;
  // The speed the ego will really aim for: v_e*, or less behind a braking leader (follow_merge).
  const SpeedRamp ramp{ego_speed_mps(w), merge_target_speed_mps(m, w), s.ego.limits.accel_max_mps2,
                       s.ego.limits.brake_min_mps2};
  const double pc_m = lane_line_x_m(m.sigmoid, s.road.lane_width_m);
  if (pc_m <= w.ego.x_m) return false;
  const auto t_reach = time_to_reach_s(w, ramp, pc_m);
  if (!t_reach) return true;  // the ego would never reach P_c
  const double v_at = ramp.speed_at_mps(*t_reach);
  const std::vector<MainLaneVehicle> lane = target_lane_vehicles(w);
  for (const ObservedVehicle& ov : w.others) {
    const MainLaneVehicle o = to_lane_vehicle(ov);
    const bool follower = o.id == d.gap->follower_id, leader = o.id == d.gap->leader_id;
    if (!follower && !leader) continue;
    const auto [x_m, v_mps] = gap_vehicle_at(m, w, lane, o, *t_reach);
    if (follower) {
      const double dl = rss_longitudinal_m({v_mps, v_at, o.length_m, s.ego.size.length_m, s.params.rss.response_time_s,
                                            o.limits.accel_max_mps2, o.limits.brake_min_mps2,
                                            s.ego.limits.brake_max_mps2});
      if (x_m + dl > pc_m) return true;
    } else if (leader_bound_margin_m(s, o, x_m, v_mps, v_at, pc_m) < 0.0) {
      return true;
    }
  }
  return false;
}

// The occupancy check of the rest of the merge with the gap vehicles as observed now.
bool committed_occupancy_clear(const CommittedMerge& m, const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const RcppDecision& d = m.decision;
  if (!d.gap) return true;
  const SpeedRamp ramp{ego_speed_mps(w), m.target_speed_mps, s.ego.limits.accel_max_mps2, s.ego.limits.brake_min_mps2};
  const double horizon_s = rest_of_merge_s(m, w);
  // The follower may still accelerate for what is left of its Def. 1.1 window (rho/2 from T_dec).
  const double follower_window_s = std::max(0.0, d.merge_duration_s - 2.0 * (w.time_s - d.time_s));
  const std::vector<MainLaneVehicle> lane = target_lane_vehicles(w);
  LaneGap gap;
  for (const MainLaneVehicle& v : lane) {
    if (v.id == d.gap->follower_id) gap.follower = v;
    if (v.id == d.gap->leader_id) gap.leader = v;
  }
  GapTracks tracks = gap_tracks(lane, gap, follower_window_s, [&](int id) { return observed_accel_mps2(w, id); },
                                leader_horizon(w, horizon_s));
  tracks.beside = beside_tracks(w);
  // The vehicle now nearest ahead in the target lane, when it lies inside the gap (the leader
  // left it, e.g. a non-compliant one that drove on): the ego must keep D_lon to it too. Not the
  // gap's follower: an ego merging ahead of a vehicle it has not passed yet is not behind it.
  if (const auto next = leader_ahead_of(lane, w.ego.x_m);
      next && (!gap.leader || lane_order_before(*next, *gap.leader)) &&
      (!gap.follower || lane_order_before(*gap.follower, *next)))
    tracks.leaders.push_back(predicted_leader(w, lane, *next, horizon_s));
  const double elapsed_s = w.time_s - d.time_s;
  const OccupancyInstants when{OccupancyInstants::over(d.merge_duration_s).step_s, elapsed_s, horizon_s};
  return occupancy_clear(s, w.ego.x_m, w.ego.y_m, m.sigmoid, ramp, when, tracks, 0.0, nullptr,
                         kOccupancyRecheckLateralSlackM);
}

// Whether a corner of the ego's body is over the lane line, in the main lane: where the rules
// judge a merge's entry (docs/spec.md §8).
bool body_in_main_lane(const WorldSnapshot& w) {
  return MergePhaseDetector::left_edge_y_m(w.setup->ego.size, w.ego.y_m, w.ego.yaw_rad) >
         -0.5 * w.setup->road.lane_width_m;
}

// Whether a vehicle of the merge's gap is seen beyond its declared limits: the right of way it
// left the ego rested on them.
bool gap_vehicle_beyond_limits(const CommittedMerge& m, const WorldSnapshot& w) {
  if (!m.decision.gap) return false;
  return beyond_declared_limits(w, m.decision.gap->follower_id) || beyond_declared_limits(w, m.decision.gap->leader_id);
}

}  // namespace

bool merge_complete(const CommittedMerge& m, const WorldSnapshot& w) {
  const double progress = (w.ego.y_m - m.sigmoid.offset_m) / m.sigmoid.width_m;
  const bool settled = progress >= kSettledFraction && std::abs(w.ego.yaw_rad) <= kSettledYawRad;
  return (w.ego.x_m >= m.sigmoid.x_at_fraction_m(1.0 - kSigmoidEndFraction) && settled) ||
         progress >= 1.0 - kSigmoidEndFraction;
}

double merge_path_y_m(const CommittedMerge& m, double x_m) {
  return std::max(m.sigmoid.y_at_m(x_m), m.from_hold ? m.start_y_m : m.sigmoid.offset_m);
}

std::vector<PathPoint> merge_path_points(const CommittedMerge& m, double x_from_m, double x_to_m, double step_m) {
  return sample_path(x_from_m, x_to_m, step_m, [&](double x) { return merge_path_y_m(m, x); });
}

bool turns_away_first(const CommittedMerge& m, const WorldSnapshot& w) {
  return merge_path_y_m(m, w.ego.x_m) < w.ego.y_m - kTurnAwayM;
}

bool heads_along(const CommittedMerge& m, const WorldSnapshot& w) {
  constexpr double kChordM = 0.5;  // half the chord the path's heading is measured over
  const double slope = (merge_path_y_m(m, w.ego.x_m + kChordM) - merge_path_y_m(m, w.ego.x_m - kChordM)) / (2.0 * kChordM);
  return w.ego.yaw_rad - std::atan(slope) <= kHeadingMatchRad;
}

bool merge_should_abort(const CommittedMerge& m, const WorldSnapshot& w) {
  // An abort returns to the side lane, sound only while the ego can still stop before its end
  // (Def. 1.3) at b_min; otherwise the merge completes under the RSS override. Nor once the body
  // is in the main lane: the rules judge the right of way at the entry, and a merge that went back
  // from there entered without it. Unless a vehicle of its gap breaks its declared limits: then
  // going back is the way out of a collision the right of way no longer protects, and a halt at
  // b_max (the halt profile's emergency braking) the way to keep Def. 1.3 for a merge into a gap
  // the breach has closed (a vehicle the ego meant to overtake, accelerating at four times its
  // a_accel^max, left no gap while the ego could still stop at b_max but no longer at b_min).
  const bool breach = gap_vehicle_beyond_limits(m, w);
  const double halt_brake_mps2 = breach ? w.setup->ego.limits.brake_max_mps2 : w.setup->ego.limits.brake_min_mps2;
  if (m.committed(w.ego.y_m) || !can_still_halt(w, halt_brake_mps2) || (body_in_main_lane(w) && !breach))
    return false;
  return m.decision.mode == DecisionMode::kDef1Merge
             ? committed_bounds_crossed(m, w) || !committed_occupancy_clear(m, w)
             : committed_bounds_crossed(m, w);
}

RcppCycle follow_merge(const CommittedMerge& m, const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  RcppCycle out;
  out.path = merge_path_points(m, w.ego.x_m - kPathBehindM, w.ego.x_m + tracked_path_ahead_m(w), kPathStepM);
  const double target = merge_target_speed_mps(m, w);
  out.target_speed_mps = target;
  out.accel_limit_mps2 = accel_limit_toward(s, ego_speed_mps(w), target);
  out.decision = m.decision;
  if (m.decision.time_s != w.time_s)
    out.decision.reason = "following the merge decided at t = " + fixed_text(m.decision.time_s, 2) +
                          " s: " + m.decision.reason;
  out.decision.time_s = w.time_s;
  return out;
}

}  // namespace mg
