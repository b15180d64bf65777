// The planner's own account of a run (the trace's planner_annotations), as the reports show it
// beside the verdict: one entry per change of reported mode, and whether the
// observation agrees where the planner claimed a merge. Read only by the report writers; no rule
// reads it.
#pragma once

#include <string>
#include <vector>

#include "rules/check.h"

namespace mg {

struct PlannerClaim {
  double time_s = 0.0;
  std::string mode;
  std::string reason;
  bool disagrees = false;  // a merge the planner reported while the observed right of way was not the ego's
};

// Empty when the trace has no annotations in the built-in planners' form ({"decisions": [...]}).
std::vector<PlannerClaim> planner_account(const CheckResult& r);

}  // namespace mg
