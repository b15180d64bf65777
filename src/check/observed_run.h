// What an observer of a simulated run could record (docs/trace_format.md): the
// declarations the scenario gives, every step's observable state of every vehicle in the road
// frame, and the V2V channel's events. The planner's decision records go into
// `planner_annotations`, which reports show and no rule reads.
#pragma once

#include "core/observed_trace.h"
#include "core/scenario.h"
#include "sim/trace.h"

namespace mg {

// How much of the planner's account a trace carries in `planner_annotations`: its name alone (all
// that judging shows: CheckResult::planner), or every decision record as well (what reports and
// saved traces show). Campaigns judge thousands of runs and write reports for a handful; the
// records as JSON cost them about a tenth of a run.
enum class PlannerAccount { kNameOnly, kDecisions };

ObservedTrace observed_trace_of(const Scenario& scenario, const Trace& trace,
                                PlannerAccount account = PlannerAccount::kDecisions);

// A vehicle's observable state from its simulated one: road-frame velocity components
// (VehicleState::road_vx_mps/road_vy_mps), the heading and the applied longitudinal acceleration.
ObservedState observed_state_of(const VehicleState& v);

}  // namespace mg
