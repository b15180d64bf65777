#include "rules/liability.h"

#include <algorithm>
#include <utility>

#include <gtest/gtest.h>

#include "rules/check.h"
#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

// The right of way of a run, as rules/check.cpp computes it from the observable trace.
RightOfWay right_of_way(const Scenario& s, const Trace& t) { return test::judge(s, t)->row; }

// Vehicle 1 starts 10.05 m behind the ego at 15 m/s, the ego at 20 m/s (speed limit 22 m/s): the
// gap ahead of vehicle 1 opens by 5 m/s. Ineq. (1.1) at the best v_e* = 22 m/s: LHS = X_o + 15*2
// + 2*4^2/8 = X_o + 34, D_lon(19 behind 22) = 4.8 + 9.5 + 0.25 + 20^2/8 - 22^2/16 = 34.3 m,
// RHS = X + 44 - 34.3: it holds once X - X_o >= 24.3 m in the paper's model; the bounded-rate ego
// (20 -> 22 m/s at 2 m/s2) is 1 m further back at rho/2, and both must hold: X - X_o >= 25.3 m,
// from t = 3.05 s (first step 3.06 s).
// (Behind vehicle 1 there is no gap: it is slower than the ego and starts too close for (1.2).)
// The ego is seen to move toward the main lane from t = 3 s at 1 m/s (start 3.1 s, midpoint
// 4.75 s, on the main-lane centre from 6.3 s); the gap has stayed feasible since 3.06 s.
//
//   t = 0      [1]--10 m--[ego]          t = 3.06 s   [1]------25.3 m------[ego]  Def. 1 holds
TEST(RightOfWay, MainLaneHoldsUntilADef1GapIsEstablished) {
  Scenario s = base_scenario();
  s.road.speed_limit_mps = 22.0;
  s.vehicles = {vehicle(1, -10.05, 15.0)};
  const Trace t = test::with_lateral_move(constant_accel_trace(s, 7.0), 3.0, 1.0);
  const RightOfWay row = right_of_way(s, t);
  ASSERT_EQ(row.timeline.size(), 3u);
  EXPECT_EQ(row.timeline[0], std::make_pair(0.0, Party::main_lane()));
  EXPECT_EQ(row.timeline[1].second, Party::ego());
  EXPECT_NEAR(row.timeline[1].first, 3.06, 1e-9);
  EXPECT_EQ(row.timeline[2].second, Party::nobody());
  EXPECT_NEAR(row.timeline[2].first, 6.3, 0.021);
  EXPECT_FALSE(row.ego_holds_at(3.0));
  EXPECT_TRUE(row.ego_holds_at(3.1));
  EXPECT_FALSE(row.ego_holds_at(6.5));
  EXPECT_FALSE(row.ego_held_within(6.4, 6.6));
  EXPECT_TRUE(row.ego_held_within(6.0, 6.6));
  EXPECT_TRUE(row.ego_held_within(0.0, 3.1));
  EXPECT_FALSE(row.ego_held_within(0.0, 3.0));
}

TEST(RightOfWay, TheEgoThatNeverMovesTowardTheMainLaneNeverHoldsIt) {
  // The same traffic, the ego staying in its lane: an open gap alone grants nothing.
  Scenario s = base_scenario();
  s.road.speed_limit_mps = 22.0;
  s.vehicles = {vehicle(1, -10.05, 15.0)};
  const RightOfWay row = right_of_way(s, constant_accel_trace(s, 7.0));
  EXPECT_TRUE(row.ego_holds.empty());
  ASSERT_EQ(row.timeline.size(), 1u);
  EXPECT_EQ(row.timeline[0], std::make_pair(0.0, Party::main_lane()));
}

// Vehicle 1 45 m behind the ego, both 20 m/s, speed limit 22 m/s: Definition 1 fails (ahead of it
// ineq. (1.1) needs 64.925 m, behind it (1.2) at v_e* = 0 fails by -45 + 40 - 4.8 = -9.8 m). The ego requests a Def. 2 merge at t = 0 and moves over from t = 0.5 s.
TEST(RightOfWay, Def2MergeWithoutAcceptanceGivesNoRightOfWay) {
  Scenario s = base_scenario();
  s.road.speed_limit_mps = 22.0;
  s.vehicles = {vehicle(1, -45.0, 20.0)};
  // P_c = 30 m: where the ego's centre crosses the lane line (1.5 s at 20 m/s).
  Trace t = test::with_lateral_move(constant_accel_trace(s, 2.0), 0.5, 1.75);
  t.events.push_back(test::message_event(0.0, MessageType::kRequest, 0, 1, CoopCase::kEgoAhead, 30, 30, 18));
  EXPECT_FALSE(right_of_way(s, t).ego_holds_at(1.0));
  // The same merge with vehicle 1's acceptance delivered at 0.3 s (within rho_c = 1 s): Def. 2.
  const TraceEvent accept = test::message_event(0.1, MessageType::kAccept, 1, 0, CoopCase::kEgoAhead, 30, 30, 18);
  t.events.push_back(accept);
  t.events.push_back(test::delivered_event(accept, 0.3));
  const RightOfWay row = right_of_way(s, t);
  EXPECT_TRUE(row.ego_holds_at(1.0));
  EXPECT_FALSE(row.ego_holds_at(0.2));
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
  EXPECT_EQ(r.collision_liable_id, Party::nobody());
  EXPECT_EQ(r.liable_id, Party::nobody());
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
  EXPECT_EQ(r.collision_liable_id, Party::vehicle(1));
  EXPECT_EQ(r.liable_id, Party::vehicle(1));
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
  a.liable_id = Party::vehicle(3);
  b.rule_id = "rss_longitudinal";
  b.holds = false;
  b.first_violation_time_s = 2.0;
  b.liable_id = Party::ego();
  r.rules = {b, a};
  r.holds = false;
  assign_liability(r);
  EXPECT_EQ(r.liable_id, Party::vehicle(3));
  EXPECT_FALSE(r.collision);
}

// A collision between vehicles 2 and 3 at t = 5.82 s, vehicle 2 beyond its declared limits since
// t = 1.02 s, and the ego's side-lane path oscillating from t = 5.74 s: the collision is blamed on
// the last danger before it, vehicle 2's, not on the ego's comfort rule (nor on its progress).
TEST(Liability, AComfortOrProgressRuleIsNeverACollisionsCause) {
  const auto broken = [](const char* id, double time_s, Party liable_id) {
    RuleResult x;
    x.rule_id = id;
    x.holds = false;
    x.first_violation_time_s = time_s;
    x.liable_id = liable_id;
    return x;
  };
  CheckResult r;
  r.rules = {broken("rss_longitudinal", 1.68, Party::vehicle(2)), broken("collision", 5.82, Party::nobody()),
             broken("smoothness_oscillation", 5.74, Party::ego()), broken("progress", 5.8, Party::ego()),
             broken("declared_limits", 1.02, Party::vehicle(2))};
  r.holds = false;
  assign_liability(r);
  EXPECT_TRUE(r.collision);
  EXPECT_EQ(r.collision_liable_id, Party::vehicle(2));
  EXPECT_EQ(r.liable_id, Party::vehicle(2));
}

}  // namespace
}  // namespace mg
