#include "planner/frenet_planner.h"

#include <algorithm>
#include <cmath>

#include "core/fixed_text.h"
#include "planner/accel_command.h"
#include "planner/world_view.h"

namespace mg {
namespace {

constexpr double kPathBehindM = 10.0;
constexpr double kPathStepM = 1.0;
constexpr double kMinPointSpacingM = 0.05;  // path points closer along X carry no direction

using Row = ParamRow<FrenetPlannerParams>;
using P = FrenetPlannerParams;

std::vector<double> durations(const FrenetPlannerParams& p) {
  std::vector<double> out;
  for (double t = p.min_duration_s; t <= p.max_duration_s + 1e-9; t += p.duration_step_s) out.push_back(t);
  return out;
}

// The trajectory's positions over the check horizon, then straight on at its end offset.
std::vector<PathPoint> path_of(const FrenetTrajectory& t, const WorldSnapshot& w, const FrenetPlannerParams& p) {
  std::vector<PathPoint> path{{w.ego.x_m - kPathBehindM, t.d_at(0.0)}};
  const double horizon_s = std::max(p.max_duration_s, t.duration_s);
  for (double time_s = 0.0; time_s <= horizon_s + 1e-9; time_s += p.check_step_s) {
    const double x = t.s_at(time_s);
    if (x > path.back().x_m + kMinPointSpacingM) path.push_back({x, t.d_at(time_s)});
  }
  const double to_x = w.ego.x_m + tracked_path_ahead_m(w);
  for (double x = path.back().x_m + kPathStepM; path.back().x_m < to_x; x += kPathStepM) path.push_back({x, t.end_d_m});
  return path;
}

std::string mode_of(const FrenetTrajectory& t, const WorldSnapshot& w) {
  const double line_y = -0.5 * w.setup->road.lane_width_m;
  if (t.end_d_m < line_y) return "keep_side_lane";
  return w.ego.y_m < line_y ? "merge" : "main_lane";
}

}  // namespace

const std::vector<ParamRow<FrenetPlannerParams>>& frenet_parameter_table() {
  static const std::vector<Row> table = {
      {"min_duration_s", [](const P& p) -> double { return p.min_duration_s; }, 0.5, 20.0, "s",
        "shortest manoeuvre duration T sampled"},
      {"max_duration_s", [](const P& p) -> double { return p.max_duration_s; }, 0.5, 20.0, "s",
        "longest manoeuvre duration sampled; the collision check's horizon"},
      {"duration_step_s", [](const P& p) -> double { return p.duration_step_s; }, 0.1, 10.0, "s",
        "step between sampled durations"},
      {"speed_samples", [](const P& p) -> double { return p.speed_samples; }, 2, 50, "",
        "target speeds sampled, evenly from 0 to the desired speed"},
      {"desired_speed_ratio", [](const P& p) -> double { return p.desired_speed_ratio; }, 0.1, 1.0, "",
        "desired speed as a share of the road's speed limit"},
      {"weight_jerk", [](const P& p) -> double { return p.weight_jerk; }, 0.0, 100.0, "",
        "k_j, on the integral of the squared jerk"},
      {"weight_time", [](const P& p) -> double { return p.weight_time; }, 0.0, 100.0, "1/s",
        "k_t, on the manoeuvre duration"},
      {"weight_deviation", [](const P& p) -> double { return p.weight_deviation; }, 0.0, 100.0, "1/m2",
        "k_d, on the end offset from the main lane's centre"},
      {"weight_speed", [](const P& p) -> double { return p.weight_speed; }, 0.0, 100.0, "s2/m2",
        "k_s, on the end speed's difference from the desired speed"},
      {"weight_lateral", [](const P& p) -> double { return p.weight_lateral; }, 0.0, 100.0, "",
        "k_lat, on the lateral cost"},
      {"weight_longitudinal", [](const P& p) -> double { return p.weight_longitudinal; }, 0.0, 100.0, "",
        "k_lon, on the longitudinal cost"},
      {"max_curvature_per_m", [](const P& p) -> double { return p.max_curvature_per_m; }, 0.01, 2.0, "1/m",
        "path curvature limit"},
      {"max_lat_accel_mps2", [](const P& p) -> double { return p.max_lat_accel_mps2; }, 0.1, 10.0, "m/s2",
        "lateral acceleration limit |d''|"},
      {"obstacle_margin_m", [](const P& p) -> double { return p.obstacle_margin_m; }, 0.0, 5.0, "m",
        "added to every obstacle's extent in the collision check"},
      {"check_step_s", [](const P& p) -> double { return p.check_step_s; }, 0.02, 0.5, "s",
        "sampling of the checks and of the jerk integral"},
  };
  return table;
}

FrenetScene frenet_scene(const WorldSnapshot& w, const FrenetPlannerParams& p) {
  const PlannerSetup& s = *w.setup;
  FrenetScene sc;
  sc.ego_length_m = s.ego.size.length_m;
  sc.ego_width_m = s.ego.size.width_m;
  sc.accel_max_mps2 = s.ego.limits.accel_max_mps2;
  sc.brake_max_mps2 = s.ego.limits.brake_max_mps2;
  sc.lat_accel_max_mps2 = p.max_lat_accel_mps2;
  sc.curvature_max_per_m = p.max_curvature_per_m;
  sc.lane_width_m = s.road.lane_width_m;
  sc.side_lane_end_x_m = s.road.side_lane_end_x_m;
  sc.margin_m = p.obstacle_margin_m;
  sc.horizon_s = p.max_duration_s;
  sc.step_s = p.check_step_s;
  for (const ObservedVehicle& o : w.others)
    sc.obstacles.push_back({o.id, o.state.x_m, o.state.y_m, o.state.road_vx_mps(), o.size.length_m, o.size.width_m});
  return sc;
}

std::vector<double> frenet_lateral_targets(const WorldSnapshot& w) {
  const Road& road = w.setup->road;
  if (w.ego.x_m + 0.5 * w.setup->ego.size.length_m < road.side_lane_end_x_m) return {road.side_lane_y_m(), 0.0};
  return {0.0};
}

FrenetChoice choose_frenet_trajectory(const FrenetStart& start, const std::vector<double>& lateral_targets_m,
                                      double desired_speed_mps, const FrenetScene& scene, const FrenetPlannerParams& p) {
  const FrenetCostWeights k{p.weight_jerk, p.weight_time, p.weight_deviation, p.weight_speed, p.weight_lateral, p.weight_longitudinal};
  FrenetChoice choice;
  for (double end_d : lateral_targets_m)
    for (double duration : durations(p))
      for (int i = 0; i < p.speed_samples; ++i) {
        const double end_speed = desired_speed_mps * i / (p.speed_samples - 1);
        FrenetCandidate c{frenet_trajectory(start, end_d, end_speed, duration), FrenetVerdict::kNotChecked};
        c.trajectory.cost = frenet_cost(c.trajectory, 0.0, desired_speed_mps, k, p.check_step_s);
        choice.candidates.push_back(std::move(c));
      }
  // Werling et al. §III-C: the candidates are checked in increasing cost, and the first valid one
  // is driven; the dearer ones need no check.
  std::vector<std::size_t> order(choice.candidates.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return choice.candidates[a].trajectory.cost < choice.candidates[b].trajectory.cost;
  });
  for (const std::size_t i : order) {
    FrenetCandidate& c = choice.candidates[i];
    c.verdict = check_trajectory(c.trajectory, scene);
    if (c.verdict != FrenetVerdict::kValid) continue;
    choice.best = c.trajectory;
    break;
  }
  return choice;
}

