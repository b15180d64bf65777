// RapidCheck generators of merge scenarios (spec §9). Ranges: fuzz/scenario_spec.h, documented
// in docs/fuzzing.md. Shrinking goes toward fewer vehicles, simpler behaviours (constant speed
// first, compliant first, no V2V first), round numbers and shorter horizons.
#pragma once

#include <cstdint>

#include <rapidcheck.h>

#include "core/scenario.h"
#include "fuzz/scenario_spec.h"

namespace mg::fuzz {

struct GenConfig {
  int max_vehicles = 6;             // main-lane vehicles, 0..max_vehicles (<= kMaxVehicles)
  bool allow_noncompliance = true;  // false: every vehicle keeps its declared limits and promises
  bool targeted_families = true;    // false: every scenario from the uniform family (scenario_families.h)
};

rc::Gen<LimitsSpec> gen_limits();
rc::Gen<RoadSpec> gen_road();
rc::Gen<EgoSpec> gen_ego();
rc::Gen<ParamsSpec> gen_params();
rc::Gen<VehicleSpec> gen_vehicle(const GenConfig& config);
// Every range of scenario_spec.h drawn independently: the exploration of everything.
rc::Gen<ScenarioSpec> gen_uniform_spec(const GenConfig& config);
// A family (scenario_families.h), then a scenario of it: uniform most of the time, targeted at
// the rarely applying rules otherwise. Shrinks toward the uniform family.
rc::Gen<ScenarioSpec> gen_scenario_spec(const GenConfig& config);
// Every generated scenario passes scenario_from_json(scenario_to_json(s)).
rc::Gen<Scenario> gen_scenario(const GenConfig& config);

// Deterministic generation outside a RapidCheck property: the scenario of run `run_index` of a
// campaign seeded with `campaign_seed`, as a Shrinkable the shrinker can walk. Independent of
// threads, shards and everything else.
std::uint64_t run_seed(std::uint64_t campaign_seed, std::uint64_t run_index);
rc::Shrinkable<Scenario> generate_scenario(std::uint64_t seed, const GenConfig& config);
// The ScenarioSpec behind generate_scenario(seed, config): mapping it through assemble_scenario
// gives the same Shrinkable (guided search perturbs specs, fuzz/guided_search.h).
rc::Shrinkable<ScenarioSpec> generate_spec(std::uint64_t seed, const GenConfig& config);

}  // namespace mg::fuzz
