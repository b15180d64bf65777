// The rule catalogue (rules/catalog.json, embedded at build time): per rule its id, paper
// reference, unit, temporal-logic statement, liability logic, kind and the rule parameters it reads
// (their defaults and ranges are RuleParams' and RssParams', core/params.h). The catalogue is
// where rule ids are declared: a monitor names the rule it judges (MarginAccumulator), which must
// be in it, and rules/check.cpp orders the monitors' results as it does.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace mg {

struct RuleSpec {
  std::string id;
  std::string paper_ref;
  std::string unit;
  std::string statement;
  std::string liability;
  std::vector<std::string> parameters;  // keys of params.rules and params.rss
  bool liveness = false;  // "kind": "liveness" (what a planner must do) or "safety" (what no run may do)
};

const nlohmann::json& rule_catalog_json();
const std::vector<RuleSpec>& rule_catalog();       // in catalogue order (= report order)
const RuleSpec& rule_spec(std::string_view id);    // std::logic_error for an unknown id
std::size_t rule_index(std::string_view id);       // its place in rule_catalog(); std::logic_error likewise

}  // namespace mg
