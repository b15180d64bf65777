// `mergeguard params`: the parameter documentation is generated from the parameter tables, and
// --check fails when the committed docs (the table of docs/scenario_format.md, the params parts
// of docs/scenario.schema.json and docs/trace.schema.json) disagree with them in any name,
// default, range end, type or unit; --update regenerates them.
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "tests/support/scratch_files.h"

namespace mg::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

const fs::path kDocs = fs::path(MG_SOURCE_DIR) / "docs";

fs::path copy_of_docs() {
  const fs::path dir = fresh_dir("params_docs");
  for (const char* f : {"scenario_format.md", "scenario.schema.json", "trace.schema.json"}) fs::copy_file(kDocs / f, dir / f);
  return dir;
}

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

void edit_schema(const fs::path& p, const std::function<void(ordered_json&)>& edit) {
  ordered_json j = ordered_json::parse(slurp(p));
  edit(j["properties"]["params"]["properties"]);
  write_text(p, j.dump(2) + "\n");
}

void edit_text(const fs::path& p, const std::string& from, const std::string& to) {
  std::string text = slurp(p);
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  write_text(p, text);
}

// --check on a copy of docs/ edited by `edit` exits 1 and says `expected`; --update repairs it.
void expect_check_fails(const std::function<void(const fs::path&)>& edit, const std::string& expected) {
  const fs::path dir = copy_of_docs();
  edit(dir);
  const CliResult r = run_cli({"params", "--check", dir.string()});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find(expected), std::string::npos) << expected << " not in:\n" << r.out;
  ASSERT_EQ(run_cli({"params", "--update", dir.string()}).exit_code, 0);
  EXPECT_EQ(run_cli({"params", "--check", dir.string()}).exit_code, 0) << "--update did not repair " << expected;
  fs::remove_all(dir);
}

TEST(ParamsCommand, TheCommittedDocsAgreeWithTheParameterTables) {
  const CliResult r = run_cli({"params", "--check", kDocs.string()});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(ParamsCommand, ASchemaDefaultRangeOrTypeThatDisagreesFails) {
  const auto scenario = [](const std::function<void(ordered_json&)>& e) {
    return [e](const fs::path& d) { edit_schema(d / "scenario.schema.json", e); };
  };
  expect_check_fails(scenario([](ordered_json& p) { p["rss"]["properties"]["response_time_s"]["default"] = 0.6; }),
                     "scenario.schema.json: params.rss.response_time_s: default: 0.6 in the file, 0.5 in the table");
  expect_check_fails(scenario([](ordered_json& p) { p["planner"]["properties"]["pf_road_beta"]["maximum"] = 5.0; }),
                     "params.planner.pf_road_beta: maximum: 5.0 in the file");
  expect_check_fails(scenario([](ordered_json& p) {
                       auto& s = p["rules"]["properties"]["sideslip_max_rad"];
                       s.erase("exclusiveMinimum");
                       s["minimum"] = 0.0;
                     }),
                     "params.rules.sideslip_max_rad: exclusiveMinimum: absent in the file");
  expect_check_fails(scenario([](ordered_json& p) { p["planner"]["properties"]["pc_candidates"]["type"] = "number"; }),
                     "params.planner.pc_candidates: type");
  expect_check_fails(scenario([](ordered_json& p) { p["planner"]["properties"].erase("kappa_max_per_m"); }),
                     "params.planner.kappa_max_per_m: missing from the file");
  expect_check_fails(scenario([](ordered_json& p) { p["sim"]["properties"]["turbo_s"] = {{"type", "number"}}; }),
                     "params.sim.turbo_s: in the file, in no parameter table");
  expect_check_fails(
      [](const fs::path& d) {
        edit_schema(d / "trace.schema.json", [](ordered_json& p) { p["rules"]["properties"]["halted_speed_mps"]["maximum"] = 2.0; });
      },
      "trace.schema.json: params.rules.halted_speed_mps: maximum");
}

TEST(ParamsCommand, ADocsTableCellThatDisagreesFails) {
  const auto md = [](const std::string& from, const std::string& to) {
    return [from, to](const fs::path& d) { edit_text(d / "scenario_format.md", from, to); };
  };
  expect_check_fails(md("| `rss.response_time_s` | s | 0.5 |", "| `rss.response_time_s` | s | 0.6 |"),
                     "scenario_format.md: docs table: `rss.response_time_s`: default: 0.6 in the file, 0.5 in the table");
  expect_check_fails(md("| `planner.pf_search_distance_m` | m |", "| `planner.pf_search_distance_m` | km |"),
                     "`planner.pf_search_distance_m`: unit: km in the file, m in the table");
  expect_check_fails(md("| `sim.horizon_s` | s | 30 | (0, 3600]", "| `sim.horizon_s` | s | 30 | [0, 3600]"),
                     "`sim.horizon_s`: valid range: [0, 3600]");
  expect_check_fails(md("| `rules.progress_lateral_margin_m`", "| `rules.progress_margin_m`"),
                     "docs table: no row `rules.progress_lateral_margin_m`");
}

TEST(ParamsCommand, PrintsTheGeneratedTableAndSchema) {
  const CliResult md = run_cli({"params", "--markdown"});
  EXPECT_EQ(md.exit_code, 0);
  EXPECT_NE(md.out.find("| `planner.kappa_max_per_m` | 1/m | 1 | [`kappa_min_per_m`, 10] |"), std::string::npos) << md.out;
  const CliResult schema = run_cli({"params", "--schema"});
  EXPECT_EQ(schema.exit_code, 0);
  const auto j = ordered_json::parse(schema.out);
  EXPECT_EQ(j["properties"]["planner"]["properties"]["kappa_max_per_m"]["exclusiveMinimum"], 0.0);
}

TEST(ParamsCommand, IsNotListedInTheUsage) {
  const CliResult r = run_cli({"--help"});
  EXPECT_EQ(r.out.find("mergeguard params"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mergeguard check"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace mg::test
