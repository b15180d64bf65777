// The `mobil` baseline: the model traffic simulators drive human drivers with (docs/baselines.md).
// Longitudinally the Intelligent Driver Model (Treiber, Hennecke, Helbing 2000): the ego follows
// its lane's leader, and in the side lane the lane's end as a standing obstacle, so that it stops
// before it. Laterally MOBIL (Kesting, Treiber, Helbing 2007): every cycle in the side lane it
// weighs the change to the main lane by the accelerations of itself and of the new follower, and
// changes when the safety criterion (the new follower brakes no harder than b_safe) and the
// incentive criterion (politeness p, threshold Delta a_th, a bias toward the main lane) hold. The
// change is a minimum-jerk lateral path of fixed duration at the speed of the decision; once
// begun it is driven to its end, following the main lane's leader. It has no RSS reasoning and
// no V2V: it is what a user would pick instead of RCPP, not tuned to pass the rules.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "planner/mobil.h"
#include "planner/param_table.h"
#include "planner/planner.h"

namespace mg {

// The planner's own parameters (defaults: IDM's of Treiber et al. 2000, Table 1 at highway speed;
// MOBIL's of Kesting et al. 2007). Ranges: mobil_parameter_table().
struct MobilPlannerParams {
  double desired_speed_ratio = 1.0;       // IDM v0 as a share of the road's speed limit
  double time_headway_s = 1.6;            // IDM T
  double min_gap_m = 2.0;                 // IDM s0
  double max_accel_mps2 = 0.73;           // IDM a
  double comfort_brake_mps2 = 1.67;       // IDM b
  double exponent = 4.0;                  // IDM delta
  double politeness = 0.5;                // MOBIL p
  double safe_brake_mps2 = 4.0;           // MOBIL b_safe
  double threshold_mps2 = 0.1;            // MOBIL Delta a_th
  double bias_mps2 = 0.3;                 // MOBIL Delta a_bias toward the main lane
  double lane_change_duration_s = 4.0;    // of the lateral path, at the speed of the decision
};
const std::vector<ParamRow<MobilPlannerParams>>& mobil_parameter_table();
IdmParams idm_params_of(const MobilPlannerParams& p, double speed_limit_mps);
MobilParams mobil_params_of(const MobilPlannerParams& p);

// A lane change's lateral path over X: Y from start_y_m to target_y_m over length_m along the
// minimum-jerk blend 10 u^3 - 15 u^4 + 6 u^5 (Flash & Hogan 1985), u = (X - start_x_m) / length_m:
// zero lateral slope and curvature at both ends; Y is start_y_m before and target_y_m after.
double min_jerk_blend(double u);
struct LaneChangePath {
  double start_x_m = 0.0;
  double start_y_m = 0.0;
  double length_m = 1.0;
  double target_y_m = 0.0;
  double end_x_m() const { return start_x_m + length_m; }
  double y_at(double x_m) const;
};
// A lane change decided at the ego's current state: its length is the distance the fixed duration
// covers at the ego's speed (at least kMinLaneChangeSpeedMps: a change from rest still moves on).
inline constexpr double kMinLaneChangeSpeedMps = 2.0;
LaneChangePath lane_change_from(const WorldSnapshot& w, double target_y_m, const MobilPlannerParams& p);

// MOBIL's reading of a change from the side lane to the main lane at this instant.
struct MobilDecision {
  MobilSituation situation;
  bool gaps_open = false;  // both new neighbours leave a positive bumper gap (a change needs room)
  bool safe = false;       // eq. (2)
  bool incentive = false;  // eq. (3)
  bool change = false;     // all three
  std::string reason;      // one line: the accelerations and the verdict
};
MobilDecision decide_mobil(const WorldSnapshot& w, const MobilPlannerParams& p);

// The ego's IDM acceleration in the lane centred at lane_y_m (its leader there, and in the side
// lane its end as a standing obstacle, whichever is nearer), inside its declared limits.
double mobil_lane_accel_mps2(const WorldSnapshot& w, double lane_y_m, bool side_lane_end_ahead, const MobilPlannerParams& p);

// The planner's state: keeping the side lane until MOBIL changes; changing along a committed path;
// in the main lane (changed, or started there), for good.
struct MobilKeepingSideLane {};
struct MobilChangingLane {
  LaneChangePath path;
};
struct MobilInMainLane {};
using MobilPhase = std::variant<MobilKeepingSideLane, MobilChangingLane, MobilInMainLane>;

class MobilPlanner : public Planner {
 public:
  explicit MobilPlanner(MobilPlannerParams params = {});
  std::string name() const override { return "mobil"; }
  PlanOutput plan(const WorldSnapshot& w) override;
  const MobilPhase& phase() const { return phase_; }

 private:
  void advance_phase(const WorldSnapshot& w);
  MobilPlannerParams params_;
  MobilPhase phase_;
};

}  // namespace mg
