#include "planner/rcpp_decision.h"

#include <cmath>
#include <cstdio>

namespace mg {
namespace {

// NaN (not applicable) becomes JSON null.
nlohmann::json number_or_null(double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); }
nlohmann::json id_or_null(int id) { return id < 0 ? nlohmann::json(nullptr) : nlohmann::json(id); }

std::string num(double v, const char* unit) {
  if (std::isnan(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f %s", v, unit);
  return buf;
}

std::string id_or_open(int id) { return id < 0 ? "open" : std::to_string(id); }

}  // namespace

std::string to_string(DecisionMode m) {
  switch (m) {
    case DecisionMode::kKeepLane: return "keep_lane";
    case DecisionMode::kDef1Merge: return "def1_merge";
    case DecisionMode::kDef2Request: return "def2_request";
    case DecisionMode::kDef2Merge: return "def2_merge";
    case DecisionMode::kDef1Halt: return "def1_halt";
    case DecisionMode::kProperResponse: return "proper_response";
    case DecisionMode::kMerged: return "merged";
  }
  return "unknown";
}

nlohmann::json RcppDecision::to_json() const {
  nlohmann::json j;
  j["gap"] = gap ? nlohmann::json{{"follower_id", id_or_null(gap->follower_id)}, {"leader_id", id_or_null(gap->leader_id)}}
                 : nlohmann::json(nullptr);
  j["ve_min_mps"] = number_or_null(ve_min_mps);
  j["ve_max_mps"] = number_or_null(ve_max_mps);
  j["ve_star_mps"] = number_or_null(ve_star_mps);
  j["pc_min_m"] = number_or_null(pc_min_m);
  j["pc_max_m"] = number_or_null(pc_max_m);
  j["pc_m"] = number_or_null(pc_m);
  j["kappa_per_m"] = number_or_null(kappa_per_m);
  j["merge_duration_s"] = number_or_null(merge_duration_s);
  j["coop_partner_id"] = id_or_null(coop_partner_id);
  j["vo_star_mps"] = number_or_null(vo_star_mps);
  j["d_lon_star_m"] = number_or_null(d_lon_star_m);
  return j;
}

std::vector<std::pair<std::string, std::string>> RcppDecision::describe() const {
  return {
      {"gap", gap ? "follower " + id_or_open(gap->follower_id) + ", leader " + id_or_open(gap->leader_id) : "-"},
      {"v_e* interval", "[" + num(ve_min_mps, "m/s") + ", " + num(ve_max_mps, "m/s") + "]"},
      {"v_e* chosen", num(ve_star_mps, "m/s")},
      {"P_c bounds", "[" + num(pc_min_m, "m") + ", " + num(pc_max_m, "m") + "]"},
      {"P_c chosen", num(pc_m, "m")},
      {"kappa", num(kappa_per_m, "1/m")},
      {"merge duration", num(merge_duration_s, "s")},
      {"cooperation", coop_partner_id < 0 ? std::string("-")
                                          : "vehicle " + std::to_string(coop_partner_id) + ", v_o* " +
                                                num(vo_star_mps, "m/s") + ", D*_lon " + num(d_lon_star_m, "m")},
  };
}

PlanOutput to_command(RcppCycle cycle) {
  PlanOutput out = std::move(static_cast<PlanOutput&>(cycle));
  out.mode = to_string(cycle.decision.mode);
  out.reason = cycle.decision.reason;
  out.annotation = std::make_shared<const RcppDecision>(std::move(cycle.decision));
  return out;
}

const RcppDecision* rcpp_decision(const std::shared_ptr<const PlanAnnotation>& annotation) {
  return dynamic_cast<const RcppDecision*>(annotation.get());
}

}  // namespace mg
