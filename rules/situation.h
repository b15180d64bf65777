// What happened in a trace, built once before any rule judges it (spec §8, point
// 26): the ego's merge phases, the V2V exchanges, the gap around the ego at every step, the
// merge attempts with the right of way toward each vehicle of the gap entered, and the right of
// way over time. Every rule is then a pure check over the trace and this; liability and the
// report come after (rules/liability.h, rules/check.h).
#pragma once

#include <vector>

#include "core/observed_trace.h"
#include "rules/coop_exchange.h"
#include "rules/definition1_gap.h"
#include "rules/liability.h"
#include "rules/merge_attempts.h"
#include "rules/merge_phases.h"

namespace mg {

struct Situation {
  MergePhases phases;
  std::vector<CoopExchange> exchanges;   // rules/coop_exchange.h
  std::vector<GapIndices> around;        // gap_around_ego at every step
  MergeAttempts attempts;                // rules/merge_attempts.h
  RightOfWay row;                        // rules/liability.h
};

Situation observe_situation(const ObservedTrace& t, const RuleParams& p);

}  // namespace mg
