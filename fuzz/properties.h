// The properties of spec §9, evaluated on one checked scenario, and failure signatures.
// A property failure names the rule (or trace-level check) that exposed it and the liable party;
// its signature (planner, property, rule, liable party class) identifies "the same bug" across
// scenarios: one corpus case is kept per signature.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/party.h"
#include "core/scenario.h"
#include "rules/check.h"

namespace mg::fuzz {

namespace property {
inline constexpr const char* kEgoNeverLiable = "ego_never_liable";
inline constexpr const char* kCompliantSafe = "compliant_others_safe";   // no collision, no unanswered unsafe state
inline constexpr const char* kCollisionLiable = "collision_has_liable_party";
inline constexpr const char* kSideLaneEnd = "ego_never_passes_side_lane_end";
inline constexpr const char* kNoOscillation = "no_oscillation";
inline constexpr const char* kDeterminism = "determinism";
inline constexpr const char* kProgress = "progress";
inline constexpr const char* kCheckCompletes = "check_completes";         // the suite itself must not throw
// An exec planner answered every call in time and within the protocol (planner/planner_fault.h);
// its rule is the fault's kind (planner_timeout, planner_exit, planner_reply), its party the ego.
inline constexpr const char* kPlannerResponds = "planner_responds";
// The simulated traffic and channel did what the scenario declares (fuzz/simulator_faithful.h);
// its rule names the check, its party the vehicle concerned (nobody for the channel).
inline constexpr const char* kSimulatorFaithful = "simulator_faithful";
}  // namespace property
const std::vector<std::string>& property_names();

// Checker rules (rules/catalog.json) that the dedicated properties read.
inline constexpr const char* kRuleSideLaneEndMonitor = "side_lane_end";
inline constexpr const char* kRuleProgress = "progress";
inline const std::vector<std::string> kOscillationRules = {"smoothness_oscillation", "sideslip"};
// Trace-level checks that are not rules of the checker get these rule names.
inline constexpr const char* kRuleSideLaneEnd = "trace_side_lane_end";  // independent cross-check of side_lane_end
inline constexpr const char* kRuleDigest = "trace_digest";
inline constexpr const char* kRuleException = "exception";

struct PropertyFailure {
  std::string property;
  std::string rule;
  Party liable_id = Party::nobody();
  double time_s = 0.0;
  double margin = 0.0;       // the rule's robustness margin (< 0), in its unit
  std::string detail;
};

// Properties over one CheckResult. `rerun_digest` is the digest of a second run of the same
// scenario (determinism is evaluated only when it is given).
std::vector<PropertyFailure> evaluate_properties(const Scenario& scenario, const CheckResult& result,
                                                 std::optional<std::uint64_t> rerun_digest);

// Simulates and checks one scenario with one planner (rules/check.h check_scenario, or a test fake).
using CheckFn = std::function<CheckResult(const Scenario&)>;

// One scenario's run: the check result (absent when the check threw) and the failed properties.
struct RunOutcome {
  std::string planner;
  std::optional<CheckResult> result;
  std::vector<PropertyFailure> failures;
};
// Runs `check` (twice when `check_determinism`) and evaluates every property. A PlannerFault
// thrown by the check fails planner_responds; any other exception fails check_completes; neither
// is propagated.
RunOutcome run_properties(const Scenario& scenario, const CheckFn& check, const std::string& planner,
                          bool check_determinism);

// Liable party class: "ego", "vehicle" (vehicle ids change when shrinking renumbers), "none".
std::string party_class(Party liable);

struct Signature {
  std::string planner;
  std::string property;
  std::string rule;
  std::string party;
  auto operator<=>(const Signature&) const = default;
  // "planner/property/rule/party"; file_stem() is the same with "__" and filename-safe.
  std::string key() const;
  std::string file_stem() const;
};
Signature signature_of(const std::string& planner, const PropertyFailure& failure);

}  // namespace mg::fuzz
