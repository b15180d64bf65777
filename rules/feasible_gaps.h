// The merges the progress rule offers (docs/rules.md, `progress`): which gaps of the rightmost
// main lane admit a Definition 1 merge from the ego's observed state at one step, shown by a
// witness merge that is comfortable and clear along its whole duration. Judged with the rules'
// own Definition 1 code (rules/definition1_gap.h); no planner code is involved.
#pragma once

#include <cstddef>
#include <vector>

#include "core/observed_trace.h"
#include "core/params.h"
#include "rules/definition1_gap.h"

namespace mg {

// A gap of the rightmost main lane that admits a Definition 1 merge from the ego's observed state
// at `step`, judged with the rules' own code (rules/definition1_gap.h): for rho = rho_m (or 1.5 or
// 2 rho_m: a merge that observably takes longer is read over its own duration; and 3 rho_m for an
// ego too slow to reach the turn-in by the midpoint of 2 rho_m even at its a_accel^max: from rest
// only a long merge reaches a midpoint a tracked path can turn in to), some v_e* in
// [progress_min_merge_speed_mps, speed limit] satisfies ineq. (1.1) and (1.2) by
// progress_gap_margin_m under both position models (the bounded-rate one starts from the ego's
// observed speed and changes it at its declared a_accel^max / a_brake^min, so a v_e* it cannot
// reach in time does not count), and at such a v_e* the ego's centre reaches the lane line
// (rho / 2 on) no sooner than the paper's sigmoid within progress_sideslip_fraction of the sideslip
// bound can turn in (shortest_turn_in_m),
// and from there covers at least its turn-out by rho (shortest_turn_out_m),
// and with its front still progress_gap_margin_m short of the side lane's end, and the whole body
// across the lane line before any corner comes within progress_gap_margin_m of that end (past it
// the road's edge is the lane line: on_road). A gap whose leader
// brakes harder than progress_leader_braking_mps2 does not count (Def. 1.2 assumes the leader
// holds its speed), nor one whose follower accelerates beyond its declared a_accel^max plus
// accel_tolerance_mps2 (Def. 1.1 bounds it by that). The merge must also be clear along its whole duration, not only at rho / 2 and
// rho: on the paper's sigmoid in X (its middle where the ego is at rho / 2, its peak curvature
// within the same share of the sideslip bound, driven on the speed profile toward v_e* with a peak
// lateral acceleration within progress_lat_accel_max_mps2),
// wherever the ego is laterally nearer a vehicle (of the target lane or the lane beyond) than
// D_lat plus progress_lateral_margin_m, it is D_lon plus progress_gap_margin_m behind it if ahead
// (a vehicle of the lane beyond where braking at its b_max from now would put it), and ahead of it
// until rho / 2 if it is a target-lane vehicle behind. Path shape and comfort beyond that are the
// planner's business.
struct FeasibleMerge {
  int follower_id = -1;  // -1: open gap
  int leader_id = -1;
  double merge_duration_s = 0.0;
  double ve_star_mps = 0.0;  // the slowest feasible v_e*
  double ve_max_mps = 0.0;   // the fastest
};
// The shortest X in which the paper's sigmoid path within progress_sideslip_fraction of the
// sideslip bound (sideslip_max_rad;
// kinematic sideslip, the centre of gravity at most half the length ahead of the rear axle) takes
// the ego's centre from Y = y_m, heading along the road, to the lane line (0 at or past it).
double shortest_turn_in_m(const ObservedTrace& t, const RuleParams& p, double y_m);
// The shortest X in which the same sigmoid takes the centre from the lane line to its end, heading
// along the road again (0 when the centre is at or past the line): a witness's second half.
double shortest_turn_out_m(const ObservedTrace& t, const RuleParams& p, double y_m);
std::vector<FeasibleMerge> def1_gaps_feasible(const ObservedTrace& t, const RuleParams& p, std::size_t step);

// Definition 1.2 counts on the gap's leader holding its speed. A leader seen braking harder than
// progress_leader_braking_mps2 does not, nor one closing on the vehicle ahead of it in its lane so
// fast that, holding its speed over rho, it would come within that vehicle's D_lon (RCPP eq. (1);
// RSS Def. 1): it must slow down for it, and the gap behind it shrinks as it does. That vehicle
// is where its own observed braking takes it, but no farther than the vehicles ahead of it let it
// go (it cannot drive through the next one). The gap is gaps[g] of the lane's gaps at the step
// (lane_gaps, in order: gaps[g + 1]'s follower is gaps[g]'s leader).
bool leader_holds_speed(const ObservedTrace& t, const RuleParams& p, std::size_t step,
                        const std::vector<GapIndices>& gaps, std::size_t g, double rho_s);

}  // namespace mg
