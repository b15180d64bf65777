#include "rules/rule_catalog.h"

#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "rules/monitor.h"

namespace mg {
namespace {

TEST(RuleCatalog, EmbeddedCatalogIsTheFileInTheRepository) {
  std::ifstream in(std::string(MG_SOURCE_DIR) + "/rules/catalog.json");
  ASSERT_TRUE(in.good());
  EXPECT_EQ(nlohmann::json::parse(in), rule_catalog_json());
}

TEST(RuleCatalog, EveryRuleHasExactlyOneMonitorInCatalogueOrder) {
  const auto& specs = rule_catalog();
  const auto& monitors = rule_monitors();
  ASSERT_EQ(specs.size(), monitors.size());
  for (std::size_t i = 0; i < specs.size(); ++i) EXPECT_EQ(specs[i].id, monitors[i].rule_id);
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

TEST(RuleCatalog, UnknownRuleIdIsALogicError) { EXPECT_THROW(rule_spec("no_such_rule"), std::logic_error); }

}  // namespace
}  // namespace mg
