// RCPP's Definition 1 stage (RCPP §II-B/C, spec §5-§6): at one decision instant, the best gap of
// the target lane, its v_e* and the sigmoid into it, over the merge durations. "No gap" is a
// normal outcome (nullopt), with the reasons.
#pragma once

#include <optional>
#include <string>

#include "planner/rcpp_decision.h"
#include "planner/sigmoid.h"

namespace mg {

// Definition 1 at one decision instant: the best gap and sigmoid over the merge durations.
struct Def1Plan {
  RcppDecision decision;  // mode kDef1Merge, gap, v_e* interval and choice, P_c bounds/choice, kappa
  Sigmoid sigmoid;
  double ve_star_mps = 0.0;
  bool late_start = false;  // its sigmoid starts more than kPromptStartS of the ego's ramp ahead
};

// kRhoM: the configured merge duration (raised to a comfortable one); kLonger: the longer ones of
// kMergeDurationFactors, tried only after Definition 2 (the paper's order: Def. 1 at rho_m, then
// cooperation, then the extension); kFlat: every duration with sigmoids flatter than
// kappa_min_per_m only, the last resort before a halt. The shortest duration with a plan that
// starts promptly wins, up to 2 rho once a late plan is found; failing that, the shortest with a
// late one. nullopt when no gap is feasible; `why` then gets the reasons.
enum class MergeDurations { kRhoM, kLonger, kFlat };
std::optional<Def1Plan> plan_definition1(const WorldSnapshot& w, MergeDurations durations, std::string* why);

}  // namespace mg
