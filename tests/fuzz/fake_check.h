// A test-only stand-in for check_scenario (check/checked_run.h) with a planted failure that shrinking can minimise:
// rule "fake_proximity" fails (ego liable) when a main-lane vehicle starts within
// kFakeProximityM of the ego in X. Deterministic; the digest hashes the scenario JSON.
#pragma once

#include <cmath>
#include <functional>
#include <string>

#include "core/scenario.h"
#include "rules/check.h"

namespace mg::test {

inline constexpr double kFakeProximityM = 30.0;

inline CheckResult fake_check(const Scenario& s) {
  CheckResult r;
  r.planner = "fake";
  RuleResult rule;
  rule.rule_id = "fake_proximity";
  rule.unit = "m";
  rule.min_margin = 1e3;
  for (const MainVehicle& v : s.vehicles) rule.min_margin = std::min(rule.min_margin, std::abs(v.x_m - s.ego.x_m) - kFakeProximityM);
  rule.holds = rule.min_margin >= 0.0;
  if (!rule.holds) {
    rule.liable_id = Party::ego();
    rule.first_violation_time_s = 0.0;
  }
  r.holds = rule.holds;
  r.rules.push_back(rule);
  r.trace.source = "fake";
  r.trace_digest = std::hash<std::string>{}(scenario_to_json(s).dump());
  return r;
}

}  // namespace mg::test
