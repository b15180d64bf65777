#include "fuzz/properties.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "fuzz/simulator_faithful.h"
#include "planner/planner_fault.h"

namespace mg::fuzz {
namespace {

bool all_compliant(const Scenario& s) {
  return std::all_of(s.vehicles.begin(), s.vehicles.end(),
                     [](const MainVehicle& v) { return v.noncompliance.type == NonComplianceType::kNone; });
}

PropertyFailure from_rule(const char* property, const RuleResult& r) {
  return {property, r.rule_id, r.liable_id, r.first_violation_time_s.value_or(r.min_margin_time_s), r.min_margin,
          r.detail};
}

bool has_rule(const CheckResult& result, const std::string& id) {
  return std::any_of(result.rules.begin(), result.rules.end(), [&](const RuleResult& r) { return r.rule_id == id; });
}

PropertyFailure collision_failure(const char* property, const CheckResult& result) {
  for (const RuleResult& r : result.rules)
    if (r.rule_id == "collision" && !r.holds) return from_rule(property, r);
  return {property, "collision", result.collision_liable_id, 0.0, -1.0, "collision"};
}

void ego_never_liable(const CheckResult& result, std::vector<PropertyFailure>& out) {
  for (const RuleResult& r : result.rules)
    if (!r.holds && r.liable_id == Party::ego()) out.push_back(from_rule(property::kEgoNeverLiable, r));
  if (result.collision && result.collision_liable_id == Party::ego() && !has_rule(result, "collision"))
    out.push_back(collision_failure(property::kEgoNeverLiable, result));
}

// With compliant others the ego must avoid collisions and every unsafe RSS state must be answered
// by a proper response (the rss_* monitors hold exactly then). A violation blamed on a main-lane
// vehicle means that vehicle did not comply (it did not brake at least b_min once unsafe, RSS),
// so only the ego's and nobody's count here.
void compliant_safe(const Scenario& s, const CheckResult& result, std::vector<PropertyFailure>& out) {
  if (!all_compliant(s)) return;
  auto others_comply = [](Party liable) { return liable.is_ego() || liable.is_nobody(); };
  if (result.collision && others_comply(result.collision_liable_id))
    out.push_back(collision_failure(property::kCompliantSafe, result));
  for (const RuleResult& r : result.rules)
    if (!r.holds && r.rule_id.rfind("rss_", 0) == 0 && others_comply(r.liable_id))
      out.push_back(from_rule(property::kCompliantSafe, r));
}

void collision_liable(const CheckResult& result, std::vector<PropertyFailure>& out) {
  if (result.collision && result.collision_liable_id == Party::nobody())
    out.push_back(collision_failure(property::kCollisionLiable, result));
}

void failed_rules(const char* property, const std::vector<std::string>& rule_ids, const CheckResult& result,
                  std::vector<PropertyFailure>& out) {
  for (const RuleResult& r : result.rules)
    if (!r.holds && std::find(rule_ids.begin(), rule_ids.end(), r.rule_id) != rule_ids.end())
      out.push_back(from_rule(property, r));
}

// The side_lane_end monitor, cross-checked on the trace: the ego's front must not pass
// side_lane_end_x while its centre is still in the side lane.
void side_lane_end(const Scenario& s, const CheckResult& result, std::vector<PropertyFailure>& out) {
  failed_rules(property::kSideLaneEnd, {kRuleSideLaneEndMonitor}, result, out);
  const double boundary_y = -s.road.lane_width_m / 2.0;
  for (const ObservedStep& step : result.trace.steps) {
    const ObservedState& ego = step.vehicles[0];
    if (ego.y_m >= boundary_y) continue;
    const double margin_m = s.road.side_lane_end_x_m - (ego.x_m + s.ego.size.length_m / 2.0);
    if (margin_m < 0.0) {
      out.push_back({property::kSideLaneEnd, kRuleSideLaneEnd, Party::ego(), step.time_s, margin_m,
                     "ego front passed the side lane end while its centre was in the side lane"});
      return;
    }
  }
}

}  // namespace

const std::vector<std::string>& property_names() {
  static const std::vector<std::string> names{property::kEgoNeverLiable, property::kCompliantSafe,
                                              property::kCollisionLiable, property::kSideLaneEnd,
                                              property::kNoOscillation,  property::kDeterminism,
                                              property::kProgress,       property::kCheckCompletes,
                                              property::kPlannerResponds, property::kSimulatorFaithful};
  return names;
}

std::vector<PropertyFailure> evaluate_properties(const Scenario& scenario, const CheckResult& result,
                                                 std::optional<std::uint64_t> rerun_digest) {
  std::vector<PropertyFailure> out;
  ego_never_liable(result, out);
  compliant_safe(scenario, result, out);
  collision_liable(result, out);
  side_lane_end(scenario, result, out);
  failed_rules(property::kNoOscillation, kOscillationRules, result, out);
  if (rerun_digest && *rerun_digest != result.trace_digest)
    out.push_back({property::kDeterminism, kRuleDigest, Party::nobody(), 0.0, -1.0, "a second run gave another trace digest"});
  failed_rules(property::kProgress, {kRuleProgress}, result, out);
  for (const SimulatorFinding& f : simulator_findings(scenario, result))
    out.push_back({property::kSimulatorFaithful, f.rule,
                   f.vehicle_id >= 1 ? Party::vehicle(f.vehicle_id) : Party::nobody(), f.time_s, f.margin, f.detail});
  return out;
}

RunOutcome run_properties(const Scenario& scenario, const CheckFn& check, const std::string& planner,
                          bool check_determinism) {
  RunOutcome outcome;
  outcome.planner = planner;
  try {
    outcome.result = check(scenario);
    std::optional<std::uint64_t> rerun;
    if (check_determinism) rerun = check(scenario).trace_digest;
    outcome.failures = evaluate_properties(scenario, *outcome.result, rerun);
  } catch (const PlannerFault& fault) {
    outcome.result.reset();
    outcome.failures = {{property::kPlannerResponds, fault.kind, Party::ego(), fault.time_s, -1.0, fault.what()}};
  } catch (const std::exception& e) {
    outcome.result.reset();
    outcome.failures = {{property::kCheckCompletes, kRuleException, Party::nobody(), 0.0, -1.0, e.what()}};
  }
  return outcome;
}

std::string party_class(Party liable) {
  if (liable.is_ego()) return "ego";
  if (liable.is_nobody()) return "none";
  return "vehicle";
}

std::string Signature::key() const { return planner + "/" + property + "/" + rule + "/" + party; }

std::string Signature::file_stem() const {
  std::string stem = planner + "__" + property + "__" + rule + "__" + party;
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '-';
  return stem;
}

Signature signature_of(const std::string& planner, const PropertyFailure& failure) {
  return {planner, failure.property, failure.rule, party_class(failure.liable_id)};
}

}  // namespace mg::fuzz
