// Each observed merge attempt and the right of way it had (rules/merge_attempts.h): Definition 1
// from the gap inequalities in the decision window before the observed start, Definition 2 from an
// acceptance delivered within rho_c, none otherwise; read from the ego's motion and the channel.
#include "rules/merge_attempts.h"

#include <limits>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "rules/definition1_gap.h"
#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

// The ego at X = 0, 20 m/s in the side lane; vehicles 1 (follower_x) and 2 (leader_x, when given)
// in the main lane at 20 m/s.
Scenario gap_scenario(double follower_x, std::optional<double> leader_x = std::nullopt, double limit_mps = 33.34) {
  Scenario s = base_scenario();
  s.road.speed_limit_mps = limit_mps;
  s.vehicles = {vehicle(1, follower_x, 20.0)};
  if (leader_x) s.vehicles.push_back(vehicle(2, *leader_x, 20.0));
  return s;
}

const MergeAttempt& only_attempt(const test::Judged& j) {
  EXPECT_EQ(j.attempts.attempts.size(), 1u);
  return j.attempts.attempts.front();
}

// The ego moves over from t = 1 s at 1.75 m/s: start observed at 1.06 s, midpoint at 2 s, complete
// at about 2.9 s.
Trace merging_from(const Scenario& s, double from_s, double duration_s = 4.0) {
  return test::with_lateral_move(constant_accel_trace(s, duration_s), from_s, 1.75);
}

//   main lane   [1]----80 m----+                     +----200 m----[2]
//   side lane                  [ego] -> starts at 1.06 s, midpoint 2 s
// Ineq. (1.1) holds by 5.825 m and (1.2) by 154.825 m at v_e* = 20 m/s (definition1_gap_test.cpp).
TEST(MergeAttempts, AStartWhereBothGapInequalitiesHoldHasTheRightOfWayByDefinition1) {
  const Scenario s = gap_scenario(-80.0, 200.0);
  const auto j = test::judge(s, merging_from(s, 1.0));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_NEAR(a.start_time_s, 1.06, 1e-9);
  ASSERT_TRUE(a.midpoint_time_s.has_value());
  EXPECT_NEAR(*a.midpoint_time_s, 2.0, 1e-9);
  EXPECT_TRUE(a.completed);
  EXPECT_EQ(a.entered_gap, (GapIndices{1, 2}));
  EXPECT_EQ(a.gap, a.entered_gap);
  EXPECT_EQ(a.basis, RowBasis::kDef1);
  // The gap was feasible since the first step of the window [start - 4 s, start], clipped to 0.
  EXPECT_EQ(a.decision_time_s, 0.0);
  EXPECT_EQ(a.def1.rho_s, 4.0);
  EXPECT_NEAR(a.def1.ve_star_mps, 20.0, 1e-9);
  EXPECT_NEAR(a.def1.margin_11_m, 5.825, 1e-9);
  EXPECT_NE(a.observation.find("ego holds (Def. 1)"), std::string::npos) << a.observation;
  EXPECT_TRUE(j->row.ego_holds_at(1.5));
}

// The ego at 20 m/s eases toward the lane from t = 1 s (0.3 m/s, still in the side lane when the
// 3 s trace ends); vehicle 1, 20 m behind at 30 m/s, is about to pass it:
//
//   t = 1.3 s   main lane     [1] 19 m --> 30 m/s
//               side lane                  [ego] 26 m --> 20 m/s, easing left
//
// Around the ego at its start is the gap ahead of vehicle 1, which fails ineq. (1.1). The ego has
// not entered the lane, so the gap it will enter is not known: the gap just behind vehicle 1, by
// ineq. (1.2) for v_e* of about 10 m/s under both position models, grants it the right of way
// (it lets vehicle 1 pass and merges behind it).
TEST(MergeAttempts, AnAttemptNotYetInTheLaneIsCreditedForTheGapBehindTheVehicleAboutToPassIt) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -20.0, 30.0)};
  const auto j = test::judge(s, test::with_lateral_move(constant_accel_trace(s, 3.0), 1.0, 0.3));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_FALSE(a.entry_step.has_value());
  EXPECT_EQ(a.entered_gap, (GapIndices{1, -1}));
  EXPECT_EQ(a.basis, RowBasis::kDef1);
  EXPECT_EQ(a.gap, (GapIndices{-1, 1}));
  EXPECT_GE(a.def1.margin_12_m, 0.0);
  // Once it has entered the lane, only the gap it entered (and the one around it) counts.
  const auto entered = test::judge(s, test::with_lateral_move(constant_accel_trace(s, 3.0), 0.0, 1.75));
  const MergeAttempt& b = only_attempt(*entered);
  EXPECT_TRUE(b.entry_step.has_value());
  EXPECT_NE(b.gap, (GapIndices{-1, 1}));
}

