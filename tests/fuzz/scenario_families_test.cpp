#include "fuzz/scenario_families.h"

#include <cmath>
#include <map>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "fake_check.h"
#include "fuzz/scenario_gen.h"
#include "fuzz/shrink.h"

namespace mg::fuzz {
namespace {

// The vehicle a shaped family puts first in the target lane: the rearmost of lane 0.
const MainVehicle* rearmost_in_target_lane(const Scenario& s) {
  const MainVehicle* first = nullptr;
  for (const MainVehicle& m : s.vehicles)
    if (m.lane == 0 && (!first || m.x_m < first->x_m)) first = &m;
  return first;
}

// Sketch (partner behind, Def. 2.1):   lane 0:  [o] ---- offset in [-40, -2] m ---->
//                                      side:          [ego] ==> merge ahead of o
void check_partner(const Scenario& s, const RealRange& offset) {
  const MainVehicle* o = rearmost_in_target_lane(s);
  RC_ASSERT(o != nullptr);
  RC_ASSERT(o->id == 1);
  RC_ASSERT(o->v2v.capable);
  RC_ASSERT(s.ego.v2v.capable);
  const double dx_m = o->x_m - s.ego.x_m;
  RC_ASSERT(dx_m >= offset.lo - 0.05);
  RC_ASSERT(dx_m <= offset.hi + 0.05);
  RC_ASSERT(s.params.planner.merge_duration_s >= range::kCoopMergeDuration.lo);
  RC_ASSERT(s.params.planner.merge_duration_s <= range::kCoopMergeDuration.hi);
  RC_ASSERT(s.params.planner.comm_threshold_s >= range::kCoopCommThreshold.lo);
  RC_ASSERT(s.params.sim.horizon_s >= range::kFamilyHorizon.lo);
  RC_ASSERT(s.vehicles.size() <= 4u);
}

RC_GTEST_PROP(ScenarioFamilies, APartnerBehindIsAV2vVehicleFirstInTheTargetLaneBehindTheEgo, ()) {
  const Scenario s = assemble_scenario(*gen_family_spec(ScenarioFamily::kCoopBehind, GenConfig{}));
  check_partner(s, range::kCoopBehindOffset);
}

RC_GTEST_PROP(ScenarioFamilies, APartnerAheadIsAV2vVehicleFirstInTheTargetLaneBesideTheEgo, ()) {
  const Scenario s = assemble_scenario(*gen_family_spec(ScenarioFamily::kCoopAhead, GenConfig{}));
  check_partner(s, range::kCoopAheadOffset);
}

RC_GTEST_PROP(ScenarioFamilies, TheFollowerFamilyPutsAVehicleBehindTheEgoInTheTargetLane, ()) {
  const Scenario s = assemble_scenario(*gen_family_spec(ScenarioFamily::kFollowerBehind, GenConfig{}));
  const MainVehicle* f = rearmost_in_target_lane(s);
  RC_ASSERT(f != nullptr);
  const double dx_m = f->x_m - s.ego.x_m;
  RC_ASSERT(dx_m >= range::kFollowerOffset.lo - 0.05);
  RC_ASSERT(dx_m <= range::kFollowerOffset.hi + 0.05);
}

RC_GTEST_PROP(ScenarioFamilies, ACompliantConfigGivesCompliantPartners, ()) {
  GenConfig config;
  config.allow_noncompliance = false;
  const Scenario s = assemble_scenario(*gen_family_spec(ScenarioFamily::kCoopAhead, config));
  for (const MainVehicle& m : s.vehicles) RC_ASSERT(m.noncompliance.type == NonComplianceType::kNone);
}

TEST(ScenarioFamilies, PartnersAnswerInEveryWayTheCooperativeRulesMustSee) {
  std::map<PartnerKind, int> seen;
  for (std::uint64_t i = 0; i < 200; ++i) {
    const auto kind = gen_partner_kind(GenConfig{})(rc::Random(run_seed(5, i)), rc::kNominalSize).value();
    ++seen[kind];
  }
  EXPECT_EQ(seen.size(), 4u);  // cooperative, non-responsive, reneging, over-braking
  // And in the scenarios: a reneging partner accepts from t = 0, an over-braking one brakes
  // beyond its declared b_max.
  bool renege = false, overbrake = false, lossy = false;
  for (std::uint64_t i = 0; i < 300; ++i) {
    const Scenario s = assemble_scenario(
        gen_family_spec(ScenarioFamily::kCoopBehind, GenConfig{})(rc::Random(run_seed(6, i)), rc::kNominalSize).value());
    const MainVehicle& o = *rearmost_in_target_lane(s);
    renege = renege || (o.noncompliance.type == NonComplianceType::kRenege && o.noncompliance.start_time_s == 0.0);
    overbrake = overbrake || (o.noncompliance.type == NonComplianceType::kExceedBrake &&
                              o.noncompliance.accel_mps2 > o.limits.brake_max_mps2);
    lossy = lossy || o.v2v.loss_prob > 0.0;
  }
  EXPECT_TRUE(renege);
  EXPECT_TRUE(overbrake);
  EXPECT_TRUE(lossy);
}

// A failure found in a family shrinks within it: the vehicles it does not need go, the partner
// stays (cooperative, V2V-capable), and its offset goes to the family's nominal value when the
// failure allows. Planted failure: a vehicle within 30 m of the ego (fake_check.h).
TEST(ScenarioFamilies, AFamilyFailureShrinksWithinTheFamily) {
  const auto planted = [](const Scenario& s) { return !test::fake_check(s).holds; };
  const auto gen = rc::gen::map(gen_family_spec(ScenarioFamily::kCoopBehind, GenConfig{}), assemble_scenario);
  for (std::uint64_t i = 0;; ++i) {
    const rc::Shrinkable<Scenario> g = gen(rc::Random(run_seed(4, i)), rc::kNominalSize);
    if (g.value().vehicles.size() < 3 || !planted(g.value())) continue;
    const ShrinkOutcome out = shrink_scenario(g, planted, {});
    ASSERT_TRUE(planted(out.scenario));
    ASSERT_EQ(out.scenario.vehicles.size(), 1u);
    const MainVehicle& o = out.scenario.vehicles[0];
    EXPECT_TRUE(o.v2v.capable);
    EXPECT_EQ(o.behaviour.type, BehaviourType::kCooperative);
    EXPECT_EQ(o.noncompliance.type, NonComplianceType::kNone);
    EXPECT_EQ(o.x_m - out.scenario.ego.x_m, range::kCoopBehindOffset.nominal);
    EXPECT_EQ(out.scenario.ego.speed_mps, range::kCoopEgoSpeed.nominal);
    return;
  }
}

TEST(ScenarioFamilies, MixedGenerationDrawsEveryFamilyAndUniformOnlyWhenAsked) {
  const auto weights = family_weights(GenConfig{});
  EXPECT_EQ(weights.front().second, ScenarioFamily::kUniform);  // shrinking walks toward it
  EXPECT_EQ(weights.size(), 4u);
  GenConfig uniform;
  uniform.targeted_families = false;
  EXPECT_EQ(family_weights(uniform).size(), 1u);
  GenConfig empty_road;
  empty_road.max_vehicles = 0;
  EXPECT_EQ(family_weights(empty_road).size(), 1u);
  // Uniform only is exactly the uniform generator, draw for draw (campaigns before the families).
  for (std::uint64_t i = 0; i < 30; ++i) {
    const rc::Random r(run_seed(9, i));
    EXPECT_EQ(assemble_scenario(gen_scenario_spec(uniform)(r, rc::kNominalSize).value()),
              assemble_scenario(gen_uniform_spec(uniform)(r, rc::kNominalSize).value()));
  }
}

}  // namespace
}  // namespace mg::fuzz
