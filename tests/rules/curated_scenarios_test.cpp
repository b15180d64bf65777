// Replays every curated scenario of corpus/scenarios/ that has an expected verdict beside it
// (<name>.expected.json: planner, verdict, liable, rules_violated, collision) and compares.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "check/checked_run.h"
#include "core/scenario.h"
#include "rules/check.h"

namespace mg {
namespace {

namespace fs = std::filesystem;

const fs::path kScenarioDir = fs::path(MG_SOURCE_DIR) / "corpus" / "scenarios";
constexpr const char* kExpectedSuffix = ".expected.json";

std::vector<std::string> curated_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kScenarioDir)) {
    const std::string file = entry.path().filename().string();
    const std::string suffix = kExpectedSuffix;
    if (file.size() > suffix.size() && file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0)
      names.push_back(file.substr(0, file.size() - suffix.size()));
  }
  std::sort(names.begin(), names.end());
  return names;
}

class CuratedScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(CuratedScenario, GivesItsStoredVerdictAndLiableParty) {
  const std::string name = GetParam();
  std::ifstream in(kScenarioDir / (name + kExpectedSuffix));
  const nlohmann::json expected = nlohmann::json::parse(in);
  const Scenario s = load_scenario((kScenarioDir / (name + ".json")).string());
  const CheckResult r = check_scenario(s, expected.value("planner", "rcpp"));
  const nlohmann::json got = check_result_to_json(r);
  EXPECT_EQ(got.at("verdict"), expected.at("verdict")) << got.at("liability_detail");
  EXPECT_EQ(got.at("liable"), expected.at("liable")) << got.at("liability_detail");
  EXPECT_EQ(got.at("collision"), expected.value("collision", false));
  const auto as_set = [](const nlohmann::json& a) { return a.get<std::set<std::string>>(); };
  EXPECT_EQ(as_set(got.at("rules_violated")), as_set(expected.at("rules_violated")));
}

INSTANTIATE_TEST_SUITE_P(Corpus, CuratedScenario, ::testing::ValuesIn(curated_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(CuratedScenarios, EveryScenarioOfTheIssueHasAnExpectedVerdict) {
  const std::vector<std::string> names = curated_names();
  for (const char* required : {"fig2_s1_ahead_noncoop", "fig2_s2_behind_noncoop", "fig2_s3_ahead_coop",
                               "fig2_s4_behind_coop", "no_feasible_gap_halt", "follower_exceeds_accel",
                               "leader_overbrakes", "responder_reneges"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
  }
}

}  // namespace
}  // namespace mg
