// The rule checker's front door (spec §8): simulate a scenario with a planner, run every rule
// monitor over the trace, assign liability. Used by `mergeguard check`, the fuzzer and replay.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scenario.h"
#include "sim/trace.h"

namespace mg {

// Liable party: kNobody, kEgoId (the ego) or a main-lane vehicle id (>= 1).
inline constexpr int kNobody = -1;
inline constexpr int kEgoId = 0;
inline constexpr int kMainLane = -2;  // right-of-way holder: the main-lane traffic as a whole
std::string party_name(int party_id);  // "none", "ego", "vehicle 3", "main lane"

// One rule's judgement over the whole trace.
struct RuleResult {
  std::string rule_id;          // e.g. "rss_longitudinal", "def1_1", "collision"
  std::string paper_ref;        // e.g. "RCPP eq. (1); RSS Def. 1"
  std::string unit;             // unit of the margin, e.g. "m", "m/s2", "rad"
  bool holds = true;
  double min_margin = 0.0;      // signed robustness: >= 0 holds
  double min_margin_time_s = 0.0;
  std::optional<double> first_violation_time_s;
  int liable_id = kNobody;      // who broke it (when it does not hold)
  double required_value = 0.0;  // at the worst moment: what the rule required ...
  double actual_value = 0.0;    // ... and what the trace had
  std::string detail;           // one line for the report
};

struct CheckResult {
  std::string planner;
  bool holds = true;            // every rule holds
  std::vector<RuleResult> rules;
  bool collision = false;
  int collision_liable_id = kNobody;  // meaningful when collision
  // Overall liable party: the party whose obligation broke first (spec §8); kNobody when
  // every rule holds, or when a collision has nobody liable (see liability_detail).
  int liable_id = kNobody;
  std::string liability_detail;       // one line: which rule, when, why
  // Right-of-way holder over time: (time_s, party id) at every change.
  std::vector<std::pair<double, int>> right_of_way;
  Trace trace;
};

// Runs the simulation and all monitors. Never throws for a valid scenario; an unknown planner
// name raises std::invalid_argument.
CheckResult check_scenario(const Scenario& scenario, const std::string& planner_name);
// Runs all monitors over an existing trace (the rvalue overload takes the trace without a copy).
CheckResult check_trace(const Scenario& scenario, const Trace& trace);
CheckResult check_trace(const Scenario& scenario, Trace&& trace);

nlohmann::json check_result_to_json(const CheckResult& r);

}  // namespace mg
