#include "planner/tripfield_planner.h"

#include <algorithm>
#include <cmath>

#include "core/fixed_text.h"
#include "planner/definition1.h"
#include "planner/potential_field.h"
#include "planner/rcpp_params.h"
#include "planner/world_view.h"

namespace mg {
namespace {

constexpr double kStepM = 2.0;
constexpr double kBehindM = 10.0;
constexpr double kGradientDeltaM = 0.05;  // central difference for dU/dY
constexpr double kLookaheadS = 1.0;       // speed adaptation looks this far ahead

struct FieldModel {
  const WorldSnapshot* w;
  const TripFieldCoefficients* k;
  double road_beta;  // RCPP's (eq. 3): the two fields draw the road marks alike

  double obstacles(double x, double y, double t) const {
    const PlannerSetup& s = *w->setup;
    double u = 0.0;
    for (const ObservedVehicle& o : w->others) {
      const double v_o = std::max(0.0, o.state.road_vx_mps());
      u += tripfield_obstacle_potential(x - (o.state.x_m + v_o * t), y - o.state.y_m, v_o,
                                        0.5 * (o.size.length_m + s.ego.size.length_m),
                                        0.5 * (o.size.width_m + s.ego.size.width_m), *k);
    }
    return u;
  }

  // The lane attraction's growth toward the side lane's end (a function of x alone).
  double urgency(double x) const {
    const Road& road = w->setup->road;
    return 1.0 + k->end_urgency_gain * std::exp(-std::max(0.0, road.side_lane_end_x_m - x) / k->end_urgency_length_m);
  }

  double total(double x, double y, double t, double urgency_at_x) const {
    const PlannerSetup& s = *w->setup;
    const Road& road = s.road;
    const bool side_lane_here = x >= road.side_lane_start_x_m && x <= road.side_lane_end_x_m;
    const double right_y = side_lane_here ? -1.5 * road.lane_width_m : -0.5 * road.lane_width_m;
    const double left_y = (road.main_lanes - 0.5) * road.lane_width_m;
    return road_mark_potential(y, right_y, false, s.ego.size.width_m, road_beta) +
           road_mark_potential(y, left_y, true, s.ego.size.width_m, road_beta) +
           obstacles(x, y, t) + 0.5 * k->lane_attraction * urgency_at_x * y * y;
  }
};

}  // namespace

double tripfield_obstacle_potential(double dx_m, double dy_m, double obstacle_speed_mps, double length_sum_m,
                                    double width_sum_m, const TripFieldCoefficients& k) {
  // Elongated in the direction of travel: ahead of the obstacle by its headway, behind by half.
  const double ax = length_sum_m + (dx_m >= 0.0 ? 1.0 : 0.5) * obstacle_speed_mps * k.headway_s;
  const double ay = width_sum_m + k.lateral_margin_m;
  return k.obstacle_gain * std::exp(-(dx_m * dx_m / (ax * ax) + dy_m * dy_m / (ay * ay)));
}

PlanOutput TripFieldPlanner::plan(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const Road& road = s.road;
  const FieldModel field{&w, &k_, rcpp_params(s).pf_road_beta};
  const double v_e = ego_speed_mps(w);
  const double v_path = std::max(v_e, 1.0);
  const double y_min = road.side_lane_y_m();
  const double y_max = (road.main_lanes - 1) * road.lane_width_m;
  PlanOutput out;
  out.path.push_back({w.ego.x_m - kBehindM, w.ego.y_m});
  double y = w.ego.y_m;
  // Each point follows from the ones before it, so a shorter path is the same path, cut (one step
  // past tracked_path_ahead_m).
  const double ahead_m = tracked_path_ahead_m(w) + kStepM;
  for (double x = w.ego.x_m; x <= w.ego.x_m + ahead_m; x += kStepM) {
    out.path.push_back({x, y});
    const double t = (x - w.ego.x_m) / v_path;
    const double urgency = field.urgency(x);
    const double grad = (field.total(x, y + kGradientDeltaM, t, urgency) - field.total(x, y - kGradientDeltaM, t, urgency)) /
                        (2.0 * kGradientDeltaM);
    const double dy = std::clamp(-k_.gradient_step * grad * kStepM, -k_.max_slope * kStepM, k_.max_slope * kStepM);
    y = std::clamp(y + dy, y_min, y_max);
    if (x + kStepM > road.side_lane_end_x_m) y = std::max(y, -0.5 * road.lane_width_m);  // no side lane there
  }
  // Speed adapted to the obstacle field a little ahead on the path.
  const double x_ahead = w.ego.x_m + v_e * kLookaheadS;
  const double u_ahead = field.obstacles(x_ahead, w.ego.y_m, kLookaheadS);
  const double cruise = s.ego.speed_mps > 0.0 ? std::min(s.ego.speed_mps, road.speed_limit_mps)
                                              : 0.8 * road.speed_limit_mps;
  double target = cruise / (1.0 + k_.speed_field_gain * u_ahead);
  double brake = s.ego.limits.brake_min_mps2;
  if (w.ego.y_m < -0.5 * road.lane_width_m) {  // still in the side lane: stop before its end
    const double stop_x = road.side_lane_end_x_m - 0.5 * s.ego.size.length_m - s.params.planner.halt_margin_m;
    target = std::min(target, halt_speed_cap_mps(w.ego.x_m, stop_x, 0.5 * s.ego.limits.brake_min_mps2));
    const double room = stop_x + s.params.planner.halt_margin_m - w.ego.x_m;
    if (room <= 0.0 || v_e * v_e / (2.0 * room) > 0.8 * brake) brake = s.ego.limits.brake_max_mps2;
  }
  out.target_speed_mps = target;
  out.accel_limit_mps2 = target >= v_e ? s.ego.limits.accel_max_mps2 : brake;
  out.mode = "potential_field";  // no discrete decision
  out.reason = "TriPField-style baseline: path follows the field gradient; obstacle field ahead " +
               fixed_text(u_ahead, 2) + ", target " + fixed_text(target, 2) + " m/s";
  return out;
}

}  // namespace mg
