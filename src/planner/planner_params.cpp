#include "planner/planner_params.h"

#include "core/json_reader.h"
#include "core/params.h"
#include "planner/rcpp_params.h"

namespace mg {

void check_planner_tunables(PlannerParams& p, const std::string& source, const std::string& path) {
  if (p.tunables.empty()) return;
  const ParamTable<RcppParams>& table = rcpp_param_table();
  const RcppParams read = read_params(table, ObjectReader(p.tunables, source, path));
  const RcppParams defaults;
  nlohmann::json off_default = nlohmann::json::object();
  for (const Param<RcppParams>& row : table.params) {
    if (row.get(read) == row.get(defaults)) continue;
    if (row.number != nullptr) off_default[std::string(row.name)] = read.*row.number;
    else off_default[std::string(row.name)] = read.*row.integer;
  }
  p.tunables = std::move(off_default);
}

Scenario planner_scenario_from_json(const nlohmann::json& j, const std::string& source) {
  Scenario s = scenario_from_json(j, source);
  check_planner_tunables(s.params.planner, source);
  return s;
}

Scenario load_planner_scenario(const std::string& path) {
  return planner_scenario_from_json(parse_json_file(path), path);
}

std::vector<ParamSection> scenario_param_sections() {
  std::vector<ParamSection> sections = core_param_sections();
  for (ParamSection& s : sections) {
    if (s.name != "planner") continue;
    s.description =
        "What every planner is told about the merge (PlannerParams, src/core/params.h) and RCPP's own tunables "
        "(RcppParams, src/planner/rcpp_params.h); every key optional.";
    for (const ParamInfo& p : param_infos(rcpp_param_table())) s.params.push_back(p);
  }
  return sections;
}

}  // namespace mg
