// The rule checker's front door (spec §8): judge an observable trace (core/observed_trace.h) by
// every rule monitor and assign liability. It reads the trace's declarations, observed states,
// V2V channel and the rule parameters, never its planner annotations; `rules/` knows nothing of
// planners or the simulator (check/checked_run.h simulates and then calls this).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/observed_trace.h"
#include "core/party.h"

namespace mg {

// One rule's judgement over the whole trace.
struct RuleResult {
  std::string rule_id;          // e.g. "rss_longitudinal", "def1_1", "collision"
  std::string paper_ref;        // e.g. "RCPP eq. (1); RSS Def. 1"
  std::string unit;             // unit of the margin, e.g. "m", "m/s2", "rad"
  bool holds = true;
  double min_margin = 0.0;      // signed robustness: >= 0 holds
  double min_margin_time_s = 0.0;
  std::optional<double> first_violation_time_s;
  Party liable_id = Party::nobody();  // who broke it (when it does not hold)
  double required_value = 0.0;  // at the worst moment: what the rule required ...
  double actual_value = 0.0;    // ... and what the trace had
  std::string detail;           // one line for the report
  // Named figures of the judgement beyond its margin (progress: the feasible gaps the ego let pass
  // and for how long), report.json's "measures".
  std::vector<std::pair<std::string, double>> measures;
};

struct CheckResult {
  std::string planner;
  bool holds = true;            // every rule holds
  std::vector<RuleResult> rules;
  bool collision = false;
  Party collision_liable_id = Party::nobody();  // meaningful when collision
  // Overall liable party: the party whose obligation broke first (spec §8); nobody when
  // every rule holds, or when a collision has nobody liable (see liability_detail).
  Party liable_id = Party::nobody();
  std::string liability_detail;       // one line: which rule, when, why
  // Right-of-way holder over time: (time_s, party) at every change; the main lane holds it
  // as a whole until a merge claims it.
  std::vector<std::pair<double, Party>> right_of_way;
  std::vector<std::string> right_of_way_observations;  // one line per merge attempt (merge_attempts.h)
  std::vector<double> merge_phase_times_s;            // the observed merge phases (merge_phases.h)
  RuleParams rule_params;                             // what the trace was judged with
  ObservedTrace trace;
  std::uint64_t trace_digest = 0;     // trace_digest(trace)
};

// Which of the catalogue's rules a judgement applies (rules/catalog.json, "kind"). An audit of a
// recording applies the safety rules only (docs/audit.md): a liveness rule's result then holds,
// is not applicable, and says why.
enum class RuleSet { kAll, kSafety };

// Judges a trace with its own rule parameters (trace.params), or with `rules` when given
// (`--params`). The rvalue overload takes the trace without a copy.
CheckResult check_observed(ObservedTrace&& trace, const std::optional<RuleParams>& rules = std::nullopt,
                           RuleSet applied = RuleSet::kAll);
CheckResult check_observed(const ObservedTrace& trace, const std::optional<RuleParams>& rules = std::nullopt,
                           RuleSet applied = RuleSet::kAll);

nlohmann::json check_result_to_json(const CheckResult& r);
// The parameters a result was judged with: {"rules": RuleParams, "rss": RssParams}.
nlohmann::json judged_with_json(const CheckResult& r);

}  // namespace mg