TEST(MergeAttempts, AGapFeasibleAllAlongIsCreditedFromBeforeTheDecisionWindow) {
  // A roomier gap (vehicle 1 250 m behind, vehicle 2 600 m ahead), the merge from t = 6 s (start
  // 6.06 s, midpoint 7 s): the window is [2.06, 6.06] s and the reading is taken in it, but the
  // gap was feasible since t = 0 (no attempt before) even for a merge whose midpoint comes 7 s
  // later (rho = 2 (7 - T) = 13 s: the follower accelerating until then, less the response time
  // T = 0.5 s): a slow merge decided long before its visible start holds the right of way from
  // its decision on.
  const Scenario s = gap_scenario(-250.0, 600.0);
  const auto j = test::judge(s, merging_from(s, 6.0, 8.0));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.basis, RowBasis::kDef1);
  EXPECT_NEAR(a.decision_time_s, 0.0, 1e-9);
  EXPECT_NEAR(a.def1.rho_s, 13.0, 1e-9);
  EXPECT_TRUE(j->row.ego_holds_at(0.5));
  EXPECT_TRUE(j->row.ego_holds_at(2.1));
}

// Definition 1.1 lets the follower accelerate until the ego merges. The gap of the first test
// (follower 80 m behind) read for the merge from 6 s, midpoint 7 s: at t = 0 it held for a merge
// of rho_m = 4 s, not for the one that happened (rho = 2 (7 - T) = 13 s, T = 0.5 s: the
// follower, at a_accel^max for 6.5 s, would be 42 m further on): the ego is credited only from
// when the gap held for a merge with its midpoint at 7 s. (Read at rho_m from t = 0, the follower was predicted to accelerate
// for 2 s only, and a follower accelerating legally until the midpoint carried the duty the
// ego's late merge created.)
TEST(MergeAttempts, AReadingPredictsTheFollowerAcceleratingUntilTheObservedMidpoint) {
  const Scenario s = gap_scenario(-80.0, 200.0);
  const auto j = test::judge(s, merging_from(s, 6.0, 8.0));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.basis, RowBasis::kDef1);
  EXPECT_GT(a.decision_time_s, 1.0);
  EXPECT_NEAR(a.def1.rho_s, 2.0 * (7.0 - 0.5 - a.decision_time_s), 1e-9);
  EXPECT_FALSE(j->row.ego_holds_at(0.5));
}

// Vehicle 1 behind the ego accelerates at its a_accel^max (2 m/s2), so ineq. (1.1) toward it
// shrinks every step; it is placed where (1.1) holds by 1 cm at t = 0 for the fastest v_e*, the
// speed limit. By the next step it fails (the follower is 0.04 m/s faster: 8 cm more over
// rho/2 alone). The gap was feasible only at the window's first instant: a planner that decided
// then merged with the right of way (a campaign finding: the window read every kScanStride
// steps from the entry missed that instant).
//
//   t = 0      main lane   [1]---(1.1) holds by 0.01 m---+
//              side lane                                  [ego] -> starts at 1.04 s, midpoint 1.98 s
// (a midpoint within rho_m/2 of t = 0, so that rho_m is the reading's duration there)
TEST(MergeAttempts, AGapFeasibleOnlyAtTheWindowsFirstInstantGrantsTheRightOfWay) {
  Scenario s = gap_scenario(-80.0);
  const auto trace_of = [](const Scenario& sc) {
    return test::with_lateral_move(constant_accel_trace(sc, 4.0, {0.0, 2.0}), 0.98, 1.75);
  };
  const double v_max = s.road.speed_limit_mps;
  const double margin0_m = def1_1_margin_m(test::observed(s, trace_of(s)), 0, 1, v_max, 4.0);
  s.vehicles[0].x_m += margin0_m - 0.01;  // (1.1) falls one for one as the follower moves up
  const ObservedTrace o = test::observed(s, trace_of(s));
  ASSERT_NEAR(def1_1_margin_m(o, 0, 1, v_max, 4.0), 0.01, 1e-9);
  ASSERT_FALSE(def1_interval(o, 1, GapIndices{1, -1}, 4.0).feasible());
  const auto j = test::judge(s, trace_of(s));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.basis, RowBasis::kDef1) << a.observation;
  EXPECT_EQ(a.decision_time_s, 0.0);
  EXPECT_GE(a.def1.margin_11_m, 0.0);
}

