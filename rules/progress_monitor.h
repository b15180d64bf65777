// Progress (RCPP Def. 1.3: halt only while space is insufficient): the ego must not stay at rest
// in the side lane for longer than progress_grace_s while a Definition 1 gap stays feasible by
// progress_gap_margin_m. (Braking toward a stop cannot be told from braking toward a slow merge
// by observation, so the grace period counts from the standstill.)
#pragma once

#include <cstddef>
#include <optional>

#include "rules/monitor.h"

namespace mg {

// Whether some gap of the rightmost main lane admits a Definition 1 merge from the ego's observed
// state at `step`, judged with the rules' own code (rules/definition1_gap.h): for rho_m, some v_e*
// in [progress_min_merge_speed_mps, speed limit] satisfies ineq. (1.1) and (1.2) by margin_m, at the
// slowest such v_e* the ego's front reaches the merge midpoint (rho_m / 2 on) margin_m before the
// side lane's end, and at least progress_min_room_m of side lane is left ahead of its front.
// A gap whose leader brakes harder than leader_braking_mps2 does not count (Def. 1.2 assumes the
// leader holds its speed). Path shape and comfort are the planner's business, not the rule's.
struct FeasibleMerge {
  int follower_id = -1;  // -1: open gap
  int leader_id = -1;
  double merge_duration_s = 0.0;
  double ve_star_mps = 0.0;
};
std::optional<FeasibleMerge> def1_gap_feasible(const ObservedTrace& t, const RuleParams& p, std::size_t step,
                                               double margin_m, double leader_braking_mps2);

MonitorOutput monitor_progress(const MonitorContext& ctx);

}  // namespace mg
