// The rule catalogue (rules/catalog.json, embedded at build time): per rule its id, paper
// reference, unit, temporal-logic statement and liability logic, plus the monitors' thresholds.
#pragma once

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
};

// Thresholds shared by the monitors ("parameters" of catalog.json).
struct CatalogParams {
  double accel_tolerance_mps2 = 0.0;
  double speed_tolerance_mps = 0.0;
  double yield_speed_tolerance_mps = 0.0;
  double halted_speed_mps = 0.0;
  double road_edge_tolerance_m = 0.0;
  double lat_speed_hysteresis_mps = 0.0;
  int max_lat_speed_sign_changes_per_merge = 0;
  double sideslip_max_rad = 0.0;
  double sideslip_min_speed_mps = 0.0;
  double progress_grace_s = 0.0;
  double progress_gap_margin_m = 0.0;
  double progress_leader_braking_mps2 = 0.0;
};

const nlohmann::json& rule_catalog_json();
const std::vector<RuleSpec>& rule_catalog();       // in catalogue order (= report order)
const RuleSpec& rule_spec(std::string_view id);    // std::logic_error for an unknown id
const CatalogParams& catalog_params();

}  // namespace mg