// Vehicle 1 45 m behind the ego at its speed, speed limit 22 m/s: ahead of vehicle 1, ineq. (1.1)
// needs 64.925 m at the best v_e* = 22 m/s; behind it, (1.2) at v_e* = 0 over rho/2 = 2 s fails by
// -45 + 20*2 - 4.8 = -9.8 m. No gap of the lane is feasible anywhere in the window.
//
//   main lane   [1]----45 m----+
//   side lane                  [ego] -> starts at 1.06 s
TEST(MergeAttempts, AStartWithTheFollowerTooCloseHasNoRightOfWay) {
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  const auto j = test::judge(s, merging_from(s, 1.0));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.entered_gap, (GapIndices{1, -1}));
  EXPECT_EQ(a.basis, RowBasis::kNone);
  EXPECT_TRUE(a.def1_read);
  EXPECT_LT(a.def1.min_margin_m(), 0.0);
  EXPECT_FALSE(a.exchange.has_value());
  EXPECT_NE(a.observation.find("no right of way"), std::string::npos) << a.observation;
  EXPECT_TRUE(j->row.ego_holds.empty());
}

// The same too-close follower; the ego asks it to yield (a Def. 2.1 request at request_s, 0.5 s
// unless given), its acceptance sent 0.1 s later and delivered at accept_delivered_s.
Trace with_exchange(Trace t, int responder, double accept_delivered_s, double request_s = 0.5, double vo_star_mps = 18,
                    double pc_m = 40) {
  const TraceEvent accept = test::message_event(request_s + 0.1, MessageType::kAccept, responder, 0,
                                                CoopCase::kEgoAhead, pc_m, 30, vo_star_mps);
  t.events = {
      test::message_event(request_s, MessageType::kRequest, 0, responder, CoopCase::kEgoAhead, pc_m, 30, vo_star_mps),
      accept, test::delivered_event(accept, accept_delivered_s)};
  return t;
}

TEST(MergeAttempts, AnAcceptanceDeliveredWithinRhoCBeforeTheStartGrantsDefinition2) {
  // Delivered at 0.9 s: 0.4 s after the request (rho_c = 1 s), before the start at 1.06 s.
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  const auto j = test::judge(s, with_exchange(merging_from(s, 1.0), 1, 0.9));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.basis, RowBasis::kDef2);
  EXPECT_NEAR(a.decision_time_s, 0.9, 1e-12);
  ASSERT_TRUE(a.exchange.has_value());
  EXPECT_EQ(a.exchange->request_time_s, 0.5);
  EXPECT_NE(a.observation.find("ego holds (Def. 2)"), std::string::npos) << a.observation;
  EXPECT_FALSE(j->row.ego_holds_at(0.8));
  EXPECT_TRUE(j->row.ego_holds_at(0.95));
}

