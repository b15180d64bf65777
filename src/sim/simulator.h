// Closed-loop simulation of a merge scenario (spec §7): ego single-track dynamics driven by a
// planner, main-lane behaviours, V2V channel. Deterministic: same scenario, same build, same trace.
#pragma once

#include "core/scenario.h"
#include "planner/planner.h"
#include "sim/trace.h"

namespace mg {

// Runs the scenario for params.sim.horizon_s with the given planner (fresh state expected).
Trace simulate(const Scenario& scenario, Planner& planner);

}  // namespace mg
