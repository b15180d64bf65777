// `mergeguard check` end to end through the built binary (env MG_CLI).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/observed_trace_json.h"

namespace {

namespace fs = std::filesystem;

int run(const std::string& args) {
  const char* cli = std::getenv("MG_CLI");
  if (!cli) return -1;
  const int status = std::system((std::string(cli) + " check " + args + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string scenario(const std::string& name) { return std::string(MG_SOURCE_DIR) + "/corpus/scenarios/" + name + ".json"; }

TEST(CmdCheck, ExitsZeroWhenEveryRuleHolds) {
  if (!std::getenv("MG_CLI")) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  EXPECT_EQ(run(scenario("fig2_s1_ahead_noncoop")), 0);
}

TEST(CmdCheck, ExitsOneAndWritesTheLiabilityReportOnAViolation) {
  if (!std::getenv("MG_CLI")) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  const fs::path dir = fs::temp_directory_path() / ("mg_cmd_check_" + std::to_string(::getpid()));
  EXPECT_EQ(run(scenario("leader_overbrakes") + " --report " + dir.string()), 1);
  std::ifstream in(dir / "report.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("verdict"), "violated");
  EXPECT_EQ(j.at("liable"), "vehicle 1");
  EXPECT_TRUE(fs::exists(dir / "report.html"));
  EXPECT_TRUE(fs::exists(dir / "report.md"));
  fs::remove_all(dir);
}

TEST(CmdCheck, SaveTraceWritesTheRunsObservableTrace) {
  if (!std::getenv("MG_CLI")) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  const fs::path file = fs::temp_directory_path() / ("mg_cmd_check_trace_" + std::to_string(::getpid()) + ".json");
  EXPECT_EQ(run(scenario("responder_reneges") + " --planner rcpp-coop --save-trace " + file.string()), 1);
  const mg::ObservedTrace t = mg::load_observed_trace(file.string());
  EXPECT_EQ(t.name, "responder_reneges");
  EXPECT_EQ(t.source, "mergeguard simulate (planner rcpp-coop)");
  EXPECT_GT(t.steps.size(), 100u);
  EXPECT_FALSE(t.channel.empty());
  EXPECT_EQ(t.planner_annotations.at("planner"), "rcpp-coop");
  fs::remove(file);
}

TEST(CmdCheck, AnUnwritableSaveTraceExitsTwoBeforeSimulating) {
  if (!std::getenv("MG_CLI")) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  const fs::path dir = fs::temp_directory_path() / ("mg_cmd_check_dir_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  EXPECT_EQ(run(scenario("fig2_s1_ahead_noncoop") + " --save-trace " + dir.string()), 2);  // a directory
  EXPECT_EQ(run(scenario("fig2_s1_ahead_noncoop") + " --save-trace /nonexistent/dir/trace.json"), 2);
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(CmdCheck, BadInputExitsTwo) {
  if (!std::getenv("MG_CLI")) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  EXPECT_EQ(run("/nonexistent/scenario.json"), 2);
  EXPECT_EQ(run(scenario("fig2_s1_ahead_noncoop") + " --planner no_such_planner"), 2);
}

}  // namespace
