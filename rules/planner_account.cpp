#include "rules/planner_account.h"

namespace mg {

std::vector<PlannerClaim> planner_account(const CheckResult& r) {
  std::vector<PlannerClaim> out;
  const nlohmann::json& a = r.trace.planner_annotations;
  if (!a.is_object() || !a.contains("decisions") || !a["decisions"].is_array()) return out;
  for (const nlohmann::json& d : a["decisions"]) {
    if (!d.is_object() || !d.contains("mode") || !d["mode"].is_string()) continue;
    PlannerClaim c;
    c.mode = d["mode"].get<std::string>();
    if (!out.empty() && out.back().mode == c.mode) continue;  // one entry per change of mode
    c.time_s = d.contains("time_s") && d["time_s"].is_number() ? d["time_s"].get<double>() : 0.0;
    if (d.contains("reason") && d["reason"].is_string()) c.reason = d["reason"].get<std::string>();
    bool ego_held = false;
    for (const auto& [from, holder] : r.right_of_way)
      if (from <= c.time_s + 1e-9) ego_held = holder.is_ego();
    c.disagrees = (c.mode == "def1_merge" || c.mode == "def2_merge") && !ego_held;
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace mg
