// Revising a committed Definition 1 merge (RCPP §II-B decides it once, at T_dec, from the world
// then): a new decision replaces it when it starts sooner, when it is faster than a crawl, or, in
// place of an abort, when the merge no longer fits its gap but a new one into the same gap does
// along the sigmoid the ego is already on. docs/planner.md, "Re-checking and aborting" and "Not
// letting a feasible gap pass".
#pragma once

#include "planner/committed_merge.h"
#include "planner/planner.h"

namespace mg {

// RCPP's merging phase: the committed merge and when its replacements are next searched for.
struct Merging {
  CommittedMerge merge;
  double next_sooner_search_s = -1.0;
  double next_faster_search_s = -1.0;
};

// Each search runs every kSoonerMergeEveryS; a sooner merge's sigmoid starts at least
// kSoonerStartM nearer than the committed one's.
inline constexpr double kSoonerMergeEveryS = 0.5;
inline constexpr double kSoonerStartM = 10.0;

// Until the ego reaches the committed sigmoid's start: a merge whose sigmoid starts sooner.
void take_sooner_merge(Merging& merging, const WorldSnapshot& w);
// While the committed merge is a crawl and can still be aborted: a merge into the same gap at a
// speed the progress rule offers.
void take_faster_merge(Merging& merging, const WorldSnapshot& w);
// For a merge the re-check would abort: a new decision into the same gap along a sigmoid the ego
// is already on, if there is one (true when the merge was replaced).
bool replan_in_place(Merging& merging, const WorldSnapshot& w);

}  // namespace mg