// Definition 2 grants the right of way toward the partner only; the gap's other vehicle is
// Definition 1's. The same exchange with vehicle 1, and vehicle 2 ahead of the ego: 100 m ahead
// it satisfies ineq. (1.2) over rho_c + rho_m = 5 s with the ego at 20 m/s; 20 m ahead (D_lon
// behind it at 20 m/s is 45 m) it does not, and the acceptance grants nothing.
TEST(MergeAttempts, AnAcceptanceGrantsTheRightOfWayOnlyWhenTheGapsOtherVehicleAllowsIt) {
  const Scenario far = gap_scenario(-45.0, 100.0, 22.0), near = gap_scenario(-45.0, 20.0, 22.0);
  const auto ok = test::judge(far, with_exchange(merging_from(far, 1.0), 1, 0.9));
  EXPECT_EQ(only_attempt(*ok).basis, RowBasis::kDef2);
  const auto refused = test::judge(near, with_exchange(merging_from(near, 1.0), 1, 0.9));
  EXPECT_NE(only_attempt(*refused).basis, RowBasis::kDef2);
  EXPECT_FALSE(refused->row.ego_holds_at(0.95));
}

// Per vehicle of the gap entered: the partner by its acceptance, the gap's other vehicle by
// Definition 1 for the pair at the request; the ego holds the right of way toward each as its
// cover gives it.
TEST(MergeAttempts, AnAcceptanceCoversItsSenderAndDefinition1TheGapsOtherVehicle) {
  const Scenario far = gap_scenario(-45.0, 100.0, 22.0), near = gap_scenario(-45.0, 20.0, 22.0);
  const auto ok = test::judge(far, with_exchange(merging_from(far, 1.0), 1, 0.9));
  const MergeAttempt& a = only_attempt(*ok);
  EXPECT_EQ(a.follower.vehicle, 1);
  EXPECT_EQ(a.follower.by, Cover::kDef2);
  EXPECT_EQ(a.leader.vehicle, 2);
  EXPECT_EQ(a.leader.by, Cover::kDef2Pair);
  EXPECT_GE(a.leader.margin_m, 0.0);
  // Vehicle 2 20 m ahead: the acceptance still covers vehicle 1, and nothing covers vehicle 2.
  const auto refused = test::judge(near, with_exchange(merging_from(near, 1.0), 1, 0.9));
  const MergeAttempt& b = only_attempt(*refused);
  EXPECT_EQ(b.basis, RowBasis::kNone);
  EXPECT_EQ(b.follower.by, Cover::kDef2);
  EXPECT_EQ(b.leader.by, Cover::kNone);
  EXPECT_LT(b.leader.margin_m, 0.0);
  EXPECT_TRUE(refused->row.ego_holds_toward_at(1, 1.0));
  EXPECT_FALSE(refused->row.ego_holds_toward_at(2, 1.0));
  EXPECT_FALSE(refused->row.ego_holds_at(1.0));
}

// A request saying P_c = 45 m; the ego merging from 0.5 s crosses the lane line at 30 m (1.5 s
// at 20 m/s), 15 m nearer vehicle 1 than it said, beyond the tolerance: the 10 m the ego covers
// in the response time T = 0.5 s at 20 m/s (more than half its length, 2.4 m). Vehicle 1 keeps what it accepted (v_o* = 20 m/s, its
// speed). The acceptance grants nothing and the attempt is the lie's.
TEST(MergeAttempts, AnAcceptanceOfARequestWhosePcTheEgoDidNotKeepGrantsNothing) {
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  const auto j = test::judge(s, with_exchange(merging_from(s, 0.5), 1, 0.9, 0.5, 20.0, 45.0));
  const MergeAttempt& a = only_attempt(*j);
  ASSERT_TRUE(a.crossing_x_m.has_value());
  EXPECT_NEAR(*a.crossing_x_m, 30.0, 1e-9);
  EXPECT_EQ(a.basis, RowBasis::kNone);
  EXPECT_EQ(a.fault, AcceptanceFault::kUntruthful);
  ASSERT_EQ(a.pc_checks.size(), 1u);
  EXPECT_NEAR(a.pc_checks[0].tolerance_m, 10.0, 1e-9);
  EXPECT_NEAR(a.pc_checks[0].margin_m, 30.0 - (45.0 - 10.0), 1e-9);
  // Where the ego crosses at 40 m (merging from 1 s), within it: Definition 2.
  const auto kept = test::judge(s, with_exchange(merging_from(s, 1.0), 1, 0.9, 0.5, 20.0, 45.0));
  EXPECT_EQ(only_attempt(*kept).basis, RowBasis::kDef2);
  // A responder that broke what it accepted (v_o* = 18 m/s, and it keeps 20) left the ego to
  // answer its breach: the crossing is not held to P_c, and its acceptance covers it.
  const auto broken = test::judge(s, with_exchange(merging_from(s, 0.5), 1, 0.9, 0.5, 18.0, 45.0));
  EXPECT_EQ(only_attempt(*broken).basis, RowBasis::kDef2);
  EXPECT_TRUE(only_attempt(*broken).pc_checks.empty());
}