FrenetPlanner::FrenetPlanner(FrenetPlannerParams params) : params_(params) {
  MG_DEMAND(params_in_range(frenet_parameter_table(), params_) && params_.min_duration_s <= params_.max_duration_s);
}

FrenetStart FrenetPlanner::start_of(const WorldSnapshot& w) const {
  FrenetStart a;
  a.s_m = w.ego.x_m;
  a.s_dot_mps = ego_speed_mps(w);
  a.s_ddot_mps2 = w.ego.accel_mps2;
  a.d_m = w.ego.y_m;
  a.d_dot_mps = ego_lat_speed_mps(w);
  if (!memory_.driving) return a;
  // Laterally, plan on from where the driven trajectory has the ego now, while the ego is near it
  // (Werling et al.'s start from the previous trajectory): a plan from the measured state would
  // take the path tracker's lag for the planner's intent each cycle, and drift with it.
  const FrenetTrajectory& t = *memory_.driving;
  const double elapsed_s = w.time_s - memory_.planned_at_s;
  if (std::abs(t.d_at(elapsed_s) - w.ego.y_m) > kReplanFromMeasuredOffsetM) return a;
  a.d_m = t.d_at(elapsed_s);
  a.d_dot_mps = t.d_dot_at(elapsed_s);
  a.d_ddot_mps2 = elapsed_s <= t.duration_s ? t.lateral.d2(elapsed_s) : 0.0;
  return a;
}

PlanOutput FrenetPlanner::plan(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const double v = ego_speed_mps(w);
  const double desired_mps = params_.desired_speed_ratio * s.road.speed_limit_mps;
  const FrenetChoice choice =
      choose_frenet_trajectory(start_of(w), frenet_lateral_targets(w), desired_mps, frenet_scene(w, params_), params_);
  PlanOutput out;
  double accel = 0.0;
  if (choice.best) {
    const FrenetTrajectory& t = *choice.best;
    memory_ = {t, w.time_s};
    out.path = path_of(t, w, params_);
    const double cycle_s = s.params.sim.planner_cycle_s;  // the mean acceleration until the next plan
    accel = (t.s_dot_at(cycle_s) - t.s_dot_at(0.0)) / cycle_s;
    out.mode = mode_of(t, w);
    out.reason = "Frenet candidate to d = " + fixed_text(t.end_d_m, 2) + " m at " + fixed_text(t.end_speed_mps, 1) +
                 " m/s in " + fixed_text(t.duration_s, 1) + " s, cost " + fixed_text(t.cost, 2);
  } else {
    memory_ = {};
    out.path = sample_path(w.ego.x_m - kPathBehindM, w.ego.x_m + tracked_path_ahead_m(w), kPathStepM,
                           [y = w.ego.y_m](double) { return y; });
    accel = -s.ego.limits.brake_max_mps2;
    out.mode = "no_valid_trajectory";
    out.reason = "every one of " + std::to_string(choice.candidates.size()) + " Frenet candidates is invalid: braking in lane";
  }
  accel = std::clamp(accel, -s.ego.limits.brake_max_mps2, s.ego.limits.accel_max_mps2);
  const SpeedCommand cmd = speed_command_for_accel(v, accel, s.road.speed_limit_mps);
  out.target_speed_mps = cmd.target_speed_mps;
  out.accel_limit_mps2 = cmd.accel_limit_mps2;
  return out;
}

}  // namespace mg
