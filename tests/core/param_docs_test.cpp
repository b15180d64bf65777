// The generated parameter documentation: how numbers and ranges are written, the schema of a
// parameter bound, and that a committed table or schema differing from the generated one in any
// field is reported, naming the parameter and the field.
#include "core/param_docs.h"

#include <gtest/gtest.h>

#include "core/params.h"

namespace mg {
namespace {

using nlohmann::ordered_json;

ParamInfo info(std::string_view section, std::string_view name) {
  for (const ParamSection& s : core_param_sections())
    if (s.name == section)
      for (const ParamInfo& p : s.params)
        if (p.name == name) return p;
  ADD_FAILURE() << section << "." << name;
  return {};
}

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
  for (const std::string& l : lines)
    if (l.find(text) != std::string::npos) return true;
  return false;
}

TEST(ParamDocs, NumbersAsTheDocumentationWritesThem) {
  EXPECT_EQ(doc_number(5.0), "5");
  EXPECT_EQ(doc_number(0.05), "0.05");
  EXPECT_EQ(doc_number(0.001), "0.001");
  EXPECT_EQ(doc_number(1000.0), "1000");
  EXPECT_EQ(doc_number(1e6), "1e6");
  EXPECT_EQ(doc_number(33.34), "33.34");
}

TEST(ParamDocs, RangesWithOpenEndsParameterEndsAndConstraints) {
  EXPECT_EQ(doc_range(info("rss", "response_time_s")), "[0, 5]");
  EXPECT_EQ(doc_range(info("rules", "sideslip_max_rad")), "(0, 0.2]");
  EXPECT_EQ(doc_range(info("rules", "merge_abort_offset_m")), "[0, `merge_start_offset_m`)");
  EXPECT_EQ(doc_range(info("rules", "max_lat_speed_sign_changes_per_merge")), "[0, 4], integer");
  EXPECT_EQ(doc_range(info("sim", "planner_cycle_s")), "[`step_s`, 5]");
  EXPECT_EQ(doc_range(info("sim", "horizon_s")), "(0, 3600]; horizon_s / step_s ≤ 1e6");
}

// The schema states the widest range a parameter bound allows and names the bound.
TEST(ParamDocs, SchemaOfAParameterBoundIsItsWidestRange) {
  const ordered_json schema = params_schema(core_param_sections());
  const ordered_json& abort = schema["properties"]["rules"]["properties"]["merge_abort_offset_m"];
  EXPECT_EQ(abort["minimum"], 0.0);
  EXPECT_EQ(abort["exclusiveMaximum"], 0.5);  // below merge_start_offset_m, itself at most 0.5
  EXPECT_NE(abort["description"].get<std::string>().find("below merge_start_offset_m"), std::string::npos);
  const ordered_json& cycle = schema["properties"]["sim"]["properties"]["planner_cycle_s"];
  EXPECT_EQ(cycle["minimum"], 0.001);
  const ordered_json& count = schema["properties"]["rules"]["properties"]["max_lat_speed_sign_changes_per_merge"];
  EXPECT_EQ(count["type"], "integer");
  EXPECT_TRUE(count["default"].is_number_integer());
  EXPECT_EQ(schema["properties"]["rss"]["additionalProperties"], false);
}

TEST(ParamDocs, AnySchemaFieldThatDiffersIsReported) {
  const ordered_json generated = params_schema(core_param_sections());
  EXPECT_TRUE(schema_differences(generated, generated).empty());
  const auto differs = [&](auto edit, const std::string& expected) {
    ordered_json committed = generated;
    edit(committed["properties"]);
    const auto diff = schema_differences(committed, generated);
    EXPECT_TRUE(mentions(diff, expected)) << expected << " not among " << testing::PrintToString(diff);
  };
  differs([](ordered_json& p) { p["rss"]["properties"]["response_time_s"]["default"] = 0.6; },
          "params.rss.response_time_s: default: 0.6 in the file, 0.5 in the table");
  differs([](ordered_json& p) { p["rss"]["properties"]["response_time_s"]["maximum"] = 6; },
          "params.rss.response_time_s: maximum");
  differs([](ordered_json& p) { p["rules"]["properties"]["sideslip_max_rad"].erase("exclusiveMinimum"); },
          "params.rules.sideslip_max_rad: exclusiveMinimum: absent in the file");
  differs([](ordered_json& p) { p["rules"]["properties"]["max_lat_speed_sign_changes_per_merge"]["type"] = "number"; },
          "params.rules.max_lat_speed_sign_changes_per_merge: type");
  differs([](ordered_json& p) { p["sim"]["properties"].erase("step_s"); }, "params.sim.step_s: missing from the file");
  differs([](ordered_json& p) { p["sim"]["properties"]["turbo"] = ordered_json::object(); },
          "params.sim.turbo: in the file, in no parameter table");
  differs([](ordered_json& p) { p["sim"]["additionalProperties"] = true; }, "params.sim: additionalProperties");
}

TEST(ParamDocs, AnyTableCellThatDiffersIsReported) {
  const std::string generated = params_markdown_table(core_param_sections());
  EXPECT_TRUE(markdown_table_differences(generated, generated).empty());
  const auto differs = [&](const std::string& from, const std::string& to, const std::string& expected) {
    std::string committed = generated;
    const std::size_t at = committed.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    committed.replace(at, from.size(), to);
    const auto diff = markdown_table_differences(committed, generated);
    EXPECT_TRUE(mentions(diff, expected)) << expected << " not among " << testing::PrintToString(diff);
  };
  differs("| `rss.response_time_s` | s | 0.5 |", "| `rss.response_time_s` | s | 0.6 |",
          "docs table: `rss.response_time_s`: default: 0.6 in the file, 0.5 in the table");
  differs("| `rss.response_time_s` | s |", "| `rss.response_time_s` | ms |", "`rss.response_time_s`: unit: ms");
  differs("| [0, 5] | T_lag", "| [0, 6] | T_lag", "`rss.response_time_s`: valid range: [0, 6]");
  differs("| `sim.step_s`", "| `sim.step_time_s`", "docs table: no row `sim.step_s`");
  differs("| `sim.step_s`", "| `sim.step_time_s`", "docs table: row `sim.step_time_s` is in no parameter table");
}

TEST(ParamDocs, TheMarkedBlockIsFoundAndReplaced) {
  const std::string text = std::string("intro\n") + kParamsTableBegin + "\nold\n" + kParamsTableEnd + "\nrest\n";
  EXPECT_EQ(marked_block(text), "old\n");
  EXPECT_EQ(replace_marked_block(text, "new\nrows\n"),
            std::string("intro\n") + kParamsTableBegin + "\nnew\nrows\n" + kParamsTableEnd + "\nrest\n");
  EXPECT_THROW(marked_block("no markers"), std::invalid_argument);
}

}  // namespace
}  // namespace mg
