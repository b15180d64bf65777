// `mergeguard check-trace` (src/cli/cmd_check_trace.cpp): judging a saved
// observable trace prints and writes exactly what `check` did for the run it was saved from, and
// every hostile trace (tests/hostile/traces/) is refused with exit 2, one line on stderr naming the
// file and the JSON path, nothing on stdout and nothing written.

#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "tests/support/scratch_files.h"

namespace mg::test {
namespace {

namespace fs = std::filesystem;

const fs::path kTraces = fs::path(MG_SOURCE_DIR) / "tests" / "hostile" / "traces";
const fs::path kScenarios = fs::path(MG_SOURCE_DIR) / "corpus" / "scenarios";

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

void expect_trace_rejection(const CliResult& r, const std::string& what, const std::string& file,
                            const std::string& expected) {
  EXPECT_EQ(r.exit_code, 2) << what << ": " << r.err;
  ASSERT_FALSE(r.err.empty()) << what;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << what << ": one line expected: " << r.err;
  EXPECT_NE(r.err.find(file + ": /"), std::string::npos) << what << ": must name the file and a JSON path: " << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << what << ": expected '" << expected << "' in: " << r.err;
  EXPECT_TRUE(r.out.empty()) << what << ": nothing on stdout on error";
}

// Each hostile trace with the JSON path and reason its message must hold (tests/hostile/README.md).
const std::vector<std::pair<std::string, std::string>> kHostileTraces = {
    {"empty.json", "/: empty input"},
    {"truncated.json", "/: malformed JSON"},
    {"nan_literal.json", "/: malformed JSON"},
    {"infinity_literal.json", "/: malformed JSON"},
    {"number_overflow.json", "number out of range of a double"},
    {"unknown_key.json", "/steps/1/turbo: unknown key"},
    {"duplicate_key.json", "/steps/1/time_s: duplicate key 'time_s'"},
    {"non_increasing_time.json", "/steps/2/time_s: times must increase strictly (0.02 after 0.02)"},
    {"decreasing_time.json", "/steps/1/time_s: times must increase strictly (0.01 after 0.02)"},
    {"vehicle_missing_from_step.json", "/steps/1/states: 2 states for 3 declared vehicles (vehicle 3 missing)"},
    {"extra_state_row.json", "/steps/2/states: 4 states for 3 declared vehicles (1 extra)"},
    {"negative_length.json", "/vehicles/1/size/length_m: must be > 0, got -4.8"},
    {"zero_length.json", "/vehicles/0/size/length_m: must be > 0"},
    {"absurd_size.json", "/vehicles/2/size/length_m: must be in (0, 30], got 4800"},
    {"zero_width.json", "/vehicles/1/size/width_m: must be > 0"},
    {"huge_width.json", "/vehicles/0/size/width_m: must be in (0, 5], got 50"},
    {"absurd_limits.json", "/vehicles/0/limits/brake_max_mps2: must be in (0, 15], got 1000000000"},
    {"negative_limit.json", "/vehicles/2/limits/accel_max_mps2: must be in"},
    {"inconsistent_limits.json", "/vehicles/0/limits/brake_min_mps2: must be <= brake_max_mps2"},
    {"request_without_pc.json", "/channel/0/message/pc_m: a request must carry a number, got null"},
    {"absurd_speed.json", "/steps/1/states/0/3: vx_mps must be in [-150.0, 150.0], got 310000000.0"},
    {"future_version.json", "/version: unsupported trace format version 2 (this build reads version 1)"},
    {"wrong_format.json", "/format: must be \"mergeguard-trace\", got \"mergeguard-scenario\""},
    {"undeclared_message_id.json", "/channel/2/message/from_id: vehicle id 7 is not declared in /vehicles"},
};

TEST(CheckTrace, EveryHostileTraceIsRefusedWithTheFileAndTheJsonPathAndNothingWritten) {
  for (const auto& [file, expected] : kHostileTraces) {
    const std::string path = (kTraces / file).string();
    const fs::path dir = fresh_dir("check_trace_hostile");
    const fs::path report = dir / "report";  // does not exist: must not be created
    expect_trace_rejection(run_cli({"check-trace", path, "--report", report.string()}), "check-trace --report " + file,
                           path, expected);
    EXPECT_FALSE(fs::exists(report)) << file << ": the report directory was created";
    expect_trace_rejection(run_cli({"check-trace", path, "--json"}), "check-trace --json " + file, path, expected);
    fs::remove_all(dir);
  }
}

TEST(CheckTrace, NoHostileTraceIsLeftOutOfTheTable) {
  std::set<std::string> listed;
  for (const auto& entry : kHostileTraces) listed.insert(entry.first);
  for (const auto& entry : fs::directory_iterator(kTraces)) {
    const std::string name = entry.path().filename().string();
    if (name != "valid.json") {
      EXPECT_TRUE(listed.count(name)) << name << " is not run through check-trace";
    }
  }
}

TEST(CheckTrace, TheControlTraceIsJudged) {
  const CliResult r = run_cli({"check-trace", (kTraces / "valid.json").string(), "--json"});
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("\"scenario\""), std::string::npos);
}

TEST(CheckTrace, AMissingTraceOrABadParamsFileIsBadInput) {
  const fs::path dir = fresh_dir("check_trace_params");
  const std::string valid = (kTraces / "valid.json").string();
  const std::string missing = (dir / "missing.json").string();
  const CliResult no_file = run_cli({"check-trace", missing});
  EXPECT_EQ(no_file.exit_code, 2);
  EXPECT_NE(no_file.err.find(missing + ": /: cannot open file"), std::string::npos) << no_file.err;

  const std::vector<std::pair<std::string, std::string>> bad_params = {
      {R"({"rules": {"turbo": 1}})", "/rules/turbo: unknown key"},
      {R"({"rules": {"merge_duration_s": 1e9}})", "/rules/merge_duration_s: must be in"},
      {R"({"rss": {"response_time_s": -1}})", "/rss/response_time_s: must be in"},
      {R"({"rules": {"comm_threshold_s": 1.0, "comm_threshold_s": 2.0}})", "duplicate key 'comm_threshold_s'"},
      {R"({"rules": )", "/: malformed JSON"},
      {R"([1, 2])", "/: must be a JSON object"},
  };
  for (const auto& [text, expected] : bad_params) {
    const fs::path params = dir / "params.json";
    write(params, text);
    const fs::path report = dir / "report";
    expect_trace_rejection(run_cli({"check-trace", valid, "--params", params.string(), "--report", report.string()}),
                           "--params " + text, params.string(), expected);
    EXPECT_FALSE(fs::exists(report)) << text;
  }
  fs::remove_all(dir);
}

TEST(CheckTrace, UnwritableReportDirectoryIsRefusedBeforeJudging) {
  const fs::path dir = fresh_dir("check_trace_unwritable");
  const fs::path file = dir / "a_file";
  write(file, "not a directory\n");
  const CliResult r = run_cli({"check-trace", (kTraces / "valid.json").string(), "--report", file.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--report " + file.string() + ": exists and is not a directory"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  fs::remove_all(dir);
}

// --params: the trace's own params object as a params file changes nothing; planner and sim parts
// are validated and ignored; a stricter rule parameter changes the judgement.
TEST(CheckTrace, ParamsFileReplacesTheTracesRuleParameters) {
  const fs::path dir = fresh_dir("check_trace_params_effect");
  const fs::path trace = dir / "trace.json";
  const CliResult saved =
      run_cli({"check", (kScenarios / "paper_merge.json").string(), "--save-trace", trace.string(), "--json"});
  ASSERT_TRUE(saved.exit_code == 0 || saved.exit_code == 1) << saved.err;
  const CliResult own = run_cli({"check-trace", trace.string(), "--json"});
  EXPECT_EQ(own.out, saved.out);

  write(dir / "same.json", R"({"planner": {"merge_duration_s": 9.0}, "sim": {"step_s": 0.1}})");
  const CliResult same = run_cli({"check-trace", trace.string(), "--json", "--params", (dir / "same.json").string()});
  EXPECT_EQ(same.exit_code, own.exit_code) << same.err;
  EXPECT_EQ(same.out, own.out);

  write(dir / "strict.json", R"({"rules": {"sideslip_max_rad": 1e-6, "sideslip_min_speed_mps": 0.0}})");
  const CliResult strict = run_cli({"check-trace", trace.string(), "--json", "--params", (dir / "strict.json").string()});
  EXPECT_EQ(strict.exit_code, 1) << strict.err;
  const auto violated = strict.out.find("\"rules_violated\"");
  ASSERT_NE(violated, std::string::npos);
  EXPECT_NE(strict.out.find("\"sideslip\"", violated), std::string::npos) << strict.out;
  fs::remove_all(dir);
}

// check SCENARIO --save-trace T and check-trace T: same stdout (JSON and human), same exit code,
// byte-identical report files, for a few corpus scenarios and planners.
TEST(CheckTrace, JudgingTheSavedTraceGivesExactlyWhatCheckGave) {
  const std::vector<std::string> scenarios = {"paper_merge.json", "fig2_s1_ahead_noncoop.json",
                                              "fig2_s4_behind_coop.json", "follower_exceeds_accel.json",
                                              "responder_reneges.json", "no_feasible_gap_halt.json"};
  std::set<int> exit_codes;
  for (const std::string planner : {"rcpp", "tripfield", "rcpp-coop"}) {
    for (const std::string& name : scenarios) {
      const std::string what = name + " with " + planner;
      const fs::path dir = fresh_dir("check_trace_same");
      const fs::path trace = dir / "trace.json";
      const std::string scenario = (kScenarios / name).string();

      const CliResult check_json = run_cli({"check", scenario, "--planner", planner, "--save-trace", trace.string(), "--json"});
      ASSERT_TRUE(check_json.exit_code == 0 || check_json.exit_code == 1) << what << ": " << check_json.err;
      const CliResult trace_json = run_cli({"check-trace", trace.string(), "--json"});
      EXPECT_EQ(trace_json.exit_code, check_json.exit_code) << what << ": " << trace_json.err;
      EXPECT_EQ(trace_json.out, check_json.out) << what;
      EXPECT_TRUE(trace_json.err.empty()) << what << ": " << trace_json.err;
      exit_codes.insert(check_json.exit_code);

      // The same --report path in both runs (the human summary prints it); check's files are moved
      // aside before check-trace writes its own.
      const fs::path report = dir / "report";
      const fs::path report_of_check = dir / "report_of_check";
      const CliResult check_human = run_cli({"check", scenario, "--planner", planner, "--report", report.string()});
      fs::rename(report, report_of_check);
      const CliResult trace_human = run_cli({"check-trace", trace.string(), "--report", report.string()});
      EXPECT_EQ(trace_human.exit_code, check_human.exit_code) << what;
      EXPECT_EQ(trace_human.out, check_human.out) << what;
      for (const char* file : {"report.json", "report.md", "report.html"}) {
        const std::string of_check = slurp(report_of_check / file);
        EXPECT_FALSE(of_check.empty()) << what << ": " << file;
        EXPECT_TRUE(of_check == slurp(report / file)) << what << ": " << file << " differs";
      }
      fs::remove_all(dir);
    }
  }
  EXPECT_EQ(exit_codes.size(), 2u) << "the scenarios should give both verdicts";
}

TEST(CheckTrace, IsListedInTheUsage) {
  const CliResult r = run_cli({"--help"});
  EXPECT_NE(r.out.find("mergeguard check-trace TRACE.json [--report DIR] [--json] [--params FILE]"), std::string::npos)
      << r.out;
  EXPECT_EQ(run_cli({"check-trace", "--help"}).exit_code, 0);
  EXPECT_EQ(run_cli({"check-trace"}).exit_code, 2);
}

}  // namespace
}  // namespace mg::test
