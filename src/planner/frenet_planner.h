// The `frenet` baseline: a sampling-based trajectory planner in the Frenet frame in the style of
// Werling, Ziegler, Kammel, Thrun (ICRA 2010), the planner the Apollo and Autoware lattice
// planners descend from (docs/baselines.md). Every cycle it samples lateral end offsets (the side
// lane's centre while the side lane goes on, the main lane's centre) x manoeuvre durations x
// target speeds, joins each lateral quintic with a velocity-keeping quartic (planner/frenet.h),
// discards the candidates that break the acceleration or curvature limits or meet an obstacle
// predicted at constant velocity (or the side lane's end), and drives the cheapest one (jerk +
// time + deviation from the main lane + deviation from the desired speed) until the next cycle.
// With no valid candidate it brakes as hard as it may in its lane. It has no RSS reasoning and no
// V2V: it is what a user would pick instead of RCPP, not tuned to pass the rules.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "planner/frenet.h"
#include "planner/param_table.h"
#include "planner/planner.h"

namespace mg {

// The planner's own parameters (cost weights: the values of the common open implementations of
// Werling et al., e.g. PythonRobotics' frenet_optimal_trajectory). Ranges: frenet_parameter_table().
struct FrenetPlannerParams {
  double min_duration_s = 2.0;         // shortest manoeuvre duration T sampled
  double max_duration_s = 6.0;         // longest (also the collision check's horizon)
  double duration_step_s = 1.0;        // between sampled durations
  int speed_samples = 7;               // target speeds, evenly from 0 to the desired speed
  double desired_speed_ratio = 1.0;    // desired speed as a share of the road's speed limit
  double weight_jerk = 0.1;            // k_j
  double weight_time = 0.1;            // k_t
  double weight_deviation = 1.0;       // k_d, on the end offset from the main lane's centre
  double weight_speed = 1.0;           // k_s, on the end speed's difference from the desired speed
  double weight_lateral = 1.0;         // k_lat
  double weight_longitudinal = 1.0;    // k_lon
  double max_curvature_per_m = 0.2;    // path curvature limit
  double max_lat_accel_mps2 = 2.0;     // |d''| limit
  double obstacle_margin_m = 0.5;      // added to every obstacle's extent in the collision check
  double check_step_s = 0.1;           // sampling of the checks and of the cost's jerk integral
};
const std::vector<ParamRow<FrenetPlannerParams>>& frenet_parameter_table();

// The candidates of one cycle with their verdicts: every candidate cheaper than the chosen one is
// invalid, the dearer ones are not checked (kNotChecked).
struct FrenetCandidate {
  FrenetTrajectory trajectory;
  FrenetVerdict verdict = FrenetVerdict::kNotChecked;
};
struct FrenetChoice {
  std::vector<FrenetCandidate> candidates;  // in sampling order
  std::optional<FrenetTrajectory> best;     // the cheapest valid candidate, none if none is valid
};

// The scene of a snapshot: the other vehicles predicted at constant velocity, the ego's declared
// longitudinal limits, the parameters' limits, margin and horizon.
FrenetScene frenet_scene(const WorldSnapshot& w, const FrenetPlannerParams& p);
// The lateral end offsets sampled from the ego's position: the side lane's centre while the ego's
// front is short of the side lane's end, and the main lane's centre.
std::vector<double> frenet_lateral_targets(const WorldSnapshot& w);
// Samples, then checks in increasing cost until a candidate is valid (ties: the first sampled).
FrenetChoice choose_frenet_trajectory(const FrenetStart& start, const std::vector<double>& lateral_targets_m,
                                      double desired_speed_mps, const FrenetScene& scene, const FrenetPlannerParams& p);

// What the planner remembers: the trajectory it drives, from when. The next cycle's lateral start
// state is that trajectory's now (as Werling et al. start from the previous trajectory) while the
// ego is within kReplanFromMeasuredOffsetM of it, its measured one otherwise.
inline constexpr double kReplanFromMeasuredOffsetM = 0.5;
struct FrenetMemory {
  std::optional<FrenetTrajectory> driving;
  double planned_at_s = 0.0;
};

class FrenetPlanner : public Planner {
 public:
  explicit FrenetPlanner(FrenetPlannerParams params = {});
  std::string name() const override { return "frenet"; }
  PlanOutput plan(const WorldSnapshot& w) override;
  const FrenetMemory& memory() const { return memory_; }

 private:
  FrenetStart start_of(const WorldSnapshot& w) const;
  FrenetPlannerParams params_;
  FrenetMemory memory_;
};

}  // namespace mg
