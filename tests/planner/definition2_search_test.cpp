// RCPP's Definition 2 search (planner/definition2_search.h): a merge on an acceptance in hand.
#include "planner/definition2_search.h"

#include <gtest/gtest.h>

#include "core/merge_duration.h"
#include "core/scenario.h"
#include "planner/rcpp_params.h"

namespace mg {
namespace {

// The ego at 17.6 m/s in its side lane, vehicle 1 (a 10.5 m truck) 27.4 m behind it in the main
// lane at 16.2 m/s, the v_o* it accepted (Def. 2.1, the ego ahead), nothing else on the road;
// rho_m = 4.8 s, T = 0.2 s. The acceptance binds vehicle 1 for `left_s` more seconds: the state
// of a cooperative merge aborted for another vehicle's braking, after the hold that follows an
// abort (campaign seed 9941, run 20967, at 2.1 s and later).
struct HeldAt {
  Scenario s;
  WorldSnapshot w;
  HeldAcceptance a;
  explicit HeldAt(double left_s) {
    s.road.lane_width_m = 3.0;
    s.params.planner.merge_duration_s = s.params.rules.merge_duration_s = 4.8;
    s.params.planner.comm_threshold_s = s.params.rules.comm_threshold_s = 1.0;
    s.params.rss.response_time_s = 0.2;
    s.ego.limits = Limits{3.1, 3.3, 4.8, 0.15, 1.5};
    s.ego.size.length_m = 4.7;
    s.ego.size.width_m = 1.75;
    s.ego.x_m = 7.0;
    s.ego.y_m = s.road.side_lane_y_m();
    s.ego.speed_mps = 17.6;
    s.ego.v2v.capable = true;
    MainVehicle partner;
    partner.id = 1;
    partner.x_m = -20.4;
    partner.speed_mps = 16.2;
    partner.size.length_m = 10.5;
    partner.size.width_m = 2.15;
    partner.limits = Limits{3.4, 4.3, 7.2, 0.5, 1.2};
    partner.v2v.capable = true;
    s.vehicles = {partner};
    w = initial_snapshot(s);
    w.time_s = 3.8;
    a = HeldAcceptance{1, CoopCase::kEgoAhead, 16.2, 11.8, 31.6, 0.3, 1.35, w.time_s + left_s};
  }
};

double shortest_merge_s(const Scenario& s) {
  return kShortestMergeFactor *
         shortest_comfortable_merge_s(s.road.lane_width_m, rcpp_params(s.params.planner).lat_accel_comfort_mps2);
}

TEST(Definition2Search, AnAcceptanceTakenUpAgainMergesAtRhoMWhileItBindsThePartnerThatLong) {
  const HeldAt h(3.0);
  const auto plan = plan_accepted_definition2(h.w, h.a);
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->sigmoid.pc_m, 7.0 + 17.6 * 2.4, 1e-9);
  EXPECT_EQ(plan->decision.mode, DecisionMode::kDef2Merge);
}

// Less than rho_m / 2 of the binding left: the merge is shortened so that its midpoint comes
// while the partner is still bound, down to the shortest comfortable lane change. It was dropped,
// and the ego waited while the acceptance stayed in force (`progress`, a campaign finding).
TEST(Definition2Search, AnAcceptanceTakenUpLateMergesSoonerDownToTheShortestComfortableMerge) {
  const double shortest_s = shortest_merge_s(HeldAt(0.0).s);
  ASSERT_LT(shortest_s, 4.0);
  const HeldAt h(2.0);
  const auto plan = plan_accepted_definition2(h.w, h.a);
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->sigmoid.pc_m, 7.0 + 17.6 * 2.0, 1e-6);
  EXPECT_FALSE(plan_accepted_definition2(HeldAt(0.5 * shortest_s - 0.01).w, HeldAt(0.5 * shortest_s - 0.01).a));
}

// Ineq. (3) and (4) rest on the partner's declared limits: the truck above is asked while it keeps
// them, and not while it is seen braking or accelerating beyond them.
TEST(Definition2Search, AVehicleSeenBeyondItsDeclaredLimitsIsNotAsked) {
  HeldAt h(3.0);
  const auto asked = plan_definition2(h.w, {});
  ASSERT_TRUE(asked.has_value());
  EXPECT_EQ(asked->partner.id, 1);
  h.w.others[0].state.accel_mps2 = -(h.s.vehicles[0].limits.brake_max_mps2 + 1.0);
  EXPECT_FALSE(plan_definition2(h.w, {}).has_value());
  h.w.others[0].state.accel_mps2 = h.s.vehicles[0].limits.accel_max_mps2 + 1.0;
  EXPECT_FALSE(plan_definition2(h.w, {}).has_value());
  h.w.others[0].state.accel_mps2 = -h.s.vehicles[0].limits.brake_max_mps2;  // at the limit
  EXPECT_TRUE(plan_definition2(h.w, {}).has_value());
}

}  // namespace
}  // namespace mg