// A 2.1 responder that did not yield and passed the ego bounds the gap entered as its leader: its
// breach changed the gap, and its acceptance still covers it there. Vehicle 1, 5 m behind at
// 20 m/s, accepts v_o* = 16 m/s and accelerates at 2 m/s2 instead; the ego keeps 20 m/s and merges
// behind it (midpoint 3 s).
TEST(MergeAttempts, AResponderThatPassedTheEgoByBreakingItsAcceptanceIsStillCovered) {
  Scenario s = gap_scenario(-5.0, std::nullopt, 33.34);
  s.vehicles[0].limits.accel_max_mps2 = 2.0;
  Trace t = test::with_lateral_move(constant_accel_trace(s, 4.0, {0.0, 2.0}), 2.0, 1.75);
  const TraceEvent accept = test::message_event(0.1, MessageType::kAccept, 1, 0, CoopCase::kEgoAhead, 60, 20, 16);
  t.events = {test::message_event(0.0, MessageType::kRequest, 0, 1, CoopCase::kEgoAhead, 60, 20, 16), accept,
              test::delivered_event(accept, 0.2)};
  const auto j = test::judge(s, t);
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.entered_gap, (GapIndices{-1, 1}));
  EXPECT_EQ(a.leader.by, Cover::kDef2);
  EXPECT_EQ(a.basis, RowBasis::kDef2);
}

// Two acceptances of vehicle 1 (v_o* its speed, kept) in the window: of a request whose P_c
// (100 m) the ego did not keep, then of a re-planned one (40 m) it kept. The attempt rests on the second; the first is no
// lie the ego merged on (an earlier acceptance, replaced after an abort, is not judged against
// the later merge's crossing).
TEST(MergeAttempts, AStaleAcceptanceOfTheSameVehicleIsNotJudgedAgainstTheCrossing) {
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  Trace t = merging_from(s, 1.0);
  const auto exchange = [&](double request_s, double pc_m, double delivered_s) {
    const TraceEvent accept = test::message_event(request_s + 0.1, MessageType::kAccept, 1, 0, CoopCase::kEgoAhead,
                                                  pc_m, 30, 20);
    t.events.push_back(test::message_event(request_s, MessageType::kRequest, 0, 1, CoopCase::kEgoAhead, pc_m, 30, 20));
    t.events.push_back(accept);
    t.events.push_back(test::delivered_event(accept, delivered_s));
  };
  exchange(0.0, 100.0, 0.2);
  exchange(0.5, 40.0, 0.9);
  const auto j = test::judge(s, t);
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.basis, RowBasis::kDef2);
  EXPECT_EQ(a.exchange->sent_time_s, 0.5);
  ASSERT_EQ(a.pc_checks.size(), 1u);
  EXPECT_GE(a.pc_checks[0].margin_m, 0.0);
  // With vehicle 2 20 m ahead nothing covers it, and the attempt has no basis: it is the
  // Definition 1 gap rules' toward vehicle 2, not the stale lie's.
  Scenario near = gap_scenario(-45.0, 20.0, 22.0);
  Trace u = t;
  const Trace moved = merging_from(near, 1.0);
  for (std::size_t i = 0; i < u.steps.size(); ++i) u.steps[i].others = moved.steps[i].others;
  const auto k = test::judge(near, u);
  const MergeAttempt& b = only_attempt(*k);
  EXPECT_EQ(b.basis, RowBasis::kNone);
  EXPECT_EQ(b.fault, AcceptanceFault::kNone);
  EXPECT_EQ(b.follower.by, Cover::kDef2);
  EXPECT_EQ(b.leader.by, Cover::kNone);
  for (const PcCheck& c : b.pc_checks) EXPECT_GE(c.margin_m, 0.0);
}

