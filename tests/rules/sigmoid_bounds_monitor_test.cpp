#include "rules/sigmoid_bounds_monitor.h"

#include <algorithm>
#include <utility>

#include <gtest/gtest.h>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

// The ego is seen moving from the side lane centre (Y = -3.5) toward the main lane from t = from_s,
// so that its centre reaches the lane line (Y = -1.75), the merge midpoint, at midpoint_s (t = 1 s
// by default; the start is observed 0.1 m out, at 0.06 s). All at 20 m/s, so D_lon = 45.175 m both
// ways (see the RSS test). The right of way the monitor reads is inferred from this motion and
// the channel (rules/merge_attempts.h).
Trace with_midpoint_at(Trace t, double midpoint_s, double from_s = 0.0) {
  return test::with_lateral_move(std::move(t), from_s, 1.75 / (midpoint_s - from_s));
}
Trace with_midpoint(Trace t) { return with_midpoint_at(std::move(t), 1.0); }

// The ego's request for a Def. 2 merge to `partner`, accepted and the acceptance delivered at
// `accepted_s` (before the observed start of the merge: the ego holds the right of way by
// Definition 2 from then). Its P_c is where the ego's centre crosses the lane line (20 m/s to a
// midpoint at 1 s, unless given): a request whose P_c the ego does not keep to grants nothing
// (def2_request_truthful).
Trace with_def2_exchange(Trace t, int partner, CoopCase c, double target_mps, double accepted_s = 0.0,
                         double pc_m = 20.0) {
  const TraceEvent accept = test::message_event(std::min(accepted_s, 0.1), MessageType::kAccept, partner, 0, c, pc_m,
                                                44, target_mps);
  t.events.push_back(test::message_event(0.0, MessageType::kRequest, 0, partner, c, pc_m, 44, target_mps));
  t.events.push_back(accept);
  t.events.push_back(test::delivered_event(accept, accepted_s));
  return t;
}

TEST(SigmoidBoundsMonitor, MidpointBetweenFollowerAndLeaderWithSafeDistancesHolds) {
  // Follower 50 m behind: 50 - 45.175 = 4.825 m; leader 60 m ahead: 14.825 m. Margin 4.825 m.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -50.0, 20.0), vehicle(2, 60.0, 20.0)};
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, with_midpoint(constant_accel_trace(s, 2.0)));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 4.825, 1e-9);
}

TEST(SigmoidBoundsMonitor, MidpointInsideTheFollowersSafeDistanceBlamesTheEgo) {
  // Follower 40 m behind: 40 - 45.175 = -5.175 m; it kept its limits, so the ego is liable.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -40.0, 20.0)};
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, with_midpoint(constant_accel_trace(s, 2.0)));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -5.175, 1e-9);
}

TEST(SigmoidBoundsMonitor, FollowerThatOveracceleratedBeforeTheMidpointIsLiable) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -45.0, 20.0)};
  const MonitorOutput out =
      test::run(monitor_sigmoid_pc_bounds, s, with_midpoint(constant_accel_trace(s, 2.0, {0.0, 3.0})));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
}

TEST(SigmoidBoundsMonitor, AFollowerThatRacedPastTheEgoBeyondItsAmaxIsLiable) {
  // The merge started at t = 0 goes ahead of vehicle 1 (3 m behind, 20 m/s). It accelerates at
  // 10 m/s2 > a_max 2 and at the midpoint (t = 1 s) is 2 m ahead of the ego: the leader there,
  // inside the ego's safe distance, because of its own breach.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -3.0, 20.0)};
  const Trace t = with_midpoint(constant_accel_trace(s, 2.0, {0.0, 10.0}));
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
}

