#include "planner/merge_revision.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/fixed_text.h"
#include "planner/definition1_search.h"
#include "planner/merge_path.h"
#include "planner/rcpp_world.h"
#include "planner/sigmoid.h"

namespace mg {
namespace {

// Whether the gap's leader is not yet ahead of the ego (it is passing it, or no such vehicle is seen).
bool leader_not_ahead(const WorldSnapshot& w, const Gap& gap) {
  if (gap.leader_id < 0) return false;
  const ObservedVehicle* leader = observed_vehicle(w, gap.leader_id);
  return !leader || leader->state.x_m <= w.ego.x_m;
}

// The committed merge becomes plan's, its reason prefixed by why, its path starting no farther
// from the main lane than the ego is.
void replace_merge(Merging& merging, const WorldSnapshot& w, Def1Plan plan, const std::string& why, bool from_hold) {
  plan.decision.reason = why + plan.decision.reason;
  merging.merge = CommittedMerge{plan.sigmoid, plan.ve_star_mps, std::move(plan.decision),
                                 std::max(w.ego.y_m, plan.sigmoid.offset_m), from_hold};
}

}  // namespace

// RCPP decides a Def. 1 merge at T_dec from the world then (RCPP §II-B); one decided with a long
// duration has its sigmoid start far ahead (P_c at rho/2), and the ego drove on in its side lane
// for seconds while a shorter merge had become feasible (progress; a campaign finding). Until the
// ego reaches the sigmoid's start, a new decision whose sigmoid starts kSoonerStartM nearer
// replaces it: nothing of the first merge has been driven yet.
void take_sooner_merge(Merging& merging, const WorldSnapshot& w) {
  const CommittedMerge& m = merging.merge;
  const double start_x_m = m.sigmoid.x_at_fraction_m(kSigmoidEndFraction);
  if (m.decision.mode != DecisionMode::kDef1Merge || w.ego.x_m >= start_x_m - kSoonerStartM) return;
  if (w.time_s + 1e-9 < merging.next_sooner_search_s) return;
  merging.next_sooner_search_s = w.time_s + kSoonerMergeEveryS;
  for (const MergeDurations durations : {MergeDurations::kRhoM, MergeDurations::kLonger}) {
    auto plan = plan_definition1(w, durations, nullptr);
    if (!plan || plan->sigmoid.x_at_fraction_m(kSigmoidEndFraction) > start_x_m - kSoonerStartM) continue;
    replace_merge(merging, w, std::move(*plan),
                  "a sooner merge replaces the one decided at t = " + fixed_text(m.decision.time_s, 2) + " s: ",
                  m.from_hold);
    return;
  }
}

// A crawl (a Definition 1 merge at a v_e* no faster than crawl_speed_mps, decided when nothing
// faster was feasible) is replaced, until it can no longer be aborted, by a new decision into the
// same gap at a speed the progress rule offers (progress_min_merge_speed_mps) once one exists; its
// path keeps the ego's offset (from_hold) so nothing is reversed. A crawl at 1.1 m/s decided
// behind a leader starting from rest went on, 5 cm of lateral speed a second, after the leader had
// pulled away and a merge at 5 m/s was feasible, and the progress rule failed the wait (a campaign
// finding). Not into another gap: a crawl behind a stopped vehicle replaced by a 23 s merge ahead
// of it held the ego at its offset while that merge's sigmoid lay far ahead (progress). Nor a merge
// at more than a crawl: one at 4.5 m/s replaced by one at 8 m/s was aborted 1.5 s later, and the
// hold let the gap go (progress; a campaign finding).
void take_faster_merge(Merging& merging, const WorldSnapshot& w) {
  const CommittedMerge& m = merging.merge;
  const double slowest_mps = w.setup->params.rules.progress_min_merge_speed_mps;
  if (m.decision.mode != DecisionMode::kDef1Merge || m.target_speed_mps > crawl_speed_mps(*w.setup) ||
      m.committed(w.ego.y_m))
    return;
  if (w.time_s + 1e-9 < merging.next_faster_search_s) return;
  merging.next_faster_search_s = w.time_s + kSoonerMergeEveryS;
  for (const MergeDurations durations : {MergeDurations::kRhoM, MergeDurations::kLonger}) {
    auto plan = plan_definition1(w, durations, nullptr);
    if (!plan || plan->ve_star_mps < slowest_mps || plan->decision.gap != m.decision.gap) continue;
    replace_merge(merging, w, std::move(*plan),
                  "a faster merge replaces the crawl decided at t = " + fixed_text(m.decision.time_s, 2) + " s: ", true);
    return;
  }
}

// A Definition 1 merge the re-check would abort is re-planned in place when a new decision now
// merges into the same gap along a sigmoid the ego is already on (within kTurnAwayM; its path
// keeps the ego's offset over those centimetres, from_hold), so nothing is reversed, while an
// abort's hold let the gap go (a campaign finding: a 16 s merge behind a vehicle overtaking the
// ego, aborted when that vehicle's braking at 0.25 m/s2, below what Def. 1.2's constant speed is
// taken to allow, moved its bound 8 s ahead; the gap was still there, and the progress rule
// failed the wait).
bool replan_in_place(Merging& merging, const WorldSnapshot& w) {
  const CommittedMerge& m = merging.merge;
  if (m.decision.mode != DecisionMode::kDef1Merge || !m.decision.gap) return false;
  for (const MergeDurations durations : {MergeDurations::kRhoM, MergeDurations::kLonger}) {
    auto plan = plan_definition1(w, durations, nullptr);
    if (!plan || plan->decision.gap != m.decision.gap) continue;
    // Only a sigmoid the ego is already on: one that starts farther ahead would hold the ego at
    // its offset first, its midpoint would come later than planned, and the judge reads the right
    // of way over the longer merge the ego then drove (def1_1_gap failed by 7 m where the abort
    // had held; a campaign finding). And, while the gap's leader has yet to pass the ego, one
    // along which the ego is heading: a path drawn from the ego's offset (merge_sigmoid) gentler
    // than the crawl it replaced put the still-turned ego's corner over the lane line ahead of the
    // vehicle it meant to merge behind (a campaign finding; heads_along).
    const CommittedMerge on_path{plan->sigmoid, plan->ve_star_mps, plan->decision, plan->sigmoid.offset_m, false};
    if (turns_away_first(on_path, w) || (leader_not_ahead(w, *m.decision.gap) && !heads_along(on_path, w))) return false;
    replace_merge(merging, w, std::move(*plan),
                  "the merge decided at t = " + fixed_text(m.decision.time_s, 2) +
                      " s no longer fits (P_c bounds crossed or lane occupied); re-planned into its gap: ",
                  true);
    return true;
  }
  return false;
}

}  // namespace mg
