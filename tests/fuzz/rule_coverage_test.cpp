#include "fuzz/rule_coverage.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "check/checked_run.h"
#include "fuzz/campaign_report.h"
#include "rules/check.h"
#include "rules/rule_catalog.h"

namespace mg::fuzz {
namespace {

namespace fs = std::filesystem;
constexpr double kNeverApplied = std::numeric_limits<double>::infinity();

TEST(MarginStats, ARuleThatNeverAppliedIsCountedButNotExercised) {
  MarginStats m;
  m.add(kNeverApplied, true);
  EXPECT_EQ(m.scenarios, 1u);
  EXPECT_EQ(m.exercised, 0u);
  EXPECT_FALSE(m.mean().has_value());
  for (auto n : m.bins) EXPECT_EQ(n, 0u);  // no sentinel folded into the top bin
  m.add(2.0, true);
  m.add(-1.0, false);
  EXPECT_EQ(m.scenarios, 3u);
  EXPECT_EQ(m.exercised, 2u);
  EXPECT_EQ(m.violated, 1u);
  EXPECT_DOUBLE_EQ(m.min, -1.0);
  ASSERT_TRUE(m.mean().has_value());
  EXPECT_DOUBLE_EQ(*m.mean(), 0.5);  // over the exercised scenarios only
}

TEST(MarginStats, MergingPartsGivesTheStatisticsOfTheWhole) {
  const std::vector<std::pair<double, bool>> margins = {{kNeverApplied, true}, {3.0, true}, {-0.5, false},
                                                        {kNeverApplied, true}, {12.0, true}};
  MarginStats whole, first, second, empty;
  for (std::size_t i = 0; i < margins.size(); ++i) {
    whole.add(margins[i].first, margins[i].second);
    (i < 2 ? first : second).add(margins[i].first, margins[i].second);
  }
  MarginStats merged;
  merged.merge(empty);
  merged.merge(first);
  merged.merge(second);
  EXPECT_EQ(merged.scenarios, whole.scenarios);
  EXPECT_EQ(merged.exercised, whole.exercised);
  EXPECT_EQ(merged.violated, whole.violated);
  EXPECT_EQ(merged.min, whole.min);
  EXPECT_EQ(merged.sum_micro, whole.sum_micro);
  EXPECT_EQ(merged.bins, whole.bins);
  // A part in which the rule never applied does not pull the minimum to its default.
  MarginStats none;
  none.add(kNeverApplied, true);
  MarginStats positive;
  positive.add(4.0, true);
  positive.merge(none);
  EXPECT_DOUBLE_EQ(positive.min, 4.0);
}

TEST(RuleCoverage, DefinitionTwoCannotApplyToTheNonCooperativePlanners) {
  for (const std::string planner : {"rcpp", "tripfield", "mobil", "frenet"}) {
    const auto na = rules_not_applicable(planner);
    for (const char* id : {"def2_1a_request", "def2_1b_responder", "def2_2a_ego_brake", "def2_2b_responder", "def2_3_fallback"})
      EXPECT_TRUE(na.count(id)) << planner << " " << id;
    for (const auto& [rule, why] : na) {
      EXPECT_NO_THROW(rule_spec(rule)) << rule;  // names real rules
      EXPECT_FALSE(why.empty());
    }
  }
  EXPECT_TRUE(rules_not_applicable("rcpp-coop").empty());
  EXPECT_TRUE(rules_not_applicable("someone-elses-planner").empty());  // unknown: every rule expected
}

// A campaign result in which rule `a` was exercised and rule `b` never applied.
CampaignResult result_with(const std::string& a, const std::string& b) {
  CampaignResult r;
  r.scenarios = 2;
  for (int i = 0; i < 2; ++i) {
    r.margins[a].unit = "m";
    r.margins[a].add(1.5, true);
    r.margins[b].unit = "m/s";
    r.margins[b].add(kNeverApplied, true);
  }
  return r;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(RuleCoverage, TheReportWarnsAboutAnApplicableRuleNeverExercisedAndMarksTheInapplicable) {
  const fs::path dir = fs::temp_directory_path() / ("mg_rule_coverage_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  CampaignOptions o;
  o.runs = 2;
  o.planner = "rcpp-coop";
  const CampaignResult r = result_with("collision", "def2_2b_responder");
  write_campaign_report(dir.string(), o, r, {});
  const std::string md = read(dir / "report.md");
  EXPECT_NE(md.find("> Warning: 1 rule(s) that can apply to rcpp-coop were exercised in none of the 2 scenarios"), std::string::npos);
  EXPECT_NE(md.find("def2_2b_responder | m/s | 2 | 0 | 0 | not exercised | not exercised"), std::string::npos) << md;
  const std::string page = read(dir / "report.html");
  EXPECT_NE(page.find("class=\"warning\""), std::string::npos);
  // One margin histogram per exercised rule, none for the rule that never applied.
  EXPECT_NE(page.find("aria-label=\"margin histogram of collision\""), std::string::npos);
  EXPECT_EQ(page.find("aria-label=\"margin histogram of def2_2b_responder\""), std::string::npos);
  const auto summary = campaign_summary_json(o, r);
  EXPECT_EQ(summary["margins"]["def2_2b_responder"]["exercised"], 0);
  EXPECT_TRUE(summary["margins"]["def2_2b_responder"]["mean"].is_null());
  EXPECT_EQ(summary["margins"]["collision"]["exercised"], 2);
  EXPECT_EQ(summary["rules_never_exercised"], nlohmann::json::array({"def2_2b_responder"}));

  o.planner = "rcpp";  // Definition 2 cannot apply: no warning, "not applicable"
  write_campaign_report(dir.string(), o, r, {});
  const std::string md_rcpp = read(dir / "report.md");
  EXPECT_EQ(md_rcpp.find("Warning"), std::string::npos);
  EXPECT_NE(md_rcpp.find("> Not applicable to rcpp: def2_1a_request def2_1b_responder def2_2a_ego_brake"), std::string::npos);
  EXPECT_NE(md_rcpp.find("| not applicable | not applicable |"), std::string::npos);
  EXPECT_FALSE(campaign_summary_json(o, r)["margins"]["def2_2b_responder"]["applicable"].get<bool>());
  fs::remove_all(dir);
}

// The CI guard (docs/fuzzing.md "Rule coverage"): a small fixed-seed campaign per planner
// exercises every rule that can apply to it, and none of those that cannot (a rule that starts
// applying means the table in rule_coverage.cpp is stale). mobil changes lanes as soon as MOBIL
// lets it, so the progress rule (an ego waiting beside a usable gap) applies in under 1 % of its
// scenarios: its campaign is longer.
struct GuardCase {
  std::string planner;
  std::uint64_t runs = 240;
};
void PrintTo(const GuardCase& g, std::ostream* os) { *os << g.planner; }

class RuleCoverageGuard : public ::testing::TestWithParam<GuardCase> {};

TEST_P(RuleCoverageGuard, ASmallCampaignExercisesEveryApplicableRuleAndNoOther) {
  const std::string planner = GetParam().planner;
  CampaignOptions o;
  o.seed = 20261201;
  o.runs = GetParam().runs;
  o.jobs = 2;
  o.planner = planner;
  o.determinism_every = 0;
  const CampaignResult r = run_campaign(o, [planner] {
    return CheckFn([planner](const Scenario& s) { return check_scenario(s, planner); });
  });
  ASSERT_EQ(r.scenarios, GetParam().runs);
  EXPECT_EQ(rules_never_exercised(planner, r), std::vector<std::string>{});
  for (const RuleCoverage& c : rule_coverage(planner, r)) {
    EXPECT_EQ(c.scenarios, GetParam().runs) << c.rule;
    if (!c.applicable) {
      EXPECT_EQ(c.exercised, 0u) << c.rule << " is listed as not applicable to " << planner;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryBuiltInPlanner, RuleCoverageGuard,
                         ::testing::Values(GuardCase{"rcpp"}, GuardCase{"rcpp-coop"}, GuardCase{"tripfield"},
                                           GuardCase{"mobil", 1000}, GuardCase{"frenet"}),
                         [](const auto& info) {
                           std::string name = info.param.planner;
                           for (char& ch : name) ch = ch == '-' ? '_' : ch;
                           return name;
                         });

}  // namespace
}  // namespace mg::fuzz
