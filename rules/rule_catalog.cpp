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
      out.push_back({r.at("id").get<std::string>(), r.at("paper_ref").get<std::string>(),
                     r.at("unit").get<std::string>(), r.at("statement").get<std::string>(),
                     r.at("liability").get<std::string>()});
    }
    return out;
  }();
  return specs;
}

const RuleSpec& rule_spec(std::string_view id) {
  for (const auto& s : rule_catalog()) {
    if (s.id == id) return s;
  }
  throw std::logic_error("rule not in rules/catalog.json: " + std::string(id));
}

const CatalogParams& catalog_params() {
  static const CatalogParams params = [] {
    const auto& p = rule_catalog_json().at("parameters");
    CatalogParams c;
    c.accel_tolerance_mps2 = p.at("accel_tolerance_mps2").get<double>();
    c.speed_tolerance_mps = p.at("speed_tolerance_mps").get<double>();
    c.yield_speed_tolerance_mps = p.at("yield_speed_tolerance_mps").get<double>();
    c.halted_speed_mps = p.at("halted_speed_mps").get<double>();
    c.road_edge_tolerance_m = p.at("road_edge_tolerance_m").get<double>();
    c.lat_speed_hysteresis_mps = p.at("lat_speed_hysteresis_mps").get<double>();
    c.max_lat_speed_sign_changes_per_merge = p.at("max_lat_speed_sign_changes_per_merge").get<int>();
    c.sideslip_max_rad = p.at("sideslip_max_rad").get<double>();
    c.sideslip_min_speed_mps = p.at("sideslip_min_speed_mps").get<double>();
    c.progress_grace_s = p.at("progress_grace_s").get<double>();
    c.progress_gap_margin_m = p.at("progress_gap_margin_m").get<double>();
    c.progress_leader_braking_mps2 = p.at("progress_leader_braking_mps2").get<double>();
    return c;
  }();
  return params;
}

}  // namespace mg