// The merge started at t = 0 goes behind vehicle 1, 2 m ahead at the ego's 20 m/s. It brakes
// at 10 m/s2 and at the midpoint (t = 1 s) is 3 m behind the ego: the follower there, inside the
// ego's safe distance, because it fell back level with the ego.
//
//   t = 0:   ego |====|        t = 1 s:       |====| ego
//                  |====| 1              |====| 1
Trace leader_falling_back(Scenario& s, double brake_mps2) {
  MainVehicle v = vehicle(1, 2.0, 20.0);
  v.limits.brake_max_mps2 = 8.0;
  s.vehicles = {v};
  return with_midpoint(constant_accel_trace(s, 2.0, {0.0, -brake_mps2}));
}

TEST(SigmoidBoundsMonitor, ALeaderThatFellBackBesideTheEgoBeyondItsBmaxIsLiable) {
  Scenario s = base_scenario();
  const Trace t = leader_falling_back(s, 10.0);
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
}

TEST(SigmoidBoundsMonitor, ALeaderThatFellBackBesideTheEgoWithinItsBmaxLeavesTheEgoLiable) {
  Scenario s = base_scenario();
  const Trace t = leader_falling_back(s, 7.0);  // 3.5 m fallen back: 1.5 m behind the ego
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
}

TEST(SigmoidBoundsMonitor, LeaderThatSlowedWithinItsLimitsLeavesThePairToTheRssRules) {
  // Leader 50 m ahead, all at 20 m/s; it brakes at 3 m/s^2 (its b_max is 8). At the midpoint
  // (t = 1 s) it is 50 - 1.5 = 48.5 m ahead at 17 m/s, D_lon(20, 17) = 45.175 + (400 - 289)/16
  // = 52.11 m: 3.6 m inside. Def. 1.2 predicted it holding 20 m/s, 50 m ahead: 4.825 m clear.
  // The ego gets the benefit of the doubt; rss_longitudinal judges its response. (The gap behind
  // vehicle 1 is a Def. 1 gap from t = 0: ineq. (1.2) holds by 4.825 m at v_e* = 20 m/s.)
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, 50.0, 20.0)};
  const Trace t = with_midpoint(constant_accel_trace(s, 2.0, {0.0, -3.0}));
  const auto judged = test::judge(s, t);
  ASSERT_EQ(judged->attempts.attempts.size(), 1u);
  ASSERT_EQ(judged->attempts.attempts[0].basis, RowBasis::kDef1);
  EXPECT_EQ(judged->attempts.attempts[0].decision_time_s, 0.0);
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, t);
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 4.825, 1e-6);
}

TEST(SigmoidBoundsMonitor, LeaderAtItsPredictedSpeedButTooCloseBlamesTheEgo) {
  // The same merge with the leader holding its speed 40 m ahead: 40 - 45.175 = -5.175 m under
  // both the real and the predicted positions.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, 40.0, 20.0)};
  const Trace t = with_midpoint(constant_accel_trace(s, 2.0));
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -5.175, 1e-6);
}

TEST(SigmoidBoundsMonitor, NonPartnerLeaderThatSlowedWithinItsLimitsInADef2MergeLeavesThePairToTheRssRules) {
  // The leader of the previous test, in a Def. 2.1 merge whose partner is vehicle 2, 60 m
  // behind (20 m/s, 14.825 m clear). The planner held the leader to ineq. (2) as Definition 1
  // does: predicted at 20 m/s it is 4.825 m clear. (At the real positions only it would be
  // -3.6 m, the ego liable; corpus case rcpp-coop__ego_never_liable__sigmoid_pc_bounds__ego.)
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, 50.0, 20.0), vehicle(2, -60.0, 20.0)};
  // Request and acceptance exchanged at t = 0 (an instantaneous channel): Def. 2 from t = 0.
  const Trace t = with_def2_exchange(with_midpoint(constant_accel_trace(s, 2.0, {0.0, -3.0, 0.0})), 2,
                                     CoopCase::kEgoAhead, 20.0);
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, t);
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 4.825, 1e-6);
}

