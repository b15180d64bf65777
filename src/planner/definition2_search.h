// RCPP's Definition 2 stage (RCPP §II-B, spec §5): when no Definition 1 gap exists, the V2V
// neighbour to ask for v_o*, the case (ego ahead, 2.1; ego behind, 2.2) and the sigmoid the
// request commits to. "Nobody to ask" is a normal outcome (nullopt).
#pragma once

#include <map>
#include <optional>

#include "planner/definition1.h"
#include "planner/definition2.h"
#include "planner/rcpp_decision.h"
#include "planner/sigmoid.h"

namespace mg {

// Definition 2 request at one decision instant.
struct Def2Plan {
  RcppDecision decision;  // mode kDef2Request, partner, v_o*, D*_lon, P_c bounds/choice, kappa
  Sigmoid sigmoid;
  VoStar vo;
  MainLaneVehicle partner;
  double ego_speed_after_mps = 0.0;  // the ego's speed during and after the exchange
};

// The cheapest request over the V2V-capable target-lane vehicles, skipping a partner before its
// time in `retry_after_s` (partner id -> earliest time of a new request).
std::optional<Def2Plan> plan_definition2(const WorldSnapshot& w, const std::map<int, double>& retry_after_s);

}  // namespace mg
