// The right of way of one observed merge attempt (rules/merge_attempts.h, which documents the
// bases): Definition 2 first (the acceptances, rules/acceptance_cover.h), then Definition 1 (the
// decision window's readings, rules/def1_reading.h), then none. Extraction and attribution stay
// apart: the attempt's span, entry, entered gap and crossing are read before (merge_attempts.cpp).
#pragma once

#include <vector>

#include "core/observed_trace.h"
#include "core/params.h"
#include "rules/coop_exchange.h"
#include "rules/definition1_gap.h"
#include "rules/merge_attempts.h"

namespace mg {

// What the attempts are read from: the trace, the rules' parameters, and what the situation
// already holds (rules/situation.h).
struct AttemptInputs {
  const ObservedTrace& t;
  const RuleParams& p;
  const std::vector<CoopExchange>& exchanges;
  const std::vector<GapIndices>& around;
};

// Sets a's basis, covers, Definition 1 reading, acceptance, fault, P_c checks and decision time.
// The decision window runs from window_from_s to the entry (or start); a run of good readings is
// credited back to credit_from_s (the previous attempt's end).
void judge_attempt_basis(const AttemptInputs& in, MergeAttempt& a, double window_from_s, double credit_from_s);

}  // namespace mg
