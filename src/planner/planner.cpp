#include "planner/planner.h"

#include <algorithm>
#include <cmath>

namespace mg {

std::string to_string(DecisionMode m) {
  switch (m) {
    case DecisionMode::kKeepLane: return "keep_lane";
    case DecisionMode::kDef1Merge: return "def1_merge";
    case DecisionMode::kDef2Request: return "def2_request";
    case DecisionMode::kDef2Merge: return "def2_merge";
    case DecisionMode::kDef1Halt: return "def1_halt";
    case DecisionMode::kProperResponse: return "proper_response";
    case DecisionMode::kMerged: return "merged";
    case DecisionMode::kPotentialField: return "potential_field";
  }
  return "unknown";
}

namespace {
// NaN (not applicable) becomes JSON null.
nlohmann::json number_or_null(double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); }
}  // namespace

nlohmann::json decision_to_json(const Decision& d) {
  nlohmann::json j;
  j["time_s"] = d.time_s;
  j["mode"] = to_string(d.mode);
  if (d.gap)
    j["gap"] = {{"follower_id", d.gap->follower_id < 0 ? nlohmann::json(nullptr) : nlohmann::json(d.gap->follower_id)},
                {"leader_id", d.gap->leader_id < 0 ? nlohmann::json(nullptr) : nlohmann::json(d.gap->leader_id)}};
  else
    j["gap"] = nullptr;
  j["ve_min_mps"] = number_or_null(d.ve_min_mps);
  j["ve_max_mps"] = number_or_null(d.ve_max_mps);
  j["ve_star_mps"] = number_or_null(d.ve_star_mps);
  j["pc_min_m"] = number_or_null(d.pc_min_m);
  j["pc_max_m"] = number_or_null(d.pc_max_m);
  j["pc_m"] = number_or_null(d.pc_m);
  j["kappa_per_m"] = number_or_null(d.kappa_per_m);
  j["merge_duration_s"] = number_or_null(d.merge_duration_s);
  j["coop_partner_id"] = d.coop_partner_id < 0 ? nlohmann::json(nullptr) : nlohmann::json(d.coop_partner_id);
  j["vo_star_mps"] = number_or_null(d.vo_star_mps);
  j["d_lon_star_m"] = number_or_null(d.d_lon_star_m);
  j["reason"] = d.reason;
  if (!d.annotation.is_null()) j["annotation"] = d.annotation;
  return j;
}

WorldSnapshot initial_snapshot(const Scenario& s) {
  WorldSnapshot w;
  w.time_s = 0.0;
  w.ego.x_m = s.ego.x_m;
  w.ego.y_m = s.ego.y_m;
  w.ego.vx_mps = s.ego.speed_mps;
  for (const MainVehicle& v : s.vehicles) {
    ObservedVehicle o;
    o.id = v.id;
    o.state.x_m = v.x_m;
    o.state.y_m = v.lane * s.road.lane_width_m;
    o.state.vx_mps = v.speed_mps;
    o.size = v.size;
    o.limits = v.limits;
    o.v2v_capable = v.v2v.capable;
    w.others.push_back(o);
  }
  std::sort(w.others.begin(), w.others.end(), [](const ObservedVehicle& a, const ObservedVehicle& b) { return a.id < b.id; });
  w.setup = &s;
  return w;
}

}  // namespace mg
