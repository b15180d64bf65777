// Scenario loader and writer: round trip of defaults, and validation errors that name the
// source and JSON path of the offending field (spec §2).
#include "core/scenario.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/json_reader.h"
#include "input_error_cases.h"

namespace mg {
namespace {

using nlohmann::json;

json minimal_scenario() {
  return json::parse(R"({
    "format_version": 1,
    "road": {"side_lane_start_x_m": 0, "side_lane_end_x_m": 300},
    "ego": {"x_m": 20, "speed_mps": 20},
    "vehicles": [
      {"id": 1, "x_m": 10, "speed_mps": 20, "behaviour": {"type": "idm"}},
      {"id": 2, "x_m": 60, "speed_mps": 21, "behaviour": {"type": "cooperative"}, "v2v": {"capable": true}}
    ]
  })");
}

// Loads `j` and returns the error message ("" when it loads).
std::string scenario_load_error(const json& j) {
  return test_support::input_error_of([&] { scenario_from_json(j, "scenario.json"); });
}

TEST(ScenarioLoader, MinimalScenarioGetsDocumentedDefaults) {
  const Scenario s = scenario_from_json(minimal_scenario(), "scenario.json");
  EXPECT_DOUBLE_EQ(s.road.lane_width_m, 3.5);
  EXPECT_DOUBLE_EQ(s.ego.y_m, -3.5);  // side lane centre
  ASSERT_EQ(s.vehicles.size(), 2u);
  EXPECT_EQ(s.vehicles[1].behaviour.type, BehaviourType::kCooperative);
  EXPECT_TRUE(s.vehicles[1].v2v.capable);
  EXPECT_DOUBLE_EQ(s.params.sim.step_s, 0.02);
  EXPECT_EQ(s.index_of(2), 1);
  EXPECT_EQ(s.index_of(7), -1);
}

TEST(ScenarioLoader, WriteThenLoadGivesEqualScenario) {
  Scenario s = scenario_from_json(minimal_scenario(), "scenario.json");
  s.vehicles[0].noncompliance = {NonComplianceType::kExceedAccel, 2.5, 1.0, 4.0};
  s.vehicles[0].behaviour.desired_speed_mps = 22.2;
  s.params.planner.merge_duration_s = 3.3;
  const auto path = std::filesystem::temp_directory_path() / "mg_scenario_roundtrip.json";
  write_scenario(s, path.string());
  EXPECT_EQ(load_scenario(path.string()), s);
  std::filesystem::remove(path);
}

TEST(ScenarioLoader, ErrorsNameFileAndJsonPath) {
  const std::vector<test_support::MutationCase> cases = {
      {"negative length", [](json& j) { j["vehicles"][1]["length_m"] = -4.0; }, "scenario.json: /vehicles/1/length_m: must be > 0"},
      {"zero width", [](json& j) { j["ego"]["width_m"] = 0; }, "/ego/width_m: must be > 0"},
      {"speed above light", [](json& j) { j["ego"]["speed_mps"] = 3e8; }, "/ego/speed_mps: must be in [0, 100]"},
      {"huge number", [](json& j) { j["vehicles"][0]["x_m"] = 1e308; }, "/vehicles/0/x_m: must be in"},
      {"string number", [](json& j) { j["vehicles"][0]["speed_mps"] = "20"; }, "/vehicles/0/speed_mps: must be a number, got a string"},
      {"unknown key", [](json& j) { j["vehicles"][0]["colour"] = "red"; }, "/vehicles/0/colour: unknown key"},
      {"missing key", [](json& j) { j["ego"].erase("x_m"); }, "/ego/x_m: missing required key"},
      {"unknown behaviour", [](json& j) { j["vehicles"][0]["behaviour"]["type"] = "aggressive"; }, "/vehicles/0/behaviour/type: unknown behaviour 'aggressive'"},
      {"duplicate id", [](json& j) { j["vehicles"][1]["id"] = 1; }, "/vehicles/1/id: duplicate vehicle id 1"},
      {"side lane ends before it starts", [](json& j) { j["road"]["side_lane_end_x_m"] = -50; }, "/road/side_lane_end_x_m: the side lane must end"},
      {"overlapping vehicles", [](json& j) { j["vehicles"][1]["x_m"] = 12; }, "/vehicles/1/x_m: overlaps vehicle id 1"},
      {"zero time step", [](json& j) { j["params"] = {{"sim", {{"step_s", 0}}}}; }, "/params/sim/step_s: must be in"},
      {"absurd horizon", [](json& j) { j["params"] = {{"sim", {{"horizon_s", 1e9}}}}; }, "/params/sim/horizon_s: must be in"},
      {"future version", [](json& j) { j["format_version"] = 99; }, "/format_version: unsupported scenario format version 99"},
      {"brake_min above brake_max", [](json& j) { j["ego"]["limits"] = {{"brake_min_mps2", 9}, {"brake_max_mps2", 8}}; }, "/ego/limits/brake_min_mps2: must be <= brake_max_mps2"},
      {"vehicles not an array", [](json& j) { j["vehicles"] = 3; }, "/vehicles: must be an array"},
      {"negative loss probability", [](json& j) { j["vehicles"][1]["v2v"]["loss_prob"] = -0.1; }, "/vehicles/1/v2v/loss_prob: must be in [0, 1]"},
  };
  test_support::expect_input_errors(minimal_scenario(), cases, [](const json& j) { scenario_from_json(j, "scenario.json"); });
}

TEST(ScenarioLoader, RejectsTooManyVehicles) {
  json j = minimal_scenario();
  j["vehicles"] = json::array();
  for (int i = 0; i < 1000; ++i) j["vehicles"].push_back({{"id", i + 1}, {"x_m", 10.0 * i}, {"speed_mps", 20}});
  EXPECT_NE(scenario_load_error(j).find("/vehicles: at most 64 vehicles"), std::string::npos);
}

TEST(JsonText, MalformedEmptyAndDeepInputsAreInputErrors) {
  EXPECT_THROW(parse_json_text("", "a.json"), InputError);
  EXPECT_THROW(parse_json_text("{\"x\": ", "a.json"), InputError);
  EXPECT_THROW(parse_json_text("\x01\x02garbage", "a.json"), InputError);
  EXPECT_THROW(parse_json_text(std::string(10000, '[') + std::string(10000, ']'), "a.json"), InputError);
  EXPECT_THROW(parse_json_text("{\"x_m\": 2e308}", "a.json"), InputError);  // overflows a double
  EXPECT_NO_THROW(parse_json_text("{\"a\": [[1]]}", "a.json"));
}

TEST(JsonText, MissingFileNamesThePath) {
  try {
    load_scenario("/nonexistent/x.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.json"), std::string::npos);
  }
}

}  // namespace
}  // namespace mg
