// The simulator under test: what the scenario declares about the main-lane traffic and the V2V
// channel, checked on the simulated trace. The rules judge the vehicles; these checks judge the
// simulator that drives them. A failure here is a fault of the simulator (or of a scenario
// behaviour), never of the planner: a driver the scenario declares compliant broke its declared
// limits or the v_o* it accepted, or the channel delivered a message sooner or later than its
// sender's declared latency, or lost one it could not lose.
#pragma once

#include <string>
#include <vector>

#include "core/scenario.h"
#include "rules/check.h"

namespace mg::fuzz {

// Rule names of the simulator checks (they are not rules of the checker).
inline constexpr const char* kRuleSimDeclaredLimits = "sim_declared_limits";
inline constexpr const char* kRuleSimV2vLatency = "sim_v2v_latency";
inline constexpr const char* kRuleSimV2vLoss = "sim_v2v_loss";
// Rules of the checker whose failure, blamed on a responder the scenario declares compliant,
// means the simulator's cooperative driver did not keep what it accepted.
inline const std::vector<std::string> kAcceptedSpeedRules = {"def2_1b_responder", "def2_2b_responder",
                                                             "def2_positions"};

struct SimulatorFinding {
  std::string rule;
  int vehicle_id = -1;  // the vehicle concerned (a main-lane vehicle), or -1 for the channel
  double time_s = 0.0;
  double margin = 0.0;  // < 0, in the rule's unit (m/s2, s, count)
  std::string detail;
};

// Every way the simulated trace departs from the scenario's declarations (empty: faithful).
// `result` must be the judgement of the trace simulated from `scenario`.
std::vector<SimulatorFinding> simulator_findings(const Scenario& scenario, const CheckResult& result);

}  // namespace mg::fuzz
