// The outside planner under the outside project's own GoogleTest/RapidCheck suite: the campaign
// and property functions of mergeguard called directly, no command line involved.
#include <iostream>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <mergeguard/mergeguard.h>

#include "naive_merge_planner.h"

namespace {

// Registered once per process, before any test looks the planner up.
const bool kRegistered = (example::register_naive_merge_planner(), true);

mg::fuzz::CheckFn naive_check() {
  return [](const mg::Scenario& s) { return mg::check_scenario(s, example::kNaivePlannerName); };
}

TEST(NaiveMergePlanner, IsRegisteredUnderItsName) {
  ASSERT_TRUE(kRegistered);
  const auto planner = mg::make_planner(example::kNaivePlannerName);
  ASSERT_NE(planner, nullptr);
  EXPECT_EQ(planner->name(), example::kNaivePlannerName);
}

// A short campaign, as `fuzz --runs 40 --seed 1` would run it. A naive planner fails some
// scenarios; every failure is recorded against it.
TEST(NaiveMergePlanner, ACampaignRunsAndBlamesThePlanner) {
  mg::fuzz::CampaignOptions options;
  options.seed = 1;
  options.runs = 40;
  options.planner = example::kNaivePlannerName;
  const mg::fuzz::CampaignResult result = mg::fuzz::run_campaign(options, [] { return naive_check(); });
  EXPECT_EQ(result.scenarios, 40u);
  for (const auto& [signature, record] : result.signatures) EXPECT_EQ(signature.planner, example::kNaivePlannerName);
  std::cout << mg::fuzz::campaign_summary_json(options, result).dump(2) << "\n";
}

// Properties the naive planner does keep, over generated scenarios: the checker completes on it
// (no property check_completes failure), and its first path runs in increasing X.
RC_GTEST_PROP(NaiveMergePlanner, CheckCompletesAndPathsIncrease, ()) {
  const mg::Scenario s = *mg::fuzz::gen_scenario(mg::fuzz::GenConfig{});
  const mg::fuzz::RunOutcome outcome = mg::fuzz::run_properties(s, naive_check(), example::kNaivePlannerName, false);
  for (const mg::fuzz::PropertyFailure& f : outcome.failures) RC_ASSERT(f.property != mg::fuzz::property::kCheckCompletes);
  const mg::PlanOutput out = example::NaiveMergePlanner().plan(mg::initial_snapshot(s));
  for (std::size_t i = 1; i < out.path.size(); ++i) RC_ASSERT(out.path[i].x_m > out.path[i - 1].x_m);
}

}  // namespace
