// What a recording cannot tell about a merge (docs/audit.md "Censoring"). Definition 1 judges a
// merge at its decision, in the window [start - W, entry] (rules/merge_attempts.h): a merge
// already under way at the first judged instant, a decision window reaching back before the
// records of the ego or its participants, or a vehicle near the gap recorded for only part of
// that window, leaves the decision unobserved. A danger already under way at the first judged
// instant has an unrecorded beginning: whether the front vehicle cut in or the rear one closed
// in, and when a response fell due, is not known, so a blame resting on it is not given.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "audit/merge_trace.h"
#include "core/observed_trace.h"
#include "rules/check.h"

namespace mg {

// The ego's decision window as the rules observe it.
struct DecisionWindow {
  bool under_way_at_first = false;  // the merge had begun (or crossed the line) at the first step
  double from_s = 0.0;              // start - W
  double to_s = 0.0;                // entry (or start)
  double start_s = 0.0;
};

// nullopt when the rules observe no merge of the ego (e.g. a halt on the ramp): nothing to decide.
std::optional<DecisionWindow> decision_window(const ObservedTrace& t, double change_time_s);

// Censoring before judging: the decision or its gap's vehicles not observed. `v` gives the
// left-out vehicles' records (where they were over the decision window).
std::optional<std::string> decision_censoring(const RecordingView& v, const MergeTrace& m, const DecisionWindow& w,
                                              std::vector<std::string>& missing);

// After judging: the overall liable party's RSS violation rests on a danger (a pair both
// longitudinally and laterally unsafe) that lasted from the first judged step to it. nullopt
// when the blame is not censored.
std::optional<std::string> censored_blame(const ObservedTrace& t, const CheckResult& r, const MergeTrace& m);

// The rule that gives the overall verdict its liable party: the earliest violated rule whose
// liable party is the overall one (nullptr when the trace holds).
const RuleResult* deciding_rule(const CheckResult& r);

// What the recording judges of an undetermined merge: the rules that need nothing before the
// window (the road, smoothness, sideslip, declared limits), one line each.
std::vector<std::string> judged_on_record(const CheckResult& r, const MergeTrace& m);

}  // namespace mg