// A request without P_c asks for nothing the rules can judge: its acceptance is no acceptance.
TEST(MergeAttempts, AnAcceptanceOfARequestWithoutANumberGrantsNothing) {
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  Trace t = with_exchange(merging_from(s, 1.0), 1, 0.9);
  for (TraceEvent& e : t.events) e.message->pc_m = std::numeric_limits<double>::quiet_NaN();
  const auto j = test::judge(s, t);
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.basis, RowBasis::kNone);
  EXPECT_EQ(a.fault, AcceptanceFault::kNone);  // judged by Definition 1 toward vehicle 1
  EXPECT_EQ(a.follower.by, Cover::kNone);
}

TEST(MergeAttempts, AnAcceptanceDeliveredAfterRhoCGrantsNothingAndIsKeptForDef23) {
  // Requested at 0.1 s, delivered at 1.2 s (1.1 s later); the merge from 1.2 s (start 1.26 s,
  // midpoint 2.2 s). (The window starts at 0: rho = max(4, 2 (2.2 - T)) stays below the 4.98 s at
  // which merging behind vehicle 1 at v_e* = 0 would satisfy ineq. (1.2).)
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  const auto j = test::judge(s, with_exchange(merging_from(s, 1.2), 1, 1.2, 0.1));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.basis, RowBasis::kNone) << a.observation;
  ASSERT_TRUE(a.exchange.has_value());
  EXPECT_EQ(a.exchange->accept_delivered_time_s, 1.2);
  EXPECT_TRUE(j->row.ego_holds.empty());
}

// The ego's left edge (Y = -3.5 + 0.95 at rest) is past the lane line (Y = -1.75) by more than
// the 0.05 m marking tolerance 0.85 m into the move at 1.75 m/s: it enters the main lane at the
// step of t = 1.5 s.
TEST(MergeAttempts, AnAcceptanceDeliveredAfterTheStartButBeforeTheEntryGrantsIt) {
  // In time for rho_c (1.3 s) and after the visible start (1.06 s), but before the ego took any
  // of the main lane's room.
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  const auto j = test::judge(s, with_exchange(merging_from(s, 1.0), 1, 1.3));
  const MergeAttempt& a = only_attempt(*j);
  ASSERT_TRUE(a.entry_time_s.has_value());
  EXPECT_NEAR(*a.entry_time_s, 1.5, 1e-9);
  EXPECT_EQ(a.basis, RowBasis::kDef2) << a.observation;
}

TEST(MergeAttempts, AnAcceptanceDeliveredOnlyAfterTheEntryGrantsNothing) {
  // Requested at 1.0 s, delivered at 1.6 s (within rho_c), but the ego entered at 1.5 s.
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  const auto j = test::judge(s, with_exchange(merging_from(s, 1.0), 1, 1.6, 1.0));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.basis, RowBasis::kNone) << a.observation;
  EXPECT_TRUE(j->row.ego_holds.empty());
}

// A Def. 2.1 merge ahead of vehicle 1 (45 m behind) and behind vehicle 2, which passes the ego at
// 30 m/s between the delivery (0.9 s) and the entry (1.5 s): 13 m behind the ego at the start, 2 m
// ahead at the entry. The trace ends at 1.8 s, before the midpoint, so the gap entered is not
// known; the gap around the ego at its entry is vehicle 1's, and its acceptance covers the
// attempt (vehicle 2, the other vehicle of the gap asked for, passes well clear by ineq. (1.2)).
// With vehicle 2 still behind the ego at the entry (at 20 m/s) vehicle 1 bounds no gap the ego
// was seen in, and the acceptance grants nothing.
TEST(MergeAttempts, AnAcceptanceFromTheFollowerAtTheEntryCoversAnAttemptCutBeforeItsMidpoint) {
  Scenario s = gap_scenario(-45.0, -13.0, 22.0);
  s.vehicles[1].speed_mps = 30.0;
  const auto j = test::judge(s, with_exchange(merging_from(s, 1.0, 1.8), 1, 0.9));
  const MergeAttempt& a = only_attempt(*j);
  ASSERT_TRUE(a.entry_time_s.has_value());
  EXPECT_FALSE(a.midpoint_time_s.has_value());
  EXPECT_EQ(a.entered_gap.follower, 2) << "the gap around the ego at its start";
  EXPECT_EQ(a.basis, RowBasis::kDef2) << a.observation;

  const Scenario behind = gap_scenario(-45.0, -13.0, 22.0);
  const auto k = test::judge(behind, with_exchange(merging_from(behind, 1.0, 1.8), 1, 0.9));
  EXPECT_NE(only_attempt(*k).basis, RowBasis::kDef2) << only_attempt(*k).observation;
}

