// The parameter tables of core (params.cpp): every default inside its range, units that agree
// with the keys, the reader's messages, and params.planner's pass-through of planners' keys.
#include "core/params.h"

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "input_error_cases.h"

namespace mg {
namespace {

using nlohmann::json;

std::string params_error(const json& j) {
  return test_support::input_error_of([&] { params_from_json(j, "p.json", "/params"); });
}

// The unit a key's suffix names (units in names), or nullopt for a key without one.
std::optional<std::string> unit_of_key(std::string_view key) {
  const std::pair<std::string_view, std::string_view> suffixes[] = {
      {"_mps2", "m/s²"}, {"_mps", "m/s"}, {"_per_m", "1/m"}, {"_rad", "rad"}, {"_m", "m"}, {"_s", "s"}};
  for (const auto& [suffix, unit] : suffixes)
    if (key.size() > suffix.size() && key.substr(key.size() - suffix.size()) == suffix) return std::string(unit);
  return std::nullopt;
}

void expect_consistent(const ParamSection& s) {
  for (const ParamInfo& p : s.params) {
    const std::string key = s.name + "." + std::string(p.name);
    if (const auto unit = unit_of_key(p.name)) {
      EXPECT_EQ(p.unit, *unit) << key;
    }
    EXPECT_FALSE(p.description.empty()) << key;
    const double lo = p.lo.param.empty() ? p.lo.value : -1e300;
    const double hi = p.hi.param.empty() ? p.hi.value : 1e300;
    EXPECT_TRUE(p.lo.open ? p.default_value > lo : p.default_value >= lo) << key << " default below its range";
    EXPECT_TRUE(p.hi.open ? p.default_value < hi : p.default_value <= hi) << key << " default above its range";
  }
}

TEST(ParamTables, DefaultsLieInTheirRangesAndUnitsMatchTheKeys) {
  for (const ParamSection& s : core_param_sections()) expect_consistent(s);
}

TEST(ParamTables, TheDefaultsAreTheStructuresInitialisers) {
  EXPECT_EQ(params_from_json(json::object(), "p.json", ""), Params{});
  const json j = params_to_json(Params{});
  EXPECT_EQ(j.at("rss").at("response_time_s"), 0.5);
  EXPECT_EQ(j.at("rules").at("max_lat_speed_sign_changes_per_merge"), 2);
  EXPECT_TRUE(j.at("rules").at("max_lat_speed_sign_changes_per_merge").is_number_integer());
  EXPECT_EQ(j.at("sim").at("horizon_s"), 30.0);
}

TEST(ParamTables, WriteThenReadGivesEqualParams) {
  Params p;
  p.rss.response_time_s = 0.8;
  p.rules.merge_abort_offset_m = 0.07;
  p.rules.max_lat_speed_sign_changes_per_merge = 3;
  p.sim.planner_cycle_s = 0.2;
  p.planner.halt_margin_m = 7.5;
  EXPECT_EQ(params_from_json(params_to_json(p), "p.json", ""), p);
}

TEST(ParamTables, BadValuesAreOneLineErrorsNamingTheField) {
  const json valid = json::object();
  test_support::expect_input_errors(
      valid,
      {
          {"unknown section", [](json& j) { j["turbo"] = json::object(); }, "p.json: /params/turbo: unknown key"},
          {"unknown rss key", [](json& j) { j["rss"] = {{"colour", 1}}; }, "/params/rss/colour: unknown key"},
          {"wrong type", [](json& j) { j["rss"] = {{"response_time_s", "0.5"}}; },
           "/params/rss/response_time_s: must be a number, got a string"},
          {"closed range", [](json& j) { j["rss"] = {{"response_time_s", 6}}; },
           "/params/rss/response_time_s: must be in [0, 5], got 6"},
          {"open lower end", [](json& j) { j["rules"] = {{"sideslip_max_rad", 0}}; },
           "/params/rules/sideslip_max_rad: must be > 0, got 0"},
          {"open lower end, above", [](json& j) { j["rules"] = {{"sideslip_max_rad", 2}}; },
           "/params/rules/sideslip_max_rad: must be in (0, 0.2], got 2"},
          {"integer", [](json& j) { j["rules"] = {{"max_lat_speed_sign_changes_per_merge", 2.5}}; },
           "/params/rules/max_lat_speed_sign_changes_per_merge: must be an integer"},
          {"integer range", [](json& j) { j["rules"] = {{"max_lat_speed_sign_changes_per_merge", 101}}; },
           "/params/rules/max_lat_speed_sign_changes_per_merge: must be in [0, 4], got 101"},
          {"abort at the start offset", [](json& j) { j["rules"] = {{"merge_abort_offset_m", 0.1}}; },
           "/params/rules/merge_abort_offset_m: must be in [0, merge_start_offset_m = 0.1), got 0.1"},
          {"abort above a given start", [](json& j) {
             j["rules"] = {{"merge_start_offset_m", 0.3}, {"merge_abort_offset_m", 0.4}};
           },
           "/params/rules/merge_abort_offset_m: must be in [0, merge_start_offset_m = 0.3), got 0.4"},
          {"cycle below the step", [](json& j) { j["sim"] = {{"planner_cycle_s", 0.01}}; },
           "/params/sim/planner_cycle_s: must be in [step_s = 0.02, 5], got 0.01"},
          {"too many steps", [](json& j) { j["sim"] = {{"step_s", 0.001}, {"horizon_s", 3000}}; },
           "/params/sim/horizon_s: horizon_s / step_s must be <= 1e6 steps"},
          {"planner common key", [](json& j) { j["planner"] = {{"merge_duration_s", 0.1}}; },
           "/params/planner/merge_duration_s: must be in [0.5, 20], got 0.1"},
      },
      [](const json& j) { params_from_json(j, "p.json", "/params"); });
}

TEST(ParamTables, ACrossParameterBoundFollowsTheGivenValue) {
  const Params p = params_from_json(json{{"rules", {{"merge_start_offset_m", 0.5}, {"merge_abort_offset_m", 0.4}}}},
                                    "p.json", "");
  EXPECT_DOUBLE_EQ(p.rules.merge_abort_offset_m, 0.4);
  EXPECT_EQ(params_error(json{{"sim", {{"step_s", 0.05}, {"planner_cycle_s", 0.05}}}}), "");
}

// Core does not know a planner's own keys: it keeps them, as given, for the planner that owns them
// (planner/planner_params.h checks them), and writes them back.
TEST(ParamTables, PlannerKeysCoreDoesNotDeclarePassThrough) {
  const json j = {{"planner", {{"merge_duration_s", 5.0}, {"pf_road_beta", 0.7}, {"anything", {{"a", 1}}}}}};
  const Params p = params_from_json(j, "p.json", "");
  EXPECT_DOUBLE_EQ(p.planner.merge_duration_s, 5.0);
  EXPECT_EQ(p.planner.tunables, (json{{"pf_road_beta", 0.7}, {"anything", {{"a", 1}}}}));
  const json written = params_to_json(p).at("planner");
  EXPECT_EQ(written.at("pf_road_beta"), 0.7);
  EXPECT_EQ(written.at("halt_margin_m"), 5.0);
  EXPECT_EQ(params_from_json(params_to_json(p), "p.json", ""), p);
}

TEST(ParamTables, TraceSectionsAreRssAndRules) {
  const auto sections = trace_param_sections();
  ASSERT_EQ(sections.size(), 2u);
  EXPECT_EQ(sections[0].name, "rss");
  EXPECT_EQ(sections[1].name, "rules");
}

}  // namespace
}  // namespace mg
