#include "rules/rule_catalog.h"

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/params.h"
#include "rules/check.h"
#include "rules/monitor.h"
#include "trace_builder.h"

namespace mg {
namespace {

TEST(RuleCatalog, EmbeddedCatalogIsTheFileInTheRepository) {
  std::ifstream in(std::string(MG_SOURCE_DIR) + "/rules/catalog.json");
  ASSERT_TRUE(in.good());
  EXPECT_EQ(nlohmann::json::parse(in), rule_catalog_json());
}

// The catalogue declares the rule ids; a monitor names the one it judges. Every monitor's rule is
// in the catalogue and every rule of the catalogue has exactly one monitor.
TEST(RuleCatalog, EveryRuleHasExactlyOneMonitorAndEveryMonitorARule) {
  const Scenario s = test::base_scenario();
  const Trace trace = test::constant_accel_trace(s, 1.0);
  std::map<std::string, int> monitors_of;
  for (const MonitorFn fn : rule_monitors()) {
    try {  // a monitor of a rule the catalogue lacks throws as it names its rule
      ++monitors_of[test::run(fn, s, trace).result.rule_id];
    } catch (const std::logic_error& e) {
      ADD_FAILURE() << "a monitor judges a rule that is not in the catalogue: " << e.what();
    }
  }
  for (const RuleSpec& r : rule_catalog()) EXPECT_EQ(monitors_of[r.id], 1) << r.id << ": monitors judging it";
}

// The checker reports the rules in catalogue order, whatever order the monitors run in.
TEST(RuleCatalog, ResultsComeInCatalogueOrder) {
  const Scenario s = test::base_scenario();
  const CheckResult r = check_observed(test::observed(s, test::constant_accel_trace(s, 1.0)));
  ASSERT_EQ(r.rules.size(), rule_catalog().size());
  for (std::size_t i = 0; i < r.rules.size(); ++i) EXPECT_EQ(r.rules[i].rule_id, rule_catalog()[i].id);
}

// A rule's "parameters" are keys of params.rules or params.rss (core/params.h): their defaults
// and ranges live there, not in the catalogue.
TEST(RuleCatalog, EveryRuleParameterIsARuleOrRssParameter) {
  for (const RuleSpec& r : rule_catalog())
    for (const std::string& p : r.parameters)
      EXPECT_TRUE(declares(rule_param_table(), p) || declares(rss_param_table(), p)) << r.id << ": " << p;
  EXPECT_FALSE(rule_catalog_json().contains("parameters")) << "defaults belong to the parameter tables";
}

TEST(RuleCatalog, EveryRuleNamesItsPaperReferenceStatementAndLiability) {
  std::set<std::string> ids;
  for (const RuleSpec& r : rule_catalog()) {
    EXPECT_TRUE(ids.insert(r.id).second) << "duplicate " << r.id;
    EXPECT_FALSE(r.paper_ref.empty()) << r.id;
    EXPECT_FALSE(r.statement.empty()) << r.id;
    EXPECT_FALSE(r.liability.empty()) << r.id;
    EXPECT_FALSE(r.unit.empty()) << r.id;
  }
  for (const char* required : {"rss_longitudinal", "rss_lateral", "def1_1_gap", "def1_2_gap", "def1_3_halt",
                               "def2_1a_request", "def2_1b_responder", "def2_2a_ego_brake", "def2_2b_responder",
                               "def2_3_fallback", "sigmoid_pc_bounds", "collision", "on_road", "side_lane_end",
                               "smoothness_oscillation", "sideslip", "progress"}) {
    EXPECT_EQ(ids.count(required), 1u) << required;
  }
}

TEST(RuleCatalog, ProgressIsTheOneLivenessRule) {
  std::vector<std::string> liveness;
  for (const RuleSpec& r : rule_catalog())
    if (r.liveness) liveness.push_back(r.id);
  EXPECT_EQ(liveness, std::vector<std::string>{"progress"});
}

// A judgement of the safety rules only (an audit's) sets the liveness rule aside: an ego that
// never merges on an empty road fails `progress` in a full check and holds in a safety check,
// where `progress` is not applicable and says why.
TEST(RuleCatalog, ASafetyJudgementSetsTheLivenessRuleAside) {
  const Scenario s = test::base_scenario();
  const ObservedTrace t = test::observed(s, test::constant_accel_trace(s, 5.0));
  const CheckResult all = check_observed(t);
  const CheckResult safety = check_observed(t, std::nullopt, RuleSet::kSafety);
  EXPECT_FALSE(all.rules[rule_index("progress")].holds);
  EXPECT_FALSE(all.holds);
  const RuleResult& p = safety.rules[rule_index("progress")];
  EXPECT_TRUE(p.holds);
  EXPECT_TRUE(std::isinf(p.min_margin));
  EXPECT_NE(p.detail.find("not judged"), std::string::npos);
  EXPECT_TRUE(safety.holds);
}

TEST(RuleCatalog, UnknownRuleIdIsALogicError) { EXPECT_THROW(rule_spec("no_such_rule"), std::logic_error); }

}  // namespace
}  // namespace mg
