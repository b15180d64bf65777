// A simulated run judged by the rule checker: simulate, turn the run into its observable trace
// (check/observed_run.h) and judge that alone (rules/check.h). What `check`, `fuzz` and `replay`
// run; the checker itself never sees the simulator or the planner.
#pragma once

#include <string>

#include "check/observed_run.h"
#include "core/scenario.h"
#include "planner/planner.h"
#include "rules/check.h"
#include "sim/trace.h"

namespace mg {

// Judges an existing run of `scenario`. The result's trace carries the planner's name only unless
// `account` asks for its decision records too (check/observed_run.h): ask for them when a report or
// the trace is written.
CheckResult check_trace(const Scenario& scenario, const Trace& trace,
                        PlannerAccount account = PlannerAccount::kNameOnly);
// Simulates with a new planner of the registry and judges the run. An unknown planner name raises
// std::invalid_argument.
CheckResult check_scenario(const Scenario& scenario, const std::string& planner_name,
                           PlannerAccount account = PlannerAccount::kNameOnly);
// Simulates with `planner` (fresh, or reset by its owner: planners keep state between cycles),
// registered or not, and judges the run: a planner under test needs no name in the registry.
CheckResult check_scenario(const Scenario& scenario, Planner& planner,
                           PlannerAccount account = PlannerAccount::kNameOnly);

}  // namespace mg
