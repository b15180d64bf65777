// What an acceptance gives a merge attempt (rules/acceptance_cover.h): whether the attempt may rest
// on it, its request's P_c against the crossing, and Definition 1 for the gap's other vehicle.
#include "rules/acceptance_cover.h"

#include <gtest/gtest.h>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::vehicle;

// A request of t_r = 1 s (rho_c = 1 s, rho_m = 4 s by default: it binds its sender until 6 s)
// accepted and delivered at 1.5 s.
struct Accepted {
  V2vMessage request;
  CoopExchange x;
  explicit Accepted(CoopCase c = CoopCase::kEgoAhead, int to_id = 1, double pc_m = 60.0) {
    request.to_id = to_id;
    request.sent_time_s = 1.0;
    request.coop_case = c;
    request.pc_m = pc_m;
    x.request = &request;
    x.sent_time_s = x.request_time_s = 1.0;
    x.accept_time_s = 1.4;
    x.accept_delivered_time_s = 1.5;
  }
};

MergeAttempt attempt_starting_at(double start_s, std::optional<double> entry_s = std::nullopt) {
  MergeAttempt a;
  a.start_time_s = start_s;
  a.entry_time_s = entry_s;
  return a;
}

TEST(AcceptanceCover, AnAcceptanceInTheDecisionWindowIsOneTheAttemptMayRestOn) {
  const Accepted acc;
  const RuleParams p;
  EXPECT_TRUE(delivered_in_window(acc.x, attempt_starting_at(3.0, 4.0), 1.0, p));
  // Delivered after the entry: the ego was already in the lane without it.
  EXPECT_FALSE(delivered_in_window(acc.x, attempt_starting_at(0.5, 1.2), 0.0, p));
}

// Delivered before the window (an earlier, aborted attempt's): it counts while it binds its
// sender, until t_r + rho_c + rho_m = 6 s, and not after.
TEST(AcceptanceCover, AnEarlierAcceptanceCountsOnlyWhileItBindsItsSender) {
  const Accepted acc;
  const RuleParams p;
  EXPECT_TRUE(delivered_in_window(acc.x, attempt_starting_at(5.9, 7.0), 4.0, p));
  EXPECT_FALSE(delivered_in_window(acc.x, attempt_starting_at(6.1, 7.0), 4.0, p));
}

// The crossing against P_c with tol = max(v T, l_e / 2): 20 m/s x 0.5 s = 10 m.
TEST(AcceptanceCover, ThePcCheckAllowsTheGroundCoveredInTheResponseTime) {
  Scenario s = base_scenario();
  const ObservedTrace t = test::observed(s, constant_accel_trace(s, 1.0));
  MergeAttempt a;
  a.crossing_x_m = 52.0;
  a.crossing_time_s = 2.6;
  a.crossing_speed_mps = 20.0;
  const Accepted ahead(CoopCase::kEgoAhead);
  const PcCheck c = pc_check_of(t, ahead.x, 3, a);
  EXPECT_EQ(c.exchange, 3u);
  EXPECT_DOUBLE_EQ(c.tolerance_m, 10.0);
  EXPECT_DOUBLE_EQ(c.margin_m, 52.0 - (60.0 - 10.0));  // ego ahead: no nearer the responder than P_c - tol
  const Accepted behind(CoopCase::kEgoBehind);
  EXPECT_DOUBLE_EQ(pc_check_of(t, behind.x, 0, a).margin_m, (60.0 + 10.0) - 52.0);
}

// A 2.1 request to vehicle 1 (the ego ahead of it): the gap's other vehicle is the one ahead of
// vehicle 1, judged by ineq. (1.2) over rho_c + rho_m at the ego's speed.
TEST(AcceptanceCover, TheOtherVehicleOfTheRequestedGapMustLeaveRoom) {
  for (const double leader_x : {200.0, 12.0}) {
    Scenario s = base_scenario();
    s.vehicles = {vehicle(1, -30.0, 20.0), vehicle(2, leader_x, 20.0)};
    const ObservedTrace t = test::observed(s, constant_accel_trace(s, 3.0));
    const Accepted acc(CoopCase::kEgoAhead, 1);
    EXPECT_EQ(requested_gap_other(t, acc.x), t.index_of(2));
    const double margin = other_vehicle_margin_m(t, s.params.rules, acc.x, t.index_of(2), false);
    EXPECT_EQ(other_gap_vehicle_clear(t, s.params.rules, acc.x), margin >= 0.0);
    EXPECT_EQ(margin >= 0.0, leader_x == 200.0) << "leader at " << leader_x << " m: margin " << margin;
  }
}

TEST(AcceptanceCover, AnOpenSideIsClear) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, -30.0, 20.0)};
  const ObservedTrace t = test::observed(s, constant_accel_trace(s, 3.0));
  const Accepted acc(CoopCase::kEgoAhead, 1);
  EXPECT_EQ(requested_gap_other(t, acc.x), -1);
  EXPECT_TRUE(other_gap_vehicle_clear(t, s.params.rules, acc.x));
}

}  // namespace
}  // namespace mg
