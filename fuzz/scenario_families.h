// Scenario families (docs/fuzzing.md "Scenario families"). Uniform draws of every range seldom
// put a V2V partner where Definition 2 applies (3,000 uniform scenarios exercised Def. 2.2 B in
// none), so a campaign mixes targeted families into the uniform one. Every family draws a
// ScenarioSpec inside the ranges of scenario_spec.h and goes through assemble_scenario, so its
// scenarios start RSS-safe and pass the loader like any other.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "fuzz/scenario_gen.h"
#include "fuzz/scenario_spec.h"

namespace mg::fuzz {

enum class ScenarioFamily {
  kUniform,     // every range drawn independently (scenario_gen.h)
  kCoopBehind,  // a V2V partner behind the ego in the target lane, too close for Def. 1: Def. 2.1
  kCoopAhead,   // a V2V partner just ahead of the ego: Def. 2.2
  kFollowerBehind,  // a vehicle behind the ego in the target lane, any behaviour: a Def. 1.1 merge ahead of it
};
std::string to_string(ScenarioFamily f);

// The families and their weights (uniform first, so shrinking walks toward it); only uniform when
// config.targeted_families is false or no vehicle is allowed.
std::vector<std::pair<std::uint64_t, ScenarioFamily>> family_weights(const GenConfig& config);

rc::Gen<ScenarioFamily> gen_family(const GenConfig& config);
rc::Gen<ScenarioSpec> gen_family_spec(ScenarioFamily family, const GenConfig& config);

// How a Definition 2 partner answers (the behaviours the cooperative rules must see).
enum class PartnerKind {
  kCooperative,    // accepts a reachable request and yields
  kNonResponsive,  // never answers
  kReneging,       // accepts and does not yield (non-compliant)
  kOverbraking,    // cooperative, with a burst of braking beyond its declared b_max (non-compliant)
};
rc::Gen<PartnerKind> gen_partner_kind(const GenConfig& config);

}  // namespace mg::fuzz
