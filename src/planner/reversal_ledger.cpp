#include "planner/reversal_ledger.h"

#include <algorithm>

namespace mg {

void ReversalLedger::observe(const WorldSnapshot& w) {
  const PlannerSetup& s = *w.setup;
  const RuleParams& rules = s.params.rules;
  if (!detector_) {
    detector_.emplace(s.road, rules, s.ego.size, w.ego.y_m);
    centre_y_m_ = s.road.side_lane_y_m() + rules.merge_abort_offset_m;
    direction_ = LateralDirection(rules.lat_speed_hysteresis_mps);
    per_approach_ = rules.max_lat_speed_sign_changes_per_merge;
  }
  const double vy_mps = w.ego.road_vy_mps();
  const MergePhaseStep phase = detector_->step(w.ego.y_m, vy_mps, w.ego.yaw_rad);
  if (phase.start) {
    // As the rule classifies a start: from the centre if the ego was back there since the last
    // one (the first start is), else off the centre.
    (!any_start_ || returned_ ? from_centre_ : after_reversal_) += 1;
    any_start_ = true;
    returned_ = false;
    in_attempt_ = true;
  }
  if (phase.abort || phase.midpoint) in_attempt_ = false;
  if (any_start_ && w.ego.y_m < centre_y_m_) returned_ = true;
  if (!any_start_) return;  // the rule counts reversals from the first start
  if (direction_.reverses(vy_mps)) ++changes_;
}

int ReversalLedger::allowed_with_merge() const {
  int approaches_then = approaches();
  // A merge started now is a new approach unless the detector's attempt is still under way: from
  // the centre always, off it only the first time.
  if (!in_attempt_ && (!any_start_ || returned_ || after_reversal_ == 0)) ++approaches_then;
  return per_approach_ * std::max(approaches_then, 1);
}

bool ReversalLedger::can_afford_merge(bool turns_away_first) const {
  if (!detector_) return true;  // nothing observed yet
  const int away = turns_away_first && direction_.sign() > 0 ? 1 : 0;           // moving toward the lane, it turns away
  const int toward = direction_.sign() < 0 || turns_away_first ? 1 : 0;         // then toward the lane
  return changes_ + away + toward + 1 <= allowed_with_merge();      // and back, should it abort
}

std::string reversal_deferral_reason(const ReversalLedger& ledger, bool turns_away_first) {
  return "merge deferred until the ego is back at its side-lane centre: " + std::to_string(ledger.changes()) +
         " lateral-speed reversal(s) so far, and a merge started now" +
         (turns_away_first ? " (its path first turning away from the main lane)" : "") +
         " and aborted would exceed the " + std::to_string(ledger.allowed_with_merge()) +
         " allowed (smoothness_oscillation)";
}

}  // namespace mg
