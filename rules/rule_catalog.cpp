#include "rules/rule_catalog.h"

#include <stdexcept>

#include "rules/rule_catalog_json.h"

namespace mg {

const nlohmann::json& rule_catalog_json() {
  static const nlohmann::json catalog = nlohmann::json::parse(generated::kRuleCatalogJson);
  return catalog;
}

const std::vector<RuleSpec>& rule_catalog() {
  static const std::vector<RuleSpec> specs = [] {
    std::vector<RuleSpec> out;
    for (const auto& r : rule_catalog_json().at("rules")) {
      const std::string kind = r.at("kind").get<std::string>();
      if (kind != "safety" && kind != "liveness") throw std::logic_error("rules/catalog.json: unknown kind " + kind);
      out.push_back({r.at("id").get<std::string>(), r.at("paper_ref").get<std::string>(),
                     r.at("unit").get<std::string>(), r.at("statement").get<std::string>(),
                     r.at("liability").get<std::string>(), r.at("parameters").get<std::vector<std::string>>(),
                     kind == "liveness"});
    }
    return out;
  }();
  return specs;
}

const RuleSpec& rule_spec(std::string_view id) { return rule_catalog()[rule_index(id)]; }

std::size_t rule_index(std::string_view id) {
  const auto& specs = rule_catalog();
  for (std::size_t i = 0; i < specs.size(); ++i)
    if (specs[i].id == id) return i;
  throw std::logic_error("rule not in rules/catalog.json: " + std::string(id));
}

}  // namespace mg
