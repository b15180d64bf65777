// The open planner registry: make_planner and planner_names (planner/planner.h) look
// planners up here, so a planner registered by a program linking mergeguard is accepted wherever
// a built-in one is (`check`, `fuzz`, `replay`, `plan`, the campaign and property functions).
// The built-ins "rcpp", "rcpp-coop", "tripfield" and the baselines "mobil" and "frenet"
// (docs/baselines.md) are registered first, in that order, the same way. Register before
// starting a campaign: lookups may run on many threads, registration is meant for start-up (both
// are safe to call concurrently, under one mutex). Names "exec:COMMAND" are not registered:
// make_planner makes an exec planner for them (planner/exec_planner.h).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "planner/planner.h"

namespace mg {

using PlannerFactory = std::function<std::unique_ptr<Planner>()>;

// Adds `name` after the planners registered so far (planner_names() keeps registration order).
// Throws std::invalid_argument for an empty name, a name already registered, a name starting with
// "exec:", or an empty factory.
// The factory is called once per simulation and must return a fresh planner whose name() is
// `name` (corpus cases and reports record it).
void register_planner(std::string name, PlannerFactory factory);

}  // namespace mg
