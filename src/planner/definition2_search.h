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

// A Definition 2 acceptance the ego holds: what its request asked, and until when it binds the
// responder (Def. 2.1 B / 2.2 B: the request's time + rho_c + rho_m).
struct HeldAcceptance {
  int partner_id = -1;
  CoopCase coop_case = CoopCase::kEgoAhead;
  double vo_star_mps = 0.0;
  double d_lon_star_m = 0.0;
  double pc_m = 0.0;  // the request's P_c
  double delivered_time_s = 0.0;
  double yield_by_s = 0.0;     // when the responder is to drive at v_o* (the request's arrival + rho_c)
  double bound_until_s = 0.0;
};
inline constexpr double kHeldAcceptanceTieS = 1e-9;
// When the responder to a request sent at request_time_s is to drive at v_o*, by the plan's
// responder model (coop_candidate): rho_c after the request arrives.
inline double yield_deadline_s(const PlannerSetup& s, double request_time_s) {
  return request_time_s + s.ego.v2v.latency_s + s.params.planner.comm_threshold_s;
}
// How far on the wrong side of the v_o* it accepted (2.1: faster; 2.2: slower) a responder past
// its yield deadline may drive before the ego takes its acceptance as broken.
inline constexpr double kBrokenPromiseMps = 0.5;
// Whether responder o, past a.yield_by_s, drives on the wrong side of v_o* by more than that.
bool responder_breaks_acceptance(const WorldSnapshot& w, const HeldAcceptance& a, const MainLaneVehicle& o);

// A merge on an acceptance still in force after the merge it was given for was aborted (the
// responder, bound to v_o*, refuses a new request meanwhile): a new sigmoid at the ego's speed
// now, its midpoint reached while the responder is still bound, crossing where the request said
// (2.1: at or beyond its P_c; 2.2: at or before it), the responder held to v_o* and the gap's
// other vehicle clear as for the request. Only once the responder is to drive at v_o*, and does
// (responder_breaks_acceptance). nullopt when none exists.
std::optional<Def2Plan> plan_accepted_definition2(const WorldSnapshot& w, const HeldAcceptance& a);

}  // namespace mg
