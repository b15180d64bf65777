#include "rules/liability.h"

#include <gtest/gtest.h>

#include "rules/check.h"
#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

TEST(RightOfWay, MainLaneHoldsUntilADef1GapIsEstablished) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -80.0, 20.0)};
  Trace t = constant_accel_trace(s, 5.0);
  Decision halt;
  halt.time_s = 0.0;
  halt.mode = DecisionMode::kDef1Halt;
  Decision merge;
  merge.time_s = 1.0;
  merge.mode = DecisionMode::kDef1Merge;
  merge.gap = Gap{1, -1};
  t.decisions = {halt, merge};
  // The ego drifts toward the main lane at 0.8 m/s and is on its centre at t = 4 s: the merge
  // is observed complete there.
  for (TraceStep& st : t.steps) st.ego.y_m = st.time_s < 4.0 ? -3.5 + 0.8 * st.time_s : 0.0;
  const RightOfWay row = compute_right_of_way(s, t);
  ASSERT_EQ(row.timeline.size(), 3u);
  EXPECT_EQ(row.timeline[0], std::make_pair(0.0, kMainLane));
  EXPECT_EQ(row.timeline[1], std::make_pair(1.0, kEgoId));
  EXPECT_EQ(row.timeline[2], std::make_pair(4.0, kNobody));
  EXPECT_FALSE(row.ego_holds_at(0.5));
  EXPECT_TRUE(row.ego_holds_at(2.0));
  EXPECT_FALSE(row.ego_holds_at(4.5));
  EXPECT_FALSE(row.ego_held_within(4.2, 4.5));
  EXPECT_TRUE(row.ego_held_within(3.5, 4.5));
  EXPECT_TRUE(row.ego_held_within(0.0, 1.0));
  EXPECT_FALSE(row.ego_held_within(0.0, 0.9));
}

TEST(RightOfWay, Def2MergeWithoutAcceptanceGivesNoRightOfWay) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -30.0, 20.0)};
  Trace t = constant_accel_trace(s, 2.0);
  Decision d;
  d.time_s = 0.5;
  d.mode = DecisionMode::kDef2Merge;
  d.coop_partner_id = 1;
  t.decisions = {d};
  EXPECT_FALSE(compute_right_of_way(s, t).ego_holds_at(1.0));
}

// Two main-lane vehicles 3 m apart (centres; 4.8 m long): they overlap from t = 0 and nobody
// broke an obligation before (the RSS episode starts at t = 0, the rear's duty only at T).
TEST(Liability, CollisionWithNobodyLiableIsReportedAndFails) {
  Scenario s = base_scenario();
  s.ego.x_m = -500.0;
  s.vehicles = {vehicle(1, 0.0, 20.0), vehicle(2, 3.0, 20.0)};
  const CheckResult r = check_trace(s, constant_accel_trace(s, 0.2));
  EXPECT_FALSE(r.holds);
  EXPECT_TRUE(r.collision);
  EXPECT_EQ(r.collision_liable_id, kNobody);
  EXPECT_EQ(r.liable_id, kNobody);
  EXPECT_NE(r.liability_detail.find("collision with nobody liable"), std::string::npos);
  EXPECT_NE(r.liability_detail.find("already in a dangerous situation at t = 0"), std::string::npos);
}

TEST(Liability, CollisionIsBlamedOnTheRearThatDidNotBrake) {
  // Vehicle 1 closes in on vehicle 2 at 10 m/s relative speed from 30 m without braking:
  // unsafe from t = 0, its duty to brake starts at T = 0.5 s; contact at 30 - 4.8 = 25.2 m
  // closed, t = 2.52 s.
  Scenario s = base_scenario();
  s.ego.x_m = -500.0;
  s.vehicles = {vehicle(1, 0.0, 30.0), vehicle(2, 30.0, 20.0)};
  const CheckResult r = check_trace(s, constant_accel_trace(s, 3.0));
  EXPECT_TRUE(r.collision);
  EXPECT_EQ(r.collision_liable_id, 1);
  EXPECT_EQ(r.liable_id, 1);
  const auto it = std::find_if(r.rules.begin(), r.rules.end(), [](const RuleResult& x) { return x.rule_id == "collision"; });
  ASSERT_NE(it, r.rules.end());
  EXPECT_NEAR(*it->first_violation_time_s, 2.52, 0.021);
}

TEST(Liability, EarliestBrokenObligationIsTheOverallLiableParty) {
  CheckResult r;
  RuleResult a, b;
  a.rule_id = "def1_1_follower";
  a.holds = false;
  a.first_violation_time_s = 1.0;
  a.liable_id = 3;
  b.rule_id = "rss_longitudinal";
  b.holds = false;
  b.first_violation_time_s = 2.0;
  b.liable_id = kEgoId;
  r.rules = {b, a};
  r.holds = false;
  assign_liability(r);
  EXPECT_EQ(r.liable_id, 3);
  EXPECT_FALSE(r.collision);
}

}  // namespace
}  // namespace mg