TEST(MergeAttempts, AnAcceptanceFromAVehicleOutsideTheGapGrantsNothing) {
  // Vehicle 2 drives in the second main lane: its acceptance in time says nothing of the gap.
  Scenario s = gap_scenario(-45.0, 10.0, 22.0);
  s.road.main_lanes = 2;
  s.vehicles[1].lane = 1;
  const auto j = test::judge(s, with_exchange(merging_from(s, 1.0), 2, 0.9));
  EXPECT_EQ(only_attempt(*j).basis, RowBasis::kNone);
}

// Out at 1 m/s for 0.5 s from 1 s and back (aborted at about 1.96 s), then over again from
// second_from_s. The acceptance of 0.9 s (request at 0.5 s) binds vehicle 1 until 0.5 + rho_c +
// rho_m = 5.5 s, the span for which progress offers it.
Trace aborted_then_over_again(const Scenario& s, double second_from_s, double horizon_s) {
  Trace t = with_exchange(test::with_aborted_move(constant_accel_trace(s, horizon_s), 1.0, 1.0, 0.5), 1, 0.9);
  const Trace second = merging_from(s, second_from_s, horizon_s);
  for (std::size_t i = 0; i < t.steps.size(); ++i)
    if (t.steps[i].time_s >= second_from_s) t.steps[i].ego = second.steps[i].ego;
  return t;
}

// Judged, with its two attempts; the first, on the acceptance, holds by Definition 2.
auto judge_aborted_then_over_again(const Scenario& s, double second_from_s, double horizon_s) {
  auto j = test::judge(s, aborted_then_over_again(s, second_from_s, horizon_s));
  EXPECT_EQ(j->attempts.attempts.size(), 2u);
  const MergeAttempt& first = j->attempts.attempts.front();
  EXPECT_EQ(first.basis, RowBasis::kDef2);
  EXPECT_TRUE(first.end_time_s.has_value() && !first.completed);
  EXPECT_TRUE(j->row.ego_holds_at(1.5));
  return j;
}

TEST(MergeAttempts, AnAbortedAttemptsAcceptanceCarriesOverWhileItBindsItsSender) {
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  const auto j = judge_aborted_then_over_again(s, 2.5, 5.0);
  ASSERT_EQ(j->attempts.attempts.size(), 2u);
  EXPECT_EQ(j->attempts.attempts[1].basis, RowBasis::kDef2) << j->attempts.attempts[1].observation;
  EXPECT_TRUE(j->row.ego_holds_at(3.0));
}

TEST(MergeAttempts, AnAbortedAttemptsAcceptanceDoesNotCarryOverPastItsSpan) {
  // The same, over again from 6 s: vehicle 1 is no longer bound, and the second attempt's window
  // starts at the abort.
  const Scenario s = gap_scenario(-45.0, std::nullopt, 22.0);
  const auto j = judge_aborted_then_over_again(s, 6.0, 9.0);
  ASSERT_EQ(j->attempts.attempts.size(), 2u);
  EXPECT_EQ(j->attempts.attempts[1].basis, RowBasis::kNone) << j->attempts.attempts[1].observation;
  EXPECT_FALSE(j->row.ego_holds_at(*j->attempts.attempts[0].end_time_s + 0.01));
  EXPECT_FALSE(j->row.ego_holds_at(7.0));
}

