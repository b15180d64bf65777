// The tunables planners own in params.planner, at the input boundary. Core reads a scenario
// without depending on any planner, so it keeps the keys of params.planner that its own table
// does not declare as PlannerParams::tunables, unchecked (core/params.h). Programs that run
// planners read scenarios with planner_scenario_from_json or load_planner_scenario, which check
// those keys against the owners' tables: among the built-in planners only RCPP owns tunables
// (planner/rcpp_params.h; TriPField draws its road marks with RCPP's beta).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/param_table.h"
#include "core/scenario.h"

namespace mg {

// Checks p.tunables: an unknown key, a wrong type or a value out of range raises InputError
// naming `source` and the key's JSON path. Then keeps only the values off their defaults, so
// that a file that spells a default out and one that leaves it to the default give equal
// scenarios (corpus merges compare scenarios) and written scenarios carry what was set.
// `path` is the JSON path of the planner object.
void check_planner_tunables(PlannerParams& p, const std::string& source, const std::string& path = "/params/planner");

// scenario_from_json / load_scenario (core/scenario.h), then check_planner_tunables.
Scenario planner_scenario_from_json(const nlohmann::json& j, const std::string& source);
Scenario load_planner_scenario(const std::string& path);

// core_param_sections() with the planners' tunables in the planner section: everything a
// scenario's params object may hold, for the generated documentation (core/param_docs.h).
std::vector<ParamSection> scenario_param_sections();

}  // namespace mg