TEST(SigmoidBoundsMonitor, PartnerLeaderIsJudgedAtItsRealPositionInADef2Merge) {
  // The same braking leader as the Def. 2.2 partner: it is bound by its accepted v_o* (here 20
  // m/s, from which it is 3 m/s away at the midpoint, beyond the 0.5 m/s tolerance), not by
  // Definition 1's prediction: judged at its real position, 3.6 m inside, and liable.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, 50.0, 20.0)};
  const Trace t = with_def2_exchange(with_midpoint(constant_accel_trace(s, 2.0, {0.0, -3.0})), 1, CoopCase::kEgoBehind, 20.0);
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
  EXPECT_LT(out.result.min_margin, -3.0);
}

TEST(SigmoidBoundsMonitor, NonPartnerLeaderAtItsPredictedSpeedButTooCloseInADef2MergeBlamesTheEgo) {
  // The non-partner leader holding its speed 40 m ahead: -5.175 m at both positions.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, 40.0, 20.0), vehicle(2, -60.0, 20.0)};
  const Trace t = with_def2_exchange(with_midpoint(constant_accel_trace(s, 2.0)), 2, CoopCase::kEgoAhead, 20.0);
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -5.175, 1e-6);
}

// Vehicle 1, 10 m behind the ego (both 20 m/s), accepted at 0.1 s the Def. 2.1 request of t = 0
// for v_o* = 15 m/s; it must be within 0.5 m/s of it from t_r + rho_c + T = 1.5 s. It slows to
// 15 m/s at `slows_at_s`. The merge midpoint is at 2 s: the ego 40 m, vehicle 1 about 25 m, inside
// D_lon(15 behind 20) = 19.6 m by 4.6 m whatever its speed history.
Trace responder_slowing_at(const Scenario& s, double slows_at_s) {
  Trace t = constant_accel_trace(s, 3.0);
  for (auto& st : t.steps) {
    st.others[0].x_m = -10.0 + 20.0 * std::min(st.time_s, 1.0) + 15.0 * std::max(0.0, st.time_s - 1.0);
    if (st.time_s >= slows_at_s - 1e-9) st.others[0].vx_mps = 15.0;
  }
  t.events.push_back(test::message_event(0.0, MessageType::kRequest, 0, 1, CoopCase::kEgoAhead, 40, 20, 15));
  t.events.push_back(test::message_event(0.1, MessageType::kAccept, 1, 0, CoopCase::kEgoAhead, 40, 20, 15));
  return with_midpoint_at(std::move(t), 2.0);
}

TEST(SigmoidBoundsMonitor, ResponderThatYieldedLateIsLiableEvenAfterItSlowed) {
  // It held 20 m/s until 1.8 s, past its yield deadline (1.5 s), and is at v_o* by the midpoint.
  // Judged by its speed at the midpoint alone, the ego would be liable (corpus case
  // rcpp-coop__ego_never_liable__sigmoid_pc_bounds__ego-4: a reneging partner that braked for a
  // stopped vehicle before the midpoint).
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -10.0, 20.0)};
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, responder_slowing_at(s, 1.8));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
}

TEST(SigmoidBoundsMonitor, ResponderThatYieldedInTimeLeavesTheEgoLiable) {
  // The same margin with vehicle 1 at v_o* from 1.2 s, before its deadline: the ego is liable.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -10.0, 20.0)};
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, responder_slowing_at(s, 1.2));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_LT(out.result.min_margin, -4.0);
}

// A Def. 2.1 merge with partner vehicle 1 (x0 behind the ego, both 20 m/s): its acceptance of the
// request of t = 0 (v_o* = 19.8 m/s, sent at 0.1 s) reaches the ego at 0.2 s, which is then seen
// moving over (midpoint at 2 s, the ego at 40 m). Vehicle 1 keeps 20 m/s: within the 0.5 m/s yield
// tolerance.
Trace partner_within_tolerance(const Scenario& s) {
  return with_midpoint_at(with_def2_exchange(constant_accel_trace(s, 3.0), 1, CoopCase::kEgoAhead, 19.8, 0.2, 40.0), 2.0,
                          0.2);
}

