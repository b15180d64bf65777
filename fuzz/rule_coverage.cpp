#include "fuzz/rule_coverage.h"

#include <algorithm>

#include "rules/rule_catalog.h"

namespace mg::fuzz {
namespace {

const char* const kNoV2vRequests =
    "the planner never sends a V2V request, and Definition 2's rules judge the ego's requests and what follows them";
std::map<std::string, std::string> definition2_rules() {
  std::map<std::string, std::string> out;
  for (const char* id : {"def2_1a_request", "def2_1b_responder", "def2_2a_ego_brake", "def2_2b_responder", "def2_3_fallback",
                         "def2_request_sound", "def2_positions", "def2_request_truthful"})
    out[id] = kNoV2vRequests;
  return out;
}

}  // namespace

std::map<std::string, std::string> rules_not_applicable(const std::string& planner) {
  // Definition 1 judges every observed merge, whoever drives it; only the built-ins that never
  // use V2V leave Definition 2's rules without anything to judge.
  if (planner == "rcpp" || planner == "tripfield" || planner == "mobil" || planner == "frenet") return definition2_rules();
  return {};
}

std::vector<RuleCoverage> rule_coverage(const std::string& planner, const CampaignResult& result) {
  const auto not_applicable = rules_not_applicable(planner);
  std::vector<std::string> ids;
  for (const RuleSpec& spec : rule_catalog()) ids.push_back(spec.id);
  for (const auto& [id, stats] : result.margins)  // a check outside the catalogue (tests) comes last
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  std::vector<RuleCoverage> out;
  for (const std::string& id : ids) {
    RuleCoverage c;
    c.rule = id;
    if (const auto m = result.margins.find(id); m != result.margins.end()) {
      c.scenarios = m->second.scenarios;
      c.exercised = m->second.exercised;
    }
    if (const auto na = not_applicable.find(id); na != not_applicable.end()) {
      c.applicable = false;
      c.not_applicable_why = na->second;
    }
    out.push_back(c);
  }
  return out;
}

std::vector<std::string> rules_never_exercised(const std::string& planner, const CampaignResult& result) {
  std::vector<std::string> out;
  for (const RuleCoverage& c : rule_coverage(planner, result))
    if (c.applicable && c.scenarios > 0 && c.exercised == 0) out.push_back(c.rule);
  return out;
}

}  // namespace mg::fuzz
