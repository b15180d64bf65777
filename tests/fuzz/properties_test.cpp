#include "fuzz/properties.h"

#include <gtest/gtest.h>

#include "planner/planner_fault.h"

namespace mg::fuzz {
namespace {

Scenario one_vehicle_scenario(NonComplianceType nc = NonComplianceType::kNone) {
  Scenario s;
  MainVehicle v;
  v.x_m = 50.0;
  v.noncompliance.type = nc;
  s.vehicles.push_back(v);
  return s;
}

RuleResult failing(const std::string& id, Party liable) {
  RuleResult r;
  r.rule_id = id;
  r.holds = false;
  r.min_margin = -1.5;
  r.first_violation_time_s = 2.0;
  r.liable_id = liable;
  return r;
}

CheckResult result_with(std::vector<RuleResult> rules) {
  CheckResult r;
  r.planner = "rcpp";
  r.rules = std::move(rules);
  r.holds = std::all_of(r.rules.begin(), r.rules.end(), [](const RuleResult& x) { return x.holds; });
  return r;
}

bool fails(const std::vector<PropertyFailure>& failures, const std::string& property, const std::string& rule) {
  return std::any_of(failures.begin(), failures.end(),
                     [&](const PropertyFailure& f) { return f.property == property && f.rule == rule; });
}

TEST(Properties, EgoLiableForAnyRuleFailsEgoNeverLiable) {
  const auto f = evaluate_properties(one_vehicle_scenario(), result_with({failing("def1_1_gap", Party::ego())}), std::nullopt);
  EXPECT_TRUE(fails(f, property::kEgoNeverLiable, "def1_1_gap"));
}

TEST(Properties, VehicleLiableDoesNotFailEgoNeverLiable) {
  const auto f = evaluate_properties(one_vehicle_scenario(), result_with({failing("def1_2_leader", Party::vehicle(1))}), std::nullopt);
  EXPECT_FALSE(fails(f, property::kEgoNeverLiable, "def1_2_leader"));
}

TEST(Properties, UnansweredRssDangerWithCompliantOthersFails) {
  const auto f = evaluate_properties(one_vehicle_scenario(), result_with({failing("rss_longitudinal", Party::ego())}), std::nullopt);
  EXPECT_TRUE(fails(f, property::kCompliantSafe, "rss_longitudinal"));
}

TEST(Properties, AVehicleBlamedForRssDangerWasNotCompliant) {
  const auto f = evaluate_properties(one_vehicle_scenario(), result_with({failing("rss_longitudinal", Party::vehicle(1))}), std::nullopt);
  EXPECT_FALSE(fails(f, property::kCompliantSafe, "rss_longitudinal"));
}

TEST(Properties, NonCompliantOthersExcuseRssDanger) {
  const auto f = evaluate_properties(one_vehicle_scenario(NonComplianceType::kExceedBrake),
                                     result_with({failing("rss_longitudinal", Party::vehicle(1))}), std::nullopt);
  EXPECT_FALSE(fails(f, property::kCompliantSafe, "rss_longitudinal"));
}

TEST(Properties, CollisionWithNobodyLiableFails) {
  CheckResult r = result_with({failing("collision", Party::nobody())});
  r.collision = true;
  r.collision_liable_id = Party::nobody();
  const auto f = evaluate_properties(one_vehicle_scenario(NonComplianceType::kExceedAccel), r, std::nullopt);
  EXPECT_TRUE(fails(f, property::kCollisionLiable, "collision"));
  EXPECT_FALSE(fails(f, property::kCompliantSafe, "collision"));  // the vehicle was non-compliant
}

TEST(Properties, CollisionBlamedOnTheEgoFailsWithCompliantOthers) {
  CheckResult r = result_with({failing("collision", Party::ego())});
  r.collision = true;
  r.collision_liable_id = Party::ego();
  const auto f = evaluate_properties(one_vehicle_scenario(), r, std::nullopt);
  EXPECT_FALSE(fails(f, property::kCollisionLiable, "collision"));
  EXPECT_TRUE(fails(f, property::kCompliantSafe, "collision"));
  EXPECT_TRUE(fails(f, property::kEgoNeverLiable, "collision"));
}

TEST(Properties, SideLaneEndIsCrossCheckedOnTheTrace) {
  Scenario s = one_vehicle_scenario();
  CheckResult r = result_with({});
  ObservedStep step;
  step.time_s = 4.0;
  step.vehicles.resize(1 + s.vehicles.size());
  step.vehicles[0].x_m = s.road.side_lane_end_x_m;  // front 2.4 m past the end, centre in the side lane
  step.vehicles[0].y_m = -s.road.lane_width_m;
  r.trace.steps.push_back(step);
  const auto f = evaluate_properties(s, r, std::nullopt);
  ASSERT_TRUE(fails(f, property::kSideLaneEnd, kRuleSideLaneEnd));
  EXPECT_NEAR(f.front().margin, -s.ego.size.length_m / 2.0, 1e-9);
  r.trace.steps.front().vehicles[0].y_m = 0.0;  // merged: the side lane's end no longer matters
  EXPECT_TRUE(evaluate_properties(s, r, std::nullopt).empty());
}

TEST(Properties, OscillationAndProgressRulesMapToTheirProperties) {
  const auto f = evaluate_properties(
      one_vehicle_scenario(), result_with({failing("smoothness_oscillation", Party::ego()), failing("progress", Party::ego())}),
      std::nullopt);
  EXPECT_TRUE(fails(f, property::kNoOscillation, "smoothness_oscillation"));
  EXPECT_TRUE(fails(f, property::kProgress, "progress"));
}

TEST(Properties, DifferentRerunDigestFailsDeterminism) {
  CheckResult r = result_with({});
  r.trace_digest = 42;
  EXPECT_TRUE(evaluate_properties(one_vehicle_scenario(), r, 42).empty());
  EXPECT_TRUE(fails(evaluate_properties(one_vehicle_scenario(), r, 43), property::kDeterminism, kRuleDigest));
}

TEST(Properties, AThrowingCheckIsAFailureNotACrash) {
  const RunOutcome o = run_properties(
      one_vehicle_scenario(), [](const Scenario&) -> CheckResult { throw std::runtime_error("boom"); }, "rcpp", true);
  EXPECT_FALSE(o.result);
  ASSERT_EQ(o.failures.size(), 1u);
  EXPECT_EQ(o.failures[0].property, property::kCheckCompletes);
  EXPECT_EQ(o.failures[0].detail, "boom");
}

TEST(Properties, AMisbehavingPlannerFailsPlannerRespondsWithTheFaultAsItsRule) {
  const RunOutcome o = run_properties(
      one_vehicle_scenario(),
      [](const Scenario&) -> CheckResult { throw PlannerFault(kFaultTimeout, 1.5, "planner process 'exec:x' (pid 7) did not answer"); },
      "exec:x", true);
  EXPECT_FALSE(o.result);
  ASSERT_EQ(o.failures.size(), 1u);
  EXPECT_EQ(o.failures[0].property, property::kPlannerResponds);
  EXPECT_EQ(o.failures[0].rule, kFaultTimeout);
  EXPECT_EQ(o.failures[0].liable_id, Party::ego());
  EXPECT_EQ(o.failures[0].time_s, 1.5);
  EXPECT_EQ(signature_of(o.planner, o.failures[0]).key(), "exec:x/planner_responds/planner_timeout/ego");
}

TEST(Properties, SignatureUsesThePartyClassNotTheVehicleId) {
  PropertyFailure a{property::kEgoNeverLiable, "r", Party::vehicle(3), 0, 0, ""};
  PropertyFailure b{property::kEgoNeverLiable, "r", Party::vehicle(1), 0, 0, ""};
  EXPECT_EQ(signature_of("rcpp", a), signature_of("rcpp", b));
  EXPECT_EQ(signature_of("rcpp", a).party, "vehicle");
  EXPECT_EQ(signature_of("rcpp", a).file_stem(), "rcpp__ego_never_liable__r__vehicle");
}

}  // namespace
}  // namespace mg::fuzz
