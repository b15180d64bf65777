// `mergeguard plan` (src/cli/cmd_plan.cpp, spec §10): a decision for every scenario of the corpus,
// JSON output, exit code 2 on bad input. Needs env MG_CLI (set by CTest).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <sys/wait.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace mg {
namespace {

struct PlanRun {
  int exit_code = -1;
  std::string out;
};

PlanRun run_plan(const std::string& args) {
  const char* cli = std::getenv("MG_CLI");
  PlanRun r;
  if (!cli) return r;
  const std::string cmd = std::string("'") + cli + "' plan " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

class PlanCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("MG_CLI")) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  }
};

TEST_F(PlanCommand, PrintsAnExplainedDecisionForEveryCorpusScenario) {
  const std::filesystem::path dir = std::filesystem::path(MG_SOURCE_DIR) / "corpus" / "scenarios";
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".json" || name.find(".expected.") != std::string::npos) continue;
    for (const std::string planner : {"rcpp", "rcpp-coop", "tripfield"}) {
      const PlanRun r = run_plan("'" + entry.path().string() + "' --planner " + planner + " --json");
      ASSERT_EQ(r.exit_code, 0) << name << " / " << planner;
      const auto j = nlohmann::json::parse(r.out);
      EXPECT_EQ(j.at("planner"), planner);
      EXPECT_FALSE(j.at("decision").at("mode").get<std::string>().empty());
      EXPECT_FALSE(j.at("decision").at("reason").get<std::string>().empty()) << name;
    }
    ++count;
  }
  EXPECT_GE(count, 4);
}

TEST_F(PlanCommand, HumanReadableOutputNamesModeGapAndBounds) {
  const PlanRun r = run_plan("'" + std::string(MG_SOURCE_DIR) + "/corpus/scenarios/fig2_s1_ahead_noncoop.json'");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* key : {"mode:", "def1_merge", "gap:", "follower 1, leader open", "v_e* interval:", "P_c bounds:",
                          "kappa:", "reason:"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
}

TEST_F(PlanCommand, BadInputExitsWithTwo) {
  EXPECT_EQ(run_plan("/nonexistent/scenario.json").exit_code, 2);
  EXPECT_EQ(run_plan("'" + std::string(MG_SOURCE_DIR) + "/corpus/scenarios/fig2_s1_ahead_noncoop.json' --planner nope")
                .exit_code,
            2);
  EXPECT_EQ(run_plan("").exit_code, 2);
}

}  // namespace
}  // namespace mg