// Vehicle 1 25 m behind the ego at its speed: D_lon(20, 20) = 45.175 m, so the ego that moves over
// ahead of it (and completes the merge there at 20 m/s) cuts in. The gap it entered, ahead of
// vehicle 1, fails ineq. (1.1) at every v_e* up to the 22 m/s limit (by -39.925 m at 22 m/s).
// Merging behind vehicle 1 would have been a Definition 1 merge (ineq. (1.2) at v_e* = 0: -25 +
// 20*2 - 4.8 = 10.2 m), but the ego did not do that.
//
//   main lane   [1]--25 m--+
//   side lane              [ego] -> over at 1.75 m/s, ahead of vehicle 1
TEST(MergeAttempts, AnEgoCuttingInAheadOfAFollowerTooCloseHasNoRightOfWay) {
  const Scenario s = gap_scenario(-25.0, std::nullopt, 22.0);
  const auto j = test::judge(s, merging_from(s, 1.0));
  const MergeAttempt& a = only_attempt(*j);
  EXPECT_EQ(a.entered_gap, (GapIndices{1, -1}));
  EXPECT_EQ(a.basis, RowBasis::kNone) << a.observation;
  EXPECT_FALSE(j->row.ego_holds_at(1.5));
}

TEST(MergeAttempts, NoLateralMotionNoAttempt) {
  const Scenario s = gap_scenario(-80.0, 200.0);
  EXPECT_TRUE(test::judge(s, constant_accel_trace(s, 4.0))->attempts.attempts.empty());
}

// Vehicle 1 stands 100 m ahead; the ego, at 30 m/s, heads for the gap ahead of it (feasible at
// t = 0 over the observed 12 s merge). From t = 1 s vehicle 1 accelerates at 7 m/s2 and stays
// just ahead of the ego (5.7 m at the closest), so the ego's body enters the main lane behind it.
//
//   t = 0    side lane [ego] 30 m/s ---------------> P_c
//            main lane                 [1] stopped, then 7 m/s2 from t = 1 s
//
// Declared a_accel^max 2 m/s2: vehicle 1 changed the ego's gap by breaking its limits, and the
// gap the ego headed for still counts. Declared 8 m/s2: no breach, and the ego is judged by the
// gap it entered, behind vehicle 1, which it never had.
TEST(MergeAttempts, AGapChangedByAVehicleBreakingItsLimitsStillGrantsTheRightOfWay) {
  const auto judged_with = [](double declared_accel_max_mps2) {
    Scenario s = base_scenario();
    s.ego.speed_mps = 30.0;
    s.vehicles = {vehicle(1, 100.0, 0.0)};
    s.vehicles[0].limits.accel_max_mps2 = declared_accel_max_mps2;
    Trace t = test::with_lateral_move(constant_accel_trace(s, 12.0), 3.7, 0.7);
    for (TraceStep& st : t.steps) {
      const double racing_s = std::max(0.0, st.time_s - 1.0);
      st.others[0].x_m = 100.0 + 3.5 * racing_s * racing_s;
      st.others[0].vx_mps = 7.0 * racing_s;
      st.others[0].accel_mps2 = st.time_s >= 1.0 ? 7.0 : 0.0;
    }
    return test::judge(s, t);
  };
  const auto breach = judged_with(2.0);
  const MergeAttempt& a = only_attempt(*breach);
  ASSERT_TRUE(a.entry_step.has_value());
  EXPECT_EQ(a.entered_gap, (GapIndices{-1, 1}));  // behind vehicle 1
  EXPECT_EQ(a.basis, RowBasis::kDef1);
  EXPECT_EQ(a.gap, (GapIndices{1, -1}));  // ahead of it, as decided
  EXPECT_EQ(a.decision_time_s, 0.0);

  const auto compliant = judged_with(8.0);
  const MergeAttempt& b = only_attempt(*compliant);
  EXPECT_EQ(b.entered_gap, (GapIndices{-1, 1}));
  EXPECT_EQ(b.basis, RowBasis::kNone);
}

}  // namespace
}  // namespace mg
