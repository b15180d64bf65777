// Rule coverage of a campaign (docs/fuzzing.md "Rule coverage"): which rules its scenarios
// exercised, which they never exercised, and which cannot apply to the planner under test at all.
// A campaign that finds nothing says nothing about a rule it never exercised, so every summary
// and report names those rules.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fuzz/campaign.h"

namespace mg::fuzz {

// The rules that cannot apply to `planner` whatever the scenario, each with the reason (empty
// for a planner this table does not know: every rule is then expected to apply). This is about
// what a campaign can test, never about verdicts: the rules themselves do not know planners.
std::map<std::string, std::string> rules_not_applicable(const std::string& planner);

struct RuleCoverage {
  std::string rule;
  std::uint64_t scenarios = 0;
  std::uint64_t exercised = 0;
  bool applicable = true;          // false: rules_not_applicable names it
  std::string not_applicable_why;  // the reason when !applicable
  double share() const { return scenarios > 0 ? static_cast<double>(exercised) / static_cast<double>(scenarios) : 0.0; }
};

// One row per rule of the catalogue, in catalogue order (then any other rule the checks reported).
std::vector<RuleCoverage> rule_coverage(const std::string& planner, const CampaignResult& result);
// The rules that can apply to the planner but that none of the scenarios that evaluated them
// exercised (a checkpoint without margins has none).
std::vector<std::string> rules_never_exercised(const std::string& planner, const CampaignResult& result);

}  // namespace mg::fuzz
