// Progress (RCPP Def. 1.3: halt only while space is insufficient): the ego must not stay
// halted, or keep braking to a halt, in the side lane for longer than progress_grace_s while a
// Definition 1 gap stays feasible by progress_gap_margin_m.
#pragma once

#include <optional>

#include "planner/definition1.h"
#include "rules/monitor.h"

namespace mg {

// v_e* candidates, evenly over [0, speed limit]: the planner's shared grid.
inline constexpr int kProgressSpeedSamples = kDef1SpeedGridSteps;

// Whether some gap of the rightmost main lane admits a Definition 1 merge from the ego's state
// at `step`: for one of the merge durations, a v_e* in [0, speed limit] satisfies ineq. (1) and
// (2) with `margin_m` (the planner's own Definition 1 margins, planner/definition1.h: the paper's
// literal form and the bounded-rate form of spec §4 must both hold), an admissible sigmoid
// (planner/merge_path.h: drivable, comfortable, completed in time) has its midpoint where the ego
// is at rho/2 and passes the occupancy check, and the ego's right edge leaves the side lane
// margin_m before the planner's exit limit (side_exit_limit_x_m). A gap whose leader brakes harder than
// leader_braking_mps2 does not count (Def. 1.2 assumes the leader holds its speed).
struct FeasibleMerge {
  int follower_id = -1;  // -1: open gap
  int leader_id = -1;
  double merge_duration_s = 0.0;
  double ve_star_mps = 0.0;
};
std::optional<FeasibleMerge> def1_gap_feasible(const Scenario& s, const TraceStep& step, double margin_m,
                                               double leader_braking_mps2);

MonitorOutput monitor_progress(const MonitorContext& ctx);

}  // namespace mg
