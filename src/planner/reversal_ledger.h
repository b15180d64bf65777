// The ego's own merge approaches and lateral-speed reversals, counted as the smoothness rule counts
// them (rules/smoothness_monitor.cpp; docs/spec_rules.md, `smoothness_oscillation`): each approach
// allows a few sign changes of the lateral speed; a start after the ego came back to its side-lane
// centre is a new approach, and only one start off the centre is. RCPP aborts a merge whose gap
// closes (§II-B) and may decide a new one at once; against a vehicle that keeps opening and closing
// the gap, merges decided and aborted before the ego was back at its centre wove beyond the rule's
// allowance (merge-abort cycling; a campaign finding). So RCPP starts a merge only while an abort
// of it would still stay within that allowance, and otherwise goes back to its centre first.
// The ledger reads what the planner observes (its own state each cycle) with the scenario's rule
// parameters (`params.rules`), the same thresholds the judge applies to the trace.
#pragma once

#include <optional>
#include <string>

#include "core/merge_phase_detector.h"
#include "planner/planner.h"

namespace mg {

class ReversalLedger {
 public:
  // The ego's state this cycle (once per cycle, in time order).
  void observe(const WorldSnapshot& w);

  // Whether a merge started now may still be aborted within the allowance: the lateral speed turns
  // toward the main lane (a change if it last pointed away) and, should the merge abort, back. A
  // merge whose path lies below the ego (turns_away_first: one begun on the way back from an
  // abort follows its sigmoid) first takes it away from the main lane: one change more for an
  // ego moving toward the lane.
  bool can_afford_merge(bool turns_away_first = false) const;

  // The sign changes so far, the merge approaches the rule credits so far, and the allowance a
  // merge started now would have.
  int changes() const { return changes_; }
  // The lateral speed last pointed toward the main lane (beyond the hysteresis, since the first
  // start): moving away from it now would be a sign change.
  bool last_moved_out() const { return direction_.sign() > 0; }
  int approaches() const { return from_centre_ + (after_reversal_ > 0 ? 1 : 0); }
  int allowed_with_merge() const;

 private:
  std::optional<MergePhaseDetector> detector_;
  double centre_y_m_ = 0.0;  // below this Y the ego is back at its side-lane centre
  int per_approach_ = 0;
  bool any_start_ = false;
  bool in_attempt_ = false;   // the detector's attempt under way (started, not aborted)
  bool returned_ = true;      // back at the centre since the last start
  int from_centre_ = 0;       // starts from the centre
  int after_reversal_ = 0;    // starts off the centre (the rule credits one)
  LateralDirection direction_;  // the lateral speed's direction since the first start
  int changes_ = 0;           // its sign changes since the first start
};

// Why a merge waits for the ego to be back at its centre (the decision's reason).
std::string reversal_deferral_reason(const ReversalLedger& ledger, bool turns_away_first);

}  // namespace mg