TEST(SigmoidBoundsMonitor, PartnerNearerThanItsAcceptedProfileAnswersForTheMargin) {
  // x0 = -45.075: really 0.1 m inside D_lon(20, 20) = 45.175 m. On the profile ineq. (3) counts
  // on (20 -> 19.8 m/s by t_r + rho_c = 1 s, then 19.8 m/s) it would be at -5.365 m with
  // D_lon(19.8, 20) = 44.03 m: 1.335 m clear. Keeping 20 m/s it is within def2_positions'
  // allowances (its response time, 0.5 m/s, 0.5 m per second), but nearer the ego than what it
  // accepted, and that is what left the ego 0.1 m short: vehicle 1 answers for the real margin
  // (spec §8, point 24).
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -45.075, 20.0)};
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, partner_within_tolerance(s));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::vehicle(1));
  EXPECT_NEAR(out.result.min_margin, -0.1, 0.01);
}

TEST(SigmoidBoundsMonitor, PartnerTooCloseEvenOnItsAcceptedProfileBlamesTheEgo) {
  // x0 = -30: -15.175 m really, -13.75 m on the accepted profile: the ego's P_c was wrong.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -30.0, 20.0)};
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, partner_within_tolerance(s));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -13.75, 0.05);
}

// The partner (vehicle 1, 50 m behind, on its accepted 20 m/s) of a Def. 2.1 merge granted at
// 0.2 s, the ego then at 20 m/s; the ego slows to 15 m/s from 1.5 s. At the midpoint (2 s, ego at 40 m)
// D_lon(20 behind 15) = 56.11 m against 50 m: -6.11 m, 4.825 m at the planned 20 m/s.
Trace slowed_ego_before_partner(const Scenario& s) {
  Trace t = partner_within_tolerance(s);
  for (auto& e : t.events)
    if (e.message) e.message->target_speed_mps = 20.0;
  for (auto& st : t.steps)
    if (st.time_s >= 1.5 - 1e-9) st.ego.vx_mps = 15.0;
  return t;
}

TEST(SigmoidBoundsMonitor, EgoSlowedByItsRssResponseIsJudgedAtItsPlannedSpeedBeforeThePartner) {
  // Vehicle 2, 30 m ahead in the ego's lane, brakes at 6 m/s2 (b_max 8) from 1 s: at the midpoint
  // it is 27 m ahead at 14 m/s, inside D_lon(15, 14) = 32.3 m: the ego brakes as the rear vehicle
  // of a dangerous pair. Judged at its real, slower speed the ego would be liable toward the
  // partner (-6.11 m; corpus case rcpp-coop__ego_never_liable__sigmoid_pc_bounds__ego-7); its
  // planned speed counts: 4.825 m.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -50.0, 20.0), vehicle(2, 30.0, 20.0)};
  Trace t = slowed_ego_before_partner(s);
  for (auto& st : t.steps) {
    const double b = std::max(0.0, st.time_s - 1.0);
    st.others[1].y_m = st.ego.y_m;
    st.others[1].x_m = 30.0 + 20.0 * st.time_s - 3.0 * b * b;
    st.others[1].vx_mps = 20.0 - 6.0 * b;
    st.others[1].accel_mps2 = st.time_s > 1.0 ? -6.0 : 0.0;
  }
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, t);
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 4.825, 0.01);
}

TEST(SigmoidBoundsMonitor, EgoSlowerThanPlannedWithoutAnRssDangerIsLiableBeforeThePartner) {
  // The same slowing with nobody ahead: nothing the ego had to answer, so its real speed counts.
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -50.0, 20.0)};
  const MonitorOutput out = test::run(monitor_sigmoid_pc_bounds, s, slowed_ego_before_partner(s));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -6.11, 0.02);
}

}  // namespace
}  // namespace mg
