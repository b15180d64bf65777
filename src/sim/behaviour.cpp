#include "sim/behaviour.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/demand.h"
#include "core/rss.h"

namespace mg {
namespace {

constexpr double kGapMarginM = 2.0;       // RSS follower / constant speed: margin above D_lon
constexpr double kBehaviourSpeedGainPerS = 1.0;  // speed tracking gain of the simple behaviours (the ego's is speed_controller.h's)
constexpr double kGapGainPerS2 = 0.2;     // RSS follower gap gain
constexpr double kCoopReleaseExtraS = 2.0;// cooperation ends rho_c + rho_m + this after acceptance
// A cooperative driver promises v_o* only if it expects to be within this of it, on the side the
// ego counts on, from t_r + rho_c + T to t_r + rho_c + rho_m (half the judge's default yield
// tolerance).
constexpr double kPromiseToleranceMps = 0.25;

double lane_centre_y(const Road& road, int lane) { return lane * road.lane_width_m; }

// D_lon of this vehicle behind the leader, centre to centre (RCPP eq. 1).
double safe_distance_behind(double speed_mps, double own_length_m, const Limits& own, const Leader& leader,
                            const RssParams& rss) {
  return rss_longitudinal_m({.rear_speed_mps = speed_mps,
                             .front_speed_mps = leader.speed_mps,
                             .rear_length_m = own_length_m,
                             .front_length_m = leader.length_m,
                             .response_time_s = rss.response_time_s,
                             .accel_max_mps2 = own.accel_max_mps2,
                             .brake_min_mps2 = own.brake_min_mps2,
                             .brake_max_mps2 = leader.brake_max_mps2});
}

}  // namespace

namespace {

Leader leader_of(const Scenario& s, const std::vector<VehicleState>& others, std::size_t j, double distance_m) {
  return Leader{s.vehicles[j].id, distance_m, others[j].vx_mps, s.vehicles[j].size.length_m,
                s.vehicles[j].limits.brake_max_mps2};
}

// The ego, once its box overlaps the lane of the vehicle at x, when nearer ahead than `main`.
Leaders with_ego(const Scenario& s, int lane, double x, const std::optional<Leader>& main, const VehicleState& ego) {
  Leaders leaders;
  leaders.main_only = main;
  leaders.with_ego = main;
  const double half_overlap = 0.5 * (s.road.lane_width_m + s.ego.size.width_m);
  const double d = ego.x_m - x;
  if (std::abs(ego.y_m - lane_centre_y(s.road, lane)) < half_overlap && d > 0.0 && !(main && d >= main->distance_m))
    leaders.with_ego = Leader{0, d, std::max(ego.road_vx_mps(), 0.0), s.ego.size.length_m, s.ego.limits.brake_max_mps2};
  return leaders;
}

}  // namespace

Leaders find_leaders(const Scenario& s, const std::vector<VehicleState>& others, std::size_t index,
                     const VehicleState& ego) {
  MG_DEMAND(index < others.size() && others.size() == s.vehicles.size());
  const int lane = s.vehicles[index].lane;
  const double x = others[index].x_m;
  std::optional<Leader> best;  // the nearest ahead; the lowest index among equal distances
  for (std::size_t j = 0; j < others.size(); ++j) {
    if (j == index || s.vehicles[j].lane != lane) continue;
    const double d = others[j].x_m - x;
    if (d > 0.0 && !(best && d >= best->distance_m)) best = leader_of(s, others, j, d);
  }
  return with_ego(s, lane, x, best, ego);
}

void LaneOrder::update(const Scenario& s, const std::vector<VehicleState>& others) {
  if (position_.size() != others.size()) {
    lanes_.assign(static_cast<std::size_t>(s.road.main_lanes), {});
    for (std::size_t j = 0; j < others.size(); ++j) lanes_[static_cast<std::size_t>(s.vehicles[j].lane)].push_back(j);
    position_.assign(others.size(), 0);
  }
  const auto before = [&others](std::size_t a, std::size_t b) {
    return others[a].x_m < others[b].x_m || (others[a].x_m == others[b].x_m && a < b);
  };
  for (std::vector<std::size_t>& lane : lanes_) {
    for (std::size_t k = 1; k < lane.size(); ++k) {  // insertion sort: nearly sorted already
      const std::size_t v = lane[k];
      std::size_t m = k;
      for (; m > 0 && before(v, lane[m - 1]); --m) lane[m] = lane[m - 1];
      lane[m] = v;
    }
    for (std::size_t k = 0; k < lane.size(); ++k) position_[lane[k]] = k;
  }
}

bool LaneOrder::any_overlap(const Scenario& s, const std::vector<VehicleState>& others) const {
  for (const std::vector<std::size_t>& lane : lanes_) {
    for (std::size_t k = 1; k < lane.size(); ++k) {
      const std::size_t rear = lane[k - 1], front = lane[k];
      const double half_lengths_m = 0.5 * (s.vehicles[rear].size.length_m + s.vehicles[front].size.length_m);
      if (others[front].x_m - others[rear].x_m < half_lengths_m) return true;
    }
  }
  return false;
}

Leaders LaneOrder::leaders(const Scenario& s, const std::vector<VehicleState>& others, std::size_t index,
                           const VehicleState& ego) const {
  const int lane_index = s.vehicles[index].lane;
  const std::vector<std::size_t>& lane = lanes_[static_cast<std::size_t>(lane_index)];
  const double x = others[index].x_m;
  std::size_t q = position_[index] + 1;
  while (q < lane.size() && !(others[lane[q]].x_m - x > 0.0)) ++q;  // level with it: not ahead
  std::optional<Leader> best;
  if (q < lane.size()) {
    // The nearest distance; of the vehicles at exactly that distance, the lowest index (as the scan).
    const double d = others[lane[q]].x_m - x;
    std::size_t j = lane[q];
    for (std::size_t r = q + 1; r < lane.size() && others[lane[r]].x_m - x == d; ++r) j = std::min(j, lane[r]);
    best = leader_of(s, others, j, d);
  }
  return with_ego(s, lane_index, x, best, ego);
}

double idm_accel_mps2(double speed_mps, double desired_speed_mps, const std::optional<Leader>& leader,
                      double own_length_m, const Behaviour& b, const Limits& limits) {
  const double a = std::max(limits.accel_max_mps2, 0.5);
  const double v0 = std::max(desired_speed_mps, 0.1);
  double interaction = 0.0;
  if (leader) {
    const double gap = leader->distance_m - 0.5 * (own_length_m + leader->length_m);
    if (gap <= 0.01) return -limits.brake_max_mps2;
    const double dv = speed_mps - leader->speed_mps;
    const double s_star = b.min_gap_m + std::max(0.0, speed_mps * b.time_headway_s +
                                                          speed_mps * dv / (2.0 * std::sqrt(a * b.comfort_brake_mps2)));
    interaction = (s_star / gap) * (s_star / gap);
  }
  return a * (1.0 - std::pow(speed_mps / v0, 4) - interaction);
}

bool rss_unsafe_behind(double speed_mps, double own_length_m, const Limits& own, const Leader& leader,
                       const RssParams& rss) {
  return leader.distance_m < safe_distance_behind(speed_mps, own_length_m, own, leader, rss);
}

void advance_on_lane(VehicleState& s, double accel_mps2, double dt_s) {
  const double v = s.vx_mps;
  const double v_new = v + accel_mps2 * dt_s;
  if (v_new < 0.0) {  // stops within the step and stays
    s.x_m += v > 0.0 ? v * v / (2.0 * -accel_mps2) : 0.0;
    s.vx_mps = 0.0;
    s.accel_mps2 = -v / dt_s;
  } else {
    s.x_m += 0.5 * (v + v_new) * dt_s;
    s.vx_mps = v_new;
    s.accel_mps2 = accel_mps2;
  }
}

MainLaneDriver::MainLaneDriver(const MainVehicle& spec, const Road& road, const Params& params)
    : spec_(spec), road_(road), params_(params), rng_(spec.behaviour.seed) {}

double MainLaneDriver::desired_speed() const {
  return spec_.behaviour.desired_speed_mps < 0.0 ? spec_.speed_mps : spec_.behaviour.desired_speed_mps;
}

bool MainLaneDriver::in_window(double time_s) const {
  const NonCompliance& n = spec_.noncompliance;
  return time_s >= n.start_time_s && time_s < n.start_time_s + n.duration_s;
}

bool MainLaneDriver::non_compliant(double time_s) const {
  const NonComplianceType t = spec_.noncompliance.type;
  if (t == NonComplianceType::kExceedAccel || t == NonComplianceType::kExceedBrake) return in_window(time_s);
  return mode_ == Mode::kReneging;
}

double MainLaneDriver::cooperating_accel(double speed_mps, double target_mps, CoopCase c,
                                         const std::optional<Leader>& leader) const {
  // Definition 2: brake at most b_min to v_o* (2.1 B: v_o* bounds the speed from above) or
  // accelerate at most a_acc to it (2.2 B: from below); a responder already on the right side of
  // v_o* holds its speed (tracking v_o* back from there would leave the profile the ego's
  // ineq. (3)/(4) counts on, which runs from its speed at the acceptance). Never closer to a leader
  // than IDM's interaction term allows (its free-road term is dropped: v_o* replaces the desired
  // speed).
  const Limits& lim = spec_.limits;
  double track =
      std::clamp(kBehaviourSpeedGainPerS * 4.0 * (target_mps - speed_mps), -lim.brake_min_mps2, lim.accel_max_mps2);
  track = c == CoopCase::kEgoAhead ? std::min(track, 0.0) : std::max(track, 0.0);
  const double idm = idm_accel_mps2(speed_mps, std::numeric_limits<double>::infinity(), leader, spec_.size.length_m,
                                    spec_.behaviour, lim);
  return std::clamp(std::min(track, idm), -lim.brake_max_mps2, lim.accel_max_mps2);
}

// The cooperating law run ahead on the leader held at its current speed, at the simulation step,
// against the promise as Def. 2's responder rules read it: from the acceptance on, no farther
// behind (2.2; ahead for 2.1) than kPromiseToleranceMps x the time since of the profile that
// changes speed linearly to v_o* by t_r + rho_c + T and then holds it (def2_positions), and from
// t_r + rho_c + T on no slower (2.2; faster for 2.1) than v_o* by kPromiseToleranceMps
// (def2_1b_responder, def2_2b_responder); until t_r + rho_c + rho_m. T is the RSS response time.
bool MainLaneDriver::keeps_promise(const V2vMessage& request, double time_s, double speed_mps,
                                   const std::optional<Leader>& leader) const {
  const double dt = params_.sim.step_s;
  const double due_s = request.sent_time_s + params_.planner.comm_threshold_s + params_.rss.response_time_s;
  const double end_s = request.sent_time_s + params_.planner.comm_threshold_s + params_.planner.merge_duration_s;
  const double target = request.target_speed_mps;
  const double side = request.coop_case == CoopCase::kEgoBehind ? 1.0 : -1.0;  // +1: no slower, -1: no faster
  const double ramp_s = std::max(due_s - time_s, 0.0);
  std::optional<Leader> ahead = leader;
  double v = speed_mps, x = 0.0, profile_x = 0.0, profile_v = speed_mps;
  for (double t = time_s; t <= end_s + 1e-9; t += dt) {
    const double tol_m = kPromiseToleranceMps * (t - time_s);
    if (side * (x - profile_x) < -tol_m) return false;
    if (t >= due_s - 1e-9 && side * (v - target) < -kPromiseToleranceMps) return false;
    const double a = cooperating_accel(v, target, request.coop_case, ahead);
    const double v_next = std::max(0.0, v + a * dt);
    const double profile_next = t + dt >= due_s || ramp_s <= 0.0
                                    ? target
                                    : speed_mps + (target - speed_mps) * (t + dt - time_s) / ramp_s;
    x += 0.5 * (v + v_next) * dt;
    profile_x += 0.5 * (profile_v + profile_next) * dt;
    if (ahead) ahead->distance_m += (ahead->speed_mps - 0.5 * (v + v_next)) * dt;
    v = v_next;
    profile_v = profile_next;
  }
  return true;
}

std::optional<V2vMessage> MainLaneDriver::answer(const V2vMessage& request, double time_s, double speed_mps,
                                                 const std::optional<Leader>& leader) {
  if (request.type != MessageType::kRequest) return std::nullopt;
  if (spec_.behaviour.type == BehaviourType::kNonResponsive) return std::nullopt;
  V2vMessage reply = request;
  reply.from_id = spec_.id;
  reply.to_id = request.from_id;
  reply.sent_time_s = time_s;
  reply.type = MessageType::kRefuse;
  if (spec_.noncompliance.type == NonComplianceType::kRenege && in_window(time_s)) {
    reply.type = MessageType::kAccept;  // accepts, and will not yield
    mode_ = Mode::kReneging;
    coop_since_s_ = time_s;
    return reply;
  }
  if (spec_.behaviour.type != BehaviourType::kCooperative || mode_ != Mode::kNormal) return reply;
  const double target = request.target_speed_mps;
  const bool braking = target <= speed_mps;
  const double rate = braking ? spec_.limits.brake_min_mps2 : spec_.limits.accel_max_mps2;
  const bool reachable = std::isfinite(target) && target >= 0.0 && target <= road_.speed_limit_mps &&
                         std::abs(target - speed_mps) <= rate * params_.planner.comm_threshold_s + 1e-9;
  if (reachable && keeps_promise(request, time_s, speed_mps, leader)) {
    reply.type = MessageType::kAccept;
    mode_ = Mode::kCooperating;
    coop_target_mps_ = target;
    coop_case_ = request.coop_case;
    coop_since_s_ = time_s;
  }
  return reply;
}

double MainLaneDriver::behaviour_accel(const DriverInput& in) {
  const Behaviour& b = spec_.behaviour;
  const Limits& lim = spec_.limits;
  const double len = spec_.size.length_m;
  const double v = in.speed_mps;
  switch (b.type) {
    case BehaviourType::kConstantSpeed: {
      if (in.leader && rss_unsafe_behind(v, len, lim, *in.leader, params_.rss)) return -lim.brake_min_mps2;
      double a = std::clamp(kBehaviourSpeedGainPerS * (desired_speed() - v), -lim.brake_min_mps2, lim.accel_max_mps2);
      if (in.leader && a > 0.0 &&
          in.leader->distance_m < safe_distance_behind(v, len, lim, *in.leader, params_.rss) + kGapMarginM)
        a = 0.0;
      return a;
    }
    case BehaviourType::kRssFollower: {
      double a = kBehaviourSpeedGainPerS * (desired_speed() - v);
      if (in.leader) {
        const double d_lon = safe_distance_behind(v, len, lim, *in.leader, params_.rss);
        if (in.leader->distance_m < d_lon) return -lim.brake_min_mps2;  // proper response
        a = std::min(a, kGapGainPerS2 * (in.leader->distance_m - d_lon - kGapMarginM) +
                            kBehaviourSpeedGainPerS * (in.leader->speed_mps - v));
      }
      return a;
    }
    case BehaviourType::kBoundedRandom: {
      const long long segment = static_cast<long long>(std::floor(in.time_s / b.segment_s));
      while (segment_ < segment) {  // one draw per segment, in order
        segment_accel_mps2_ = -lim.brake_max_mps2 + rng_.uniform01() * (lim.accel_max_mps2 + lim.brake_max_mps2);
        ++segment_;
      }
      double a = segment_accel_mps2_;
      if (v >= road_.speed_limit_mps) a = std::min(a, 0.0);
      if (in.leader && rss_unsafe_behind(v, len, lim, *in.leader, params_.rss)) a = std::min(a, -lim.brake_min_mps2);
      return a;
    }
    case BehaviourType::kIdm:
    case BehaviourType::kCooperative:
    case BehaviourType::kNonResponsive:
      return idm_accel_mps2(v, desired_speed(), in.leader, len, b, lim);
  }
  return 0.0;
}

double MainLaneDriver::accel_mps2(const DriverInput& in) {
  const Limits& lim = spec_.limits;
  const NonCompliance& n = spec_.noncompliance;
  if (n.type == NonComplianceType::kExceedAccel && in_window(in.time_s))
    return in.speed_mps < kMaxScriptedSpeedMps ? n.accel_mps2 : 0.0;
  if (n.type == NonComplianceType::kExceedBrake && in_window(in.time_s)) return -n.accel_mps2;

  const double release_s = params_.planner.comm_threshold_s + params_.planner.merge_duration_s + kCoopReleaseExtraS;
  if (mode_ != Mode::kNormal && (in.ego_in_lane || in.time_s - coop_since_s_ > release_s)) mode_ = Mode::kNormal;

  double a = 0.0;
  if (mode_ == Mode::kCooperating) {
    a = cooperating_accel(in.speed_mps, coop_target_mps_, coop_case_, in.leader);
  } else if (mode_ == Mode::kReneging) {
    // Accepted, but keeps driving as if the ego were not there.
    a = idm_accel_mps2(in.speed_mps, desired_speed(), in.leader_main_only, spec_.size.length_m, spec_.behaviour, lim);
  } else {
    a = behaviour_accel(in);
  }
  return std::clamp(a, -lim.brake_max_mps2, lim.accel_max_mps2);
}

}  // namespace mg
