// The properties of spec §9 as CTest property tests for the RCPP planners, with the real
// simulator and checker (the budget comes from RC_PARAMS; the default 100 scenarios per property
// take a few seconds). A failure prints the shrunk scenario as JSON: save it and run
// `mergeguard check` on it, or let `mergeguard fuzz` put it in the corpus.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "check/checked_run.h"
#include "fuzz/properties.h"
#include "fuzz/scenario_gen.h"
#include "rules/check.h"

namespace mg::fuzz {
namespace {

GenConfig ci_config() {
  GenConfig c;
  c.max_vehicles = 4;
  return c;
}

void holds_for_generated_scenarios(const std::string& planner, const std::string& property) {
  const Scenario s = *gen_scenario(ci_config());
  const RunOutcome o = run_properties(
      s, [&](const Scenario& x) { return check_scenario(x, planner); }, planner, property == property::kDeterminism);
  for (const PropertyFailure& f : o.failures)
    if (f.property == property || f.property == property::kCheckCompletes)
      RC_FAIL(signature_of(planner, f).key() + " at t = " + std::to_string(f.time_s) + " s: " + f.detail +
              "\nscenario: " + scenario_to_json(s).dump());
}

RC_GTEST_PROP(RcppProperties, EgoIsNeverLiable, ()) {
  holds_for_generated_scenarios("rcpp", property::kEgoNeverLiable);
}
RC_GTEST_PROP(RcppProperties, CompliantOthersMeanNoCollisionAndNoUnansweredDanger, ()) {
  holds_for_generated_scenarios("rcpp", property::kCompliantSafe);
}
RC_GTEST_PROP(RcppProperties, EveryCollisionHasALiableParty, ()) {
  holds_for_generated_scenarios("rcpp", property::kCollisionLiable);
}
RC_GTEST_PROP(RcppProperties, EgoNeverPassesTheSideLaneEnd, ()) {
  holds_for_generated_scenarios("rcpp", property::kSideLaneEnd);
}
RC_GTEST_PROP(RcppProperties, NoOscillation, ()) { holds_for_generated_scenarios("rcpp", property::kNoOscillation); }
RC_GTEST_PROP(RcppProperties, SameScenarioSameTraceDigest, ()) {
  holds_for_generated_scenarios("rcpp", property::kDeterminism);
}
RC_GTEST_PROP(RcppProperties, NoNeedlessHalt, ()) {
  holds_for_generated_scenarios("rcpp", property::kProgress);
}

RC_GTEST_PROP(RcppCoopProperties, EgoIsNeverLiable, ()) {
  holds_for_generated_scenarios("rcpp-coop", property::kEgoNeverLiable);
}
RC_GTEST_PROP(RcppCoopProperties, CompliantOthersMeanNoCollisionAndNoUnansweredDanger, ()) {
  holds_for_generated_scenarios("rcpp-coop", property::kCompliantSafe);
}
RC_GTEST_PROP(RcppCoopProperties, EveryCollisionHasALiableParty, ()) {
  holds_for_generated_scenarios("rcpp-coop", property::kCollisionLiable);
}
// The simulator keeps the scenario's declarations (fuzz/simulator_faithful.h): its drivers their
// limits and the speeds they accept, its channel the declared latencies and losses. The
// cooperative planner exercises the responders and the channel.
RC_GTEST_PROP(RcppCoopProperties, TheSimulatorKeepsWhatTheScenarioDeclares, ()) {
  holds_for_generated_scenarios("rcpp-coop", property::kSimulatorFaithful);
}

// The baseline is expected to fail (spec §6: it weaves and merges late); determinism and
// completing the check are what it must still satisfy.
RC_GTEST_PROP(TripfieldProperties, SameScenarioSameTraceDigest, ()) {
  holds_for_generated_scenarios("tripfield", property::kDeterminism);
}

}  // namespace
}  // namespace mg::fuzz
