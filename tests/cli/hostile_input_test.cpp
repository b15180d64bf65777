// Hostile input suite: every file of tests/hostile/ through every command that
// reads it. Each must give exit 2 within the time bound (run_cli kills at 120 s -> 124), one line
// on stderr naming the file and a JSON path, nothing on stdout and no output file written.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "tests/support/scratch_files.h"

namespace mg::test {
namespace {

namespace fs = std::filesystem;

const fs::path kHostileDir = fs::path(MG_SOURCE_DIR) / "tests" / "hostile";

struct Expectation {
  std::string file;
  std::string scenario_error;  // substring expected from plan/check (scenario loader)
};

const std::vector<Expectation> kFiles = {
    {"empty.json", "empty input"},
    {"binary_garbage.json", "malformed JSON"},
    {"truncated.json", "malformed JSON"},
    {"deeply_nested.json", "nested deeper than"},
    {"wrong_types.json", "/ego: must be a JSON object"},
    {"number_as_string.json", "/vehicles/0/speed_mps: must be a number"},
    {"huge_number.json", "/vehicles/1/x_m: must be in"},
    {"nan_literal.json", "malformed JSON"},
    {"number_overflow.json", "number out of range of a double"},
    {"negative_length.json", "/vehicles/1/length_m: must be > 0"},
    {"zero_width.json", "/ego/width_m: must be > 0"},
    {"faster_than_light.json", "/ego/speed_mps: must be in [0, 100]"},
    {"zero_time_step.json", "/params/sim/step_s: must be in"},
    {"huge_horizon.json", "/params/sim/horizon_s: must be in"},
    {"duplicate_ids.json", "/vehicles/1/id: duplicate vehicle id 1"},
    {"side_lane_inverted.json", "/road/side_lane_end_x_m"},
    {"overlapping_vehicles.json", "/vehicles/1/x_m: overlaps vehicle id 1"},
    {"unknown_behaviour.json", "/vehicles/0/behaviour/type: unknown behaviour 'kamikaze'"},
    {"unknown_key.json", "/ego/turbo: unknown key"},
    {"unknown_planner_key.json", "/params/planner/turbo: unknown key"},
    {"kappa_inverted.json", "/params/planner/kappa_max_per_m: must be in [kappa_min_per_m = 0.5, 10], got 0.1"},
    {"negative_field_coefficient.json", "/params/planner/pf_road_beta: must be in [0, 1000000], got -1"},
    {"future_version_scenario.json", "/format_version: unsupported"},
    {"future_version_case.json", ": /"},
};

bool dir_is_empty(const fs::path& dir) { return !fs::exists(dir) || fs::is_empty(dir); }

void expect_clean_rejection(const CliResult& r, const std::string& what, const std::string& file,
                            const std::string& expected) {
  EXPECT_EQ(r.exit_code, 2) << what << " " << file << ": " << r.err;
  ASSERT_FALSE(r.err.empty()) << what << " " << file;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << what << " " << file << ": one line expected: " << r.err;
  EXPECT_NE(r.err.find(file), std::string::npos) << what << ": message must name the file: " << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << what << " " << file << ": " << r.err;
  EXPECT_TRUE(r.out.empty()) << what << " " << file << ": nothing on stdout on error";
}

TEST(HostileInput, PlanAndCheckRejectEveryFileCleanly) {
  for (const auto& e : kFiles) {
    const std::string path = (kHostileDir / e.file).string();
    expect_clean_rejection(run_cli({"plan", path}), "plan", e.file, e.scenario_error);
    const auto report = fresh_dir("hostile_check");
    expect_clean_rejection(run_cli({"check", path, "--report", report.string()}), "check", e.file, e.scenario_error);
    EXPECT_TRUE(dir_is_empty(report)) << "check wrote output for " << e.file;
    fs::remove_all(report);
  }
}

TEST(HostileInput, ReplayRejectsEveryFileCleanly) {
  for (const auto& e : kFiles) {
    const std::string path = (kHostileDir / e.file).string();
    expect_clean_rejection(run_cli({"replay", path}), "replay", e.file, ": ");
  }
}

TEST(HostileInput, FuzzRefusesACorpusHoldingAHostileFile) {
  for (const auto& e : kFiles) {
    const auto corpus = fresh_dir("hostile_corpus");
    const auto report = fresh_dir("hostile_report");
    fs::copy_file(kHostileDir / e.file, corpus / e.file);
    const auto r = run_cli({"fuzz", "--runs", "1", "--corpus", corpus.string(), "--report", report.string()});
    expect_clean_rejection(r, "fuzz --corpus", e.file, ": ");
    EXPECT_TRUE(dir_is_empty(report)) << "fuzz wrote a report for " << e.file;
    EXPECT_EQ(slurp(corpus / e.file), slurp(kHostileDir / e.file)) << "the corpus file must be left untouched";
    fs::remove_all(corpus);
    fs::remove_all(report);
  }
}

TEST(HostileInput, RssRejectsEveryFileOnStdin) {
  for (const auto& e : kFiles) {
    const auto r = run_cli({"rss", "longitudinal"}, slurp(kHostileDir / e.file));
    EXPECT_EQ(r.exit_code, 2) << e.file << ": " << r.err;
    EXPECT_NE(r.err.find("<stdin>: /"), std::string::npos) << e.file << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << e.file << ": " << r.err;
  }
}

TEST(HostileInput, MillionVehiclesIsRejectedQuickly) {
  const auto dir = fresh_dir("hostile_million");
  const auto path = dir / "million_vehicles.json";
  {
    std::ofstream out(path);
    out << R"({"format_version":1,"ego":{"x_m":20,"speed_mps":20},"vehicles":[)";
    for (int i = 0; i < 1000000; ++i) out << (i ? "," : "") << R"({"id":)" << i + 1 << R"(,"x_m":)" << 10 * i << "}";
    out << "]}";
  }
  const auto r = run_cli({"plan", path.string()});
  expect_clean_rejection(r, "plan", "million_vehicles.json", "/vehicles: at most 64 vehicles");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mg::test
