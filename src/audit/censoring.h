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
  bool right_of_way = false;        // the rules found the ego's right of way in what was observed
};

// nullopt when the rules observe no merge of the ego (e.g. a halt on the ramp): nothing to decide.
std::optional<DecisionWindow> decision_window(const ObservedTrace& t, double change_time_s);

// Whether the verdict `r` rests on what was not observed of the decision. A decision window cut
// by the recording matters only to a violated merge whose right of way the rules did not find in
// what was observed (more of the window can only add a right of way, which only waives duties);
// a vehicle next to the ego in the lane entered, recorded for only part of the decision window,
// matters only to a merge that holds (a vehicle unseen can only add duties). `v` gives the
// left-out vehicles' records.
std::optional<std::string> decision_censoring(const RecordingView& v, const MergeTrace& m, const DecisionWindow& w,
                                              const CheckResult& r, std::vector<std::string>& missing);

// After judging: the overall liable party's RSS violation rests on a danger (a pair both
// longitudinally and laterally unsafe) that lasted from the first step of `whole`, the merge's
// trace as built (where the recording of the pair begins), to the violation: nullopt when the
// blame is not censored. `r` may judge `whole` from a later step on.
struct CensoredBlame {
  std::string reason;
  std::string pair;                     // "vehicle 2 and vehicle 3"
  std::optional<std::size_t> end_step;  // the first step of `whole` at which the danger is over
};
std::optional<CensoredBlame> censored_blame(const ObservedTrace& whole, const CheckResult& r, const MergeTrace& m);

// The rule that gives the overall verdict its liable party: the earliest violated rule whose
// liable party is the overall one (nullptr when the trace holds).
const RuleResult* deciding_rule(const CheckResult& r);

// What the recording judges of an undetermined merge: the rules that need nothing before the
// window (the road, smoothness, sideslip, declared limits), one line each.
std::vector<std::string> judged_on_record(const CheckResult& r, const MergeTrace& m);

}  // namespace mg
