// Liveness through the built binary: `check` on the curated scenarios with the exec planners of
// tests/planner/exec_helpers/fake_exec_planner.cpp that never merge (creep: slows to 0.06 m/s in
// its lane; stop-short: stops 39 m before the side lane's end and waits) exits 1 naming the
// progress rule, ego liable, and report.json says what it judged with and what the ego let pass.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace mg {
namespace {

std::string fake(const std::string& mode) { return std::string("exec:") + MG_FAKE_EXEC_PLANNER + " " + mode; }

std::string scenario(const std::string& name) { return std::string(MG_SOURCE_DIR) + "/corpus/scenarios/" + name + ".json"; }

const nlohmann::json& rule_of(const nlohmann::json& report, const std::string& id) {
  for (const nlohmann::json& r : report.at("rules"))
    if (r.at("rule_id") == id) return r;
  throw std::runtime_error("no rule " + id);
}

class NeverMerging : public testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(NeverMerging, CheckExitsOneNamingProgressWithTheEgoLiable) {
  const auto& [mode, name] = GetParam();
  const auto r = test::run_cli({"check", scenario(name), "--planner", fake(mode), "--json"});
  ASSERT_EQ(r.exit_code, 1) << r.err << r.out;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report.at("verdict"), "violated");
  const std::vector<std::string> violated = report.at("rules_violated");
  EXPECT_NE(std::find(violated.begin(), violated.end(), "progress"), violated.end()) << r.out;
  const nlohmann::json& progress = rule_of(report, "progress");
  EXPECT_EQ(progress.at("liable"), "ego");
  EXPECT_NE(progress.at("detail").get<std::string>().find("let the right of way pass"), std::string::npos);
  EXPECT_GE(progress.at("measures").at("feasible_gaps_let_pass").get<double>(), 1.0);
  EXPECT_GT(progress.at("measures").at("offered_unused_s").get<double>(), 3.0);
  EXPECT_EQ(report.at("judged_with").at("rules").at("progress_grace_s"), 3.0);
  EXPECT_TRUE(report.at("judged_with").at("rss").contains("response_time_s"));
}

INSTANTIATE_TEST_SUITE_P(CuratedScenarios, NeverMerging,
                         testing::Combine(testing::Values("creep", "stop-short"),
                                          testing::Values("fig2_s1_ahead_noncoop", "fig2_s2_behind_noncoop",
                                                          "bench_std4")),
                         [](const auto& info) {
                           std::string n = std::get<0>(info.param) + "_" + std::get<1>(info.param);
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

}  // namespace
}  // namespace mg
