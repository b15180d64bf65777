#include "fuzz/simulator_faithful.h"

#include <gtest/gtest.h>

#include "fuzz/properties.h"

namespace mg::fuzz {
namespace {

// One main-lane vehicle (id 1, limits a_max 2, b_max 8) and the ego, both with V2V (latency 0.1 s).
Scenario scenario(NonComplianceType nc = NonComplianceType::kNone) {
  Scenario s;
  s.ego.v2v = {true, 0.1, 0.0};
  MainVehicle v;
  v.id = 1;
  v.x_m = 50.0;
  v.behaviour.type = BehaviourType::kCooperative;
  v.v2v = {true, 0.1, 0.0};
  v.noncompliance.type = nc;
  s.vehicles.push_back(v);
  return s;
}

// A judged trace of `s`: `accels` of vehicle 1 at steps 0.02 s apart, the ego idle.
CheckResult judged(const Scenario& s, const std::vector<double>& accels) {
  CheckResult r;
  r.trace.road = s.road;
  r.trace.vehicles = {VehicleDeclaration{0, s.ego.size, s.ego.limits, true},
                      VehicleDeclaration{1, s.vehicles[0].size, s.vehicles[0].limits, true}};
  for (std::size_t k = 0; k < accels.size(); ++k) {
    ObservedState ego;
    ego.y_m = -3.5;
    ObservedState other;
    other.x_m = 50.0 + static_cast<double>(k);
    other.accel_mps2 = accels[k];
    r.trace.steps.push_back({0.02 * static_cast<double>(k), {ego, other}});
  }
  return r;
}

V2vMessage message(MessageType type, int from, int to, double sent_s) {
  return V2vMessage{.type = type, .from_id = from, .to_id = to, .sent_time_s = sent_s};
}

bool has(const std::vector<SimulatorFinding>& f, const std::string& rule) {
  return std::any_of(f.begin(), f.end(), [&](const SimulatorFinding& x) { return x.rule == rule; });
}

TEST(SimulatorFaithful, ACompliantVehicleBeyondItsDeclaredLimitsIsAFinding) {
  const Scenario s = scenario();
  const auto findings = simulator_findings(s, judged(s, {0.0, -8.0, -9.0, 2.0}));
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].rule, kRuleSimDeclaredLimits);
  EXPECT_EQ(findings[0].vehicle_id, 1);
  EXPECT_DOUBLE_EQ(findings[0].time_s, 0.04);
  EXPECT_NEAR(findings[0].margin, -0.95, 1e-12) << "beyond b_max + the judge's 0.05 m/s2 tolerance";
  EXPECT_TRUE(simulator_findings(s, judged(s, {0.0, -8.04, 2.04})).empty()) << "within the tolerance";
}

TEST(SimulatorFaithful, AScriptedBreachOfTheLimitsIsDeclaredAndNoFinding) {
  const Scenario s = scenario(NonComplianceType::kExceedAccel);
  EXPECT_TRUE(simulator_findings(s, judged(s, {0.0, 7.0})).empty());
}

TEST(SimulatorFaithful, ANonFiniteAccelerationIsAFinding) {
  const Scenario s = scenario();
  EXPECT_TRUE(has(simulator_findings(s, judged(s, {0.0, std::nan("")})), kRuleSimDeclaredLimits));
}

TEST(SimulatorFaithful, ADeliveryBeforeOrLongAfterTheSendersLatencyIsAFinding) {
  const Scenario s = scenario();
  for (const auto& [delivered_s, finding] : {std::pair{1.0, true}, std::pair{1.08, true}, std::pair{1.1, false},
                                             std::pair{1.12, false}, std::pair{1.2, true}}) {
    CheckResult r = judged(s, std::vector<double>(200, 0.0));
    const V2vMessage m = message(MessageType::kRequest, 0, 1, 1.0);
    r.trace.channel = {{1.0, ChannelEventKind::kSent, m}, {delivered_s, ChannelEventKind::kDelivered, m}};
    EXPECT_EQ(has(simulator_findings(s, r), kRuleSimV2vLatency), finding) << "delivered at " << delivered_s;
  }
}

TEST(SimulatorFaithful, ALossTheLinkCannotHaveOrAVanishedMessageIsAFinding) {
  Scenario s = scenario();
  CheckResult r = judged(s, std::vector<double>(200, 0.0));
  const V2vMessage m = message(MessageType::kRequest, 0, 1, 1.0);
  r.trace.channel = {{1.0, ChannelEventKind::kSent, m}, {1.0, ChannelEventKind::kLost, m}};
  EXPECT_TRUE(has(simulator_findings(s, r), kRuleSimV2vLoss)) << "loss_prob 0";
  s.ego.v2v.loss_prob = 0.2;
  EXPECT_FALSE(has(simulator_findings(s, r), kRuleSimV2vLoss)) << "a lossy link may lose it";
  r.trace.channel = {{1.0, ChannelEventKind::kSent, m}};
  EXPECT_TRUE(has(simulator_findings(s, r), kRuleSimV2vLoss)) << "neither delivered nor lost";
  r.trace.channel = {{3.9, ChannelEventKind::kSent, message(MessageType::kRequest, 0, 1, 3.9)}};
  EXPECT_FALSE(has(simulator_findings(s, r), kRuleSimV2vLoss)) << "still in flight when the trace ends (3.98 s)";
}

TEST(SimulatorFaithful, AResponderRuleBlamingACompliantResponderIsAFindingUnlessItsLeaderBraked) {
  const Scenario s = scenario();
  CheckResult r = judged(s, std::vector<double>(200, 0.0));
  const V2vMessage accept = message(MessageType::kAccept, 1, 0, 0.2);
  r.trace.channel = {{0.2, ChannelEventKind::kSent, accept}, {0.3, ChannelEventKind::kDelivered, accept}};
  RuleResult broken;
  broken.rule_id = "def2_2b_responder";
  broken.holds = false;
  broken.min_margin = -1.0;
  broken.first_violation_time_s = 2.0;
  broken.liable_id = Party::vehicle(1);
  r.rules = {broken};
  EXPECT_TRUE(has(simulator_findings(s, r), "def2_2b_responder"));
  EXPECT_TRUE(simulator_findings(scenario(NonComplianceType::kRenege), r).empty()) << "a declared renege";

  // A vehicle 2 directly ahead of the responder that brakes after the acceptance held it back.
  Scenario with_leader = s;
  MainVehicle ahead = s.vehicles[0];
  ahead.id = 2;
  with_leader.vehicles.push_back(ahead);
  r.trace.vehicles.push_back({2, ahead.size, ahead.limits, false});
  for (ObservedStep& step : r.trace.steps) {
    ObservedState a = step.vehicles[1];
    a.x_m += 30.0;
    a.accel_mps2 = step.time_s > 1.0 && step.time_s < 1.5 ? -3.0 : 0.0;
    step.vehicles.push_back(a);
  }
  EXPECT_TRUE(simulator_findings(with_leader, r).empty());
}

TEST(SimulatorFaithful, AFindingFailsTheSimulatorFaithfulPropertyOnTheVehicle) {
  const Scenario s = scenario();
  const auto failures = evaluate_properties(s, judged(s, {0.0, 3.0}), std::nullopt);
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].property, property::kSimulatorFaithful);
  EXPECT_EQ(failures[0].rule, kRuleSimDeclaredLimits);
  EXPECT_EQ(failures[0].liable_id, Party::vehicle(1));
}

}  // namespace
}  // namespace mg::fuzz
