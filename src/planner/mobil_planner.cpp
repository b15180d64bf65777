#include "planner/mobil_planner.h"

#include <algorithm>
#include <cmath>

#include "core/fixed_text.h"
#include "planner/accel_command.h"
#include "planner/world_view.h"

namespace mg {
namespace {

constexpr double kMobilPathBehindM = 10.0;
constexpr double kMobilPathStepM = 1.0;

using MobilRow = ParamRow<MobilPlannerParams>;
using MobilP = MobilPlannerParams;

// The vehicles of the lane centred at lane_y_m nearest ahead of and behind x_m (a vehicle level
// with x_m is behind: it is the one that would follow).
struct LaneNeighbours {
  const ObservedVehicle* leader = nullptr;
  const ObservedVehicle* follower = nullptr;
};

LaneNeighbours neighbours(const WorldSnapshot& w, double lane_y_m, double x_m) {
  LaneNeighbours n;
  for (const ObservedVehicle& o : w.others) {
    if (std::abs(o.state.y_m - lane_y_m) >= 0.5 * w.setup->road.lane_width_m) continue;
    if (o.state.x_m > x_m) {
      if (!n.leader || o.state.x_m < n.leader->state.x_m) n.leader = &o;
    } else if (!n.follower || o.state.x_m > n.follower->state.x_m) {
      n.follower = &o;
    }
  }
  return n;
}

double speed_of(const ObservedVehicle& o) { return std::max(0.0, o.state.road_vx_mps()); }

// A leader ahead of a vehicle with centre rear_x_m and length rear_length_m.
IdmLeader leader_of(double rear_x_m, double rear_length_m, const ObservedVehicle& lead) {
  return {lead.state.x_m - rear_x_m - 0.5 * (rear_length_m + lead.size.length_m), speed_of(lead)};
}

// The side lane's end as a standing obstacle ahead of the ego's front.
IdmLeader side_lane_end(const WorldSnapshot& w) {
  return {w.setup->road.side_lane_end_x_m - w.ego.x_m - 0.5 * w.setup->ego.size.length_m, 0.0};
}

std::optional<IdmLeader> nearer(const std::optional<IdmLeader>& a, const std::optional<IdmLeader>& b) {
  if (!a) return b;
  if (!b) return a;
  return a->gap_m <= b->gap_m ? a : b;
}

double lane_centre_y(const WorldSnapshot& w) {
  const double lane_w = w.setup->road.lane_width_m;
  return std::max(0.0, std::round(w.ego.y_m / lane_w)) * lane_w;
}

std::vector<PathPoint> straight_path(const WorldSnapshot& w, double y_m) {
  return sample_path(w.ego.x_m - kMobilPathBehindM, w.ego.x_m + tracked_path_ahead_m(w), kMobilPathStepM,
                     [y_m](double) { return y_m; });
}

}  // namespace

const std::vector<ParamRow<MobilPlannerParams>>& mobil_parameter_table() {
  static const std::vector<MobilRow> table = {
      {"desired_speed_ratio", [](const MobilP& p) -> double { return p.desired_speed_ratio; }, 0.1, 1.0, "",
        "IDM desired speed v0 as a share of the road's speed limit"},
      {"time_headway_s", [](const MobilP& p) -> double { return p.time_headway_s; }, 0.1, 5.0, "s", "IDM time headway T"},
      {"min_gap_m", [](const MobilP& p) -> double { return p.min_gap_m; }, 0.0, 20.0, "m",
        "IDM standstill gap s0 (bumper to bumper)"},
      {"max_accel_mps2", [](const MobilP& p) -> double { return p.max_accel_mps2; }, 0.1, 5.0, "m/s2",
        "IDM maximum acceleration a"},
      {"comfort_brake_mps2", [](const MobilP& p) -> double { return p.comfort_brake_mps2; }, 0.1, 10.0, "m/s2",
        "IDM comfortable deceleration b"},
      {"exponent", [](const MobilP& p) -> double { return p.exponent; }, 1.0, 10.0, "", "IDM acceleration exponent delta"},
      {"politeness", [](const MobilP& p) -> double { return p.politeness; }, 0.0, 2.0, "",
        "MOBIL politeness p: weight of the new follower's disadvantage"},
      {"safe_brake_mps2", [](const MobilP& p) -> double { return p.safe_brake_mps2; }, 0.1, 15.0, "m/s2",
        "MOBIL b_safe: hardest braking a change may impose on the new follower"},
      {"threshold_mps2", [](const MobilP& p) -> double { return p.threshold_mps2; }, 0.0, 2.0, "m/s2",
        "MOBIL changing threshold Delta a_th"},
      {"bias_mps2", [](const MobilP& p) -> double { return p.bias_mps2; }, 0.0, 5.0, "m/s2",
        "MOBIL bias Delta a_bias toward the main lane (the side lane ends)"},
      {"lane_change_duration_s", [](const MobilP& p) -> double { return p.lane_change_duration_s; }, 1.0, 10.0, "s",
        "duration of the lateral path of a change"},
  };
  return table;
}

IdmParams idm_params_of(const MobilPlannerParams& p, double speed_limit_mps) {
  return {p.desired_speed_ratio * speed_limit_mps, p.time_headway_s, p.min_gap_m, p.max_accel_mps2, p.comfort_brake_mps2,
          p.exponent};
}

MobilParams mobil_params_of(const MobilPlannerParams& p) {
  return {p.politeness, p.safe_brake_mps2, p.threshold_mps2, p.bias_mps2};
}

double min_jerk_blend(double u) {
  const double t = std::clamp(u, 0.0, 1.0);
  return t * t * t * (10.0 - 15.0 * t + 6.0 * t * t);
}

double LaneChangePath::y_at(double x_m) const {
  return start_y_m + (target_y_m - start_y_m) * min_jerk_blend((x_m - start_x_m) / length_m);
}

LaneChangePath lane_change_from(const WorldSnapshot& w, double target_y_m, const MobilPlannerParams& p) {
  const double speed = std::max(ego_speed_mps(w), kMinLaneChangeSpeedMps);
  return {w.ego.x_m, w.ego.y_m, speed * p.lane_change_duration_s, target_y_m};
}

double mobil_lane_accel_mps2(const WorldSnapshot& w, double lane_y_m, bool side_lane_end_ahead, const MobilPlannerParams& p) {
  const PlannerSetup& s = *w.setup;
  const LaneNeighbours n = neighbours(w, lane_y_m, w.ego.x_m);
  std::optional<IdmLeader> leader;
  if (n.leader) leader = leader_of(w.ego.x_m, s.ego.size.length_m, *n.leader);
  if (side_lane_end_ahead) leader = nearer(leader, side_lane_end(w));
  const double a = idm_accel_mps2(ego_speed_mps(w), leader, idm_params_of(p, s.road.speed_limit_mps));
  return std::clamp(a, -s.ego.limits.brake_max_mps2, s.ego.limits.accel_max_mps2);
}

MobilDecision decide_mobil(const WorldSnapshot& w, const MobilPlannerParams& p) {
  const PlannerSetup& s = *w.setup;
  const IdmParams idm = idm_params_of(p, s.road.speed_limit_mps);
  const double v = ego_speed_mps(w);
  const double ego_len = s.ego.size.length_m;
  const LaneNeighbours side = neighbours(w, s.road.side_lane_y_m(), w.ego.x_m);
  const LaneNeighbours main = neighbours(w, 0.0, w.ego.x_m);
  MobilDecision d;
  std::optional<IdmLeader> side_leader = side_lane_end(w);
  if (side.leader) side_leader = nearer(side_leader, leader_of(w.ego.x_m, ego_len, *side.leader));
  d.situation.ego_before_mps2 = idm_accel_mps2(v, side_leader, idm);
  std::optional<IdmLeader> main_leader;
  if (main.leader) main_leader = leader_of(w.ego.x_m, ego_len, *main.leader);
  d.situation.ego_after_mps2 = idm_accel_mps2(v, main_leader, idm);
  d.gaps_open = !main_leader || main_leader->gap_m > 0.0;
  if (main.follower) {
    const ObservedVehicle& f = *main.follower;
    std::optional<IdmLeader> before;
    if (main.leader) before = leader_of(f.state.x_m, f.size.length_m, *main.leader);
    const IdmLeader after{w.ego.x_m - f.state.x_m - 0.5 * (ego_len + f.size.length_m), v};
    d.situation.new_follower_before_mps2 = idm_accel_mps2(speed_of(f), before, idm);
    d.situation.new_follower_after_mps2 = idm_accel_mps2(speed_of(f), after, idm);
    d.gaps_open = d.gaps_open && after.gap_m > 0.0;
  }
  if (side.follower) {  // another vehicle in the side lane behind the ego
    const ObservedVehicle& f = *side.follower;
    const IdmLeader before{w.ego.x_m - f.state.x_m - 0.5 * (ego_len + f.size.length_m), v};
    std::optional<IdmLeader> after = IdmLeader{s.road.side_lane_end_x_m - f.state.x_m - 0.5 * f.size.length_m, 0.0};
    if (side.leader) after = nearer(after, leader_of(f.state.x_m, f.size.length_m, *side.leader));
    d.situation.old_follower_before_mps2 = idm_accel_mps2(speed_of(f), before, idm);
    d.situation.old_follower_after_mps2 = idm_accel_mps2(speed_of(f), after, idm);
  }
  const MobilParams mobil = mobil_params_of(p);
  d.safe = mobil_safe(d.situation, mobil);
  d.incentive = mobil_incentive(d.situation, mobil);
  d.change = d.gaps_open && d.safe && d.incentive;
  d.reason = "MOBIL: own acceleration " + fixed_text(d.situation.ego_before_mps2, 2) + " -> " +
             fixed_text(d.situation.ego_after_mps2, 2) + " m/s2, new follower " +
             (d.situation.new_follower_after_mps2 ? fixed_text(*d.situation.new_follower_after_mps2, 2) + " m/s2" : "none") +
             ", advantage " + fixed_text(mobil_advantage_mps2(d.situation, mobil), 2) + " m/s2: " +
             (!d.gaps_open ? "no room" : !d.safe ? "unsafe" : !d.incentive ? "no incentive" : "change");
  return d;
}

MobilPlanner::MobilPlanner(MobilPlannerParams params) : params_(params) {
  MG_DEMAND(params_in_range(mobil_parameter_table(), params_));
}

void MobilPlanner::advance_phase(const WorldSnapshot& w) {
  const double line_y = -0.5 * w.setup->road.lane_width_m;
  if (std::holds_alternative<MobilKeepingSideLane>(phase_) && w.ego.y_m >= line_y) phase_ = MobilInMainLane{};
  if (const auto* c = std::get_if<MobilChangingLane>(&phase_); c && w.ego.x_m >= c->path.end_x_m()) phase_ = MobilInMainLane{};
}

PlanOutput MobilPlanner::plan(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  advance_phase(w);
  PlanOutput out;
  double accel = 0.0;
  if (std::holds_alternative<MobilKeepingSideLane>(phase_)) {
    const MobilDecision d = decide_mobil(w, params_);
    out.reason = d.reason;
    if (d.change) phase_ = MobilChangingLane{lane_change_from(w, 0.0, params_)};
  }
  if (std::holds_alternative<MobilKeepingSideLane>(phase_)) {
    out.mode = "keep_side_lane";
    out.path = straight_path(w, s.road.side_lane_y_m());
    accel = mobil_lane_accel_mps2(w, s.road.side_lane_y_m(), true, params_);
  } else if (const auto* c = std::get_if<MobilChangingLane>(&phase_)) {
    out.mode = "lane_change";
    if (out.reason.empty()) out.reason = "lane change to the main lane, ends at x = " + fixed_text(c->path.end_x_m(), 1) + " m";
    const double to_x = std::max(w.ego.x_m + tracked_path_ahead_m(w), c->path.end_x_m() + kMobilPathStepM);
    out.path = sample_path(w.ego.x_m - kMobilPathBehindM, to_x, kMobilPathStepM, [&c](double x) { return c->path.y_at(x); });
    accel = mobil_lane_accel_mps2(w, 0.0, false, params_);  // committed: it follows the main lane's leader
  } else {
    out.mode = "main_lane";
    out.reason = "IDM car following in the main lane";
    out.path = straight_path(w, lane_centre_y(w));
    accel = mobil_lane_accel_mps2(w, lane_centre_y(w), false, params_);
  }
  const SpeedCommand cmd = speed_command_for_accel(ego_speed_mps(w), accel, s.road.speed_limit_mps);
  out.target_speed_mps = cmd.target_speed_mps;
  out.accel_limit_mps2 = cmd.accel_limit_mps2;
  return out;
}

}  // namespace mg
