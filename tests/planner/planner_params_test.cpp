// The planners' tunables at the input boundary (planner/planner_params.h): checked against RCPP's
// table with the file and JSON path in every error, kept only off their defaults; and every
// scenario and corpus case committed with those keys still loads to the values it spells out.
#include "planner/planner_params.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/json_reader.h"
#include "core/params.h"
#include "planner/rcpp_params.h"

namespace mg {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

json scenario_with_planner(const json& planner) {
  return {{"format_version", 1}, {"ego", {{"x_m", 20}, {"speed_mps", 20}}}, {"params", {{"planner", planner}}}};
}

std::string load_error(const json& planner) {
  try {
    planner_scenario_from_json(scenario_with_planner(planner), "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PlannerParams, BadTunablesAreOneLineErrorsNamingTheFileAndField) {
  EXPECT_EQ(load_error({{"turbo", 1}}), "s.json: /params/planner/turbo: unknown key");
  EXPECT_EQ(load_error({{"pf_road_beta", -1}}), "s.json: /params/planner/pf_road_beta: must be in [0, 1000000], got -1");
  EXPECT_EQ(load_error({{"pc_candidates", 1.5}}), "s.json: /params/planner/pc_candidates: must be an integer, got a number");
  EXPECT_EQ(load_error({{"pf_search_distance_m", 0}}), "s.json: /params/planner/pf_search_distance_m: must be > 0, got 0");
  EXPECT_EQ(load_error({{"kappa_min_per_m", 0.5}, {"kappa_max_per_m", 0.1}}),
            "s.json: /params/planner/kappa_max_per_m: must be in [kappa_min_per_m = 0.5, 10], got 0.1");
  EXPECT_EQ(load_error({{"lat_accel_comfort_mps2", "1.5"}}),
            "s.json: /params/planner/lat_accel_comfort_mps2: must be a number, got a string");
  EXPECT_EQ(load_error({{"merge_duration_s", 4.5}, {"pf_lane_xi", 0.3}}), "");
}

// A default spelled out and a default left out give equal scenarios; a value set stays.
TEST(PlannerParams, OnlyValuesOffTheirDefaultsAreKept) {
  const Scenario spelled = planner_scenario_from_json(
      scenario_with_planner({{"pf_road_beta", 0.5}, {"pc_candidates", 15}, {"kappa_max_per_m", 1.0}}), "s.json");
  const Scenario left_out = planner_scenario_from_json(scenario_with_planner(json::object()), "s.json");
  EXPECT_EQ(spelled, left_out);
  EXPECT_TRUE(spelled.params.planner.tunables.empty());
  const Scenario set = planner_scenario_from_json(scenario_with_planner({{"pf_road_beta", 0.8}, {"pc_candidates", 15}}), "s.json");
  EXPECT_EQ(set.params.planner.tunables, (json{{"pf_road_beta", 0.8}}));
  EXPECT_EQ(planner_scenario_from_json(scenario_to_json(set), "again.json"), set);
}

// What every committed file spells out for RCPP is what RCPP now reads (the values of its keys,
// the defaults for the rest), and the core keys keep their values.
void expect_reads_as_written(const json& scenario, const std::string& source) {
  const Scenario s = planner_scenario_from_json(scenario, source);
  const json planner = scenario.contains("params") && scenario["params"].contains("planner") ? scenario["params"]["planner"] : json::object();
  const RcppParams read = rcpp_params(s);
  const RcppParams defaults;
  for (const Param<RcppParams>& row : rcpp_param_table().params) {
    const double expected = planner.contains(row.name) ? planner[std::string(row.name)].get<double>() : row.get(defaults);
    EXPECT_EQ(row.get(read), expected) << source << ": " << row.name;
  }
  const json common = params_to_json(s.params).at("planner");
  for (const char* key : {"merge_duration_s", "comm_threshold_s", "halt_margin_m"}) {
    if (planner.contains(key)) {
      EXPECT_EQ(common.at(key), planner.at(key).get<double>()) << source << ": " << key;
    }
  }
}

TEST(PlannerParams, EveryCommittedScenarioAndCaseReadsAsWritten) {
  int files = 0;
  for (const char* dir : {"corpus/cases", "corpus/scenarios", "examples", "reports", "tests/data"}) {
    const fs::path root = fs::path(MG_SOURCE_DIR) / dir;
    if (!fs::exists(root)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (entry.path().extension() != ".json") continue;
      const json j = parse_json_file(entry.path().string());
      if (j.is_object() && j.contains("signature") && j.contains("scenario")) expect_reads_as_written(j["scenario"], entry.path().string());
      else if (j.is_object() && j.contains("format_version") && j.contains("ego")) expect_reads_as_written(j, entry.path().string());
      else continue;
      ++files;
    }
  }
  EXPECT_GT(files, 100);
}

TEST(PlannerParams, TheScenarioSectionsHoldRcppsKeysInThePlannerSection) {
  bool found = false;
  for (const ParamSection& s : scenario_param_sections()) {
    if (s.name != "planner") continue;
    for (const ParamInfo& p : s.params) found = found || p.name == "pf_road_beta";
    EXPECT_EQ(s.params.front().name, "merge_duration_s");
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace mg
