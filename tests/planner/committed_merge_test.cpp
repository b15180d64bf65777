// The reference path of a committed merge (planner/committed_merge.h, merge_path_points): the
// sigmoid; for a merge begun from a hold, never farther from the main lane than the Y held.
#include "planner/committed_merge.h"

#include <algorithm>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/rss.h"
#include "core/scenario.h"
#include "planner/rcpp_world.h"

namespace mg {
namespace {

// A merge from lane centre Y = -3.5 to Y = 0 (W = 3.5 m) with P_c = 50 m, started at start_y_m,
// from a hold there or not.
CommittedMerge merge_from(double start_y_m, bool from_hold, double kappa_per_m = 0.1) {
  CommittedMerge m;
  m.sigmoid = Sigmoid{3.5, kappa_per_m, 50.0, -3.5};
  m.start_y_m = start_y_m;
  m.from_hold = from_hold;
  return m;
}

TEST(CommittedMerge, FromTheSideLanesCentreThePathIsTheSigmoidOverTheWholeRange) {
  const CommittedMerge m = merge_from(-3.5, false);
  const auto path = merge_path_points(m, -10.0, 150.5, 1.0);
  EXPECT_DOUBLE_EQ(path.front().x_m, -10.0);
  EXPECT_DOUBLE_EQ(path.back().x_m, 150.5);
  for (std::size_t i = 1; i < path.size(); ++i) EXPECT_GT(path[i].x_m, path[i - 1].x_m);
  for (const PathPoint& p : path) EXPECT_DOUBLE_EQ(p.y_m, m.sigmoid.y_at_m(p.x_m));
}

//   Y = 0     main lane centre                         ____________
//   Y = -3.14 held after an abort  ==========________/     <- the path keeps -3.14 until the
//   Y = -3.5  side lane centre     ____.---'                  sigmoid passes it, no swing back
TEST(CommittedMerge, AMergeFromAHoldNearerTheMainLaneNeverSwingsBackToTheCentre) {
  const CommittedMerge m = merge_from(-3.14, true);
  const auto path = merge_path_points(m, 0.0, 100.0, 0.5);
  EXPECT_DOUBLE_EQ(path.front().y_m, -3.14);  // the sigmoid is at -3.48 there
  for (const PathPoint& p : path) EXPECT_GE(p.y_m, -3.14);
  EXPECT_DOUBLE_EQ(path.back().y_m, m.sigmoid.y_at_m(100.0));
}

// An ego on its way back to the centre (not holding) when the merge begins goes on to the
// sigmoid: that also takes it away from the main lane's vehicles it is beside.
TEST(CommittedMerge, AMergeBegunOnTheWayBackToTheCentreFollowsTheSigmoid) {
  const CommittedMerge m = merge_from(-3.05, false);
  const auto path = merge_path_points(m, 0.0, 100.0, 0.5);
  for (const PathPoint& p : path) EXPECT_DOUBLE_EQ(p.y_m, m.sigmoid.y_at_m(p.x_m));
  EXPECT_LT(path.front().y_m, -3.4);
}

// A crawl merge's sharp sigmoid (kappa 0.468/m, its end at X = 58.3 m) is tracked up to 0.9 m
// behind. Past its end the merge completes (and lane keeping takes the ego to the speed limit)
// only once the ego is within a tenth of the lane change of the lane and turned along the road:
// an ego accelerating from there still turned toward the lane overshot the lane centre.
//
//   Y = 0      ____________________  main lane centre
//   Y = -0.3       ..-'' settled once |yaw| <= 0.05 rad
//   Y = -0.9     .'      not settled: 0.74 of the lane change
TEST(CommittedMerge, PastTheSigmoidsEndAMergeCompletesOnlyOnceTheEgoHasSettled) {
  const CommittedMerge m = merge_from(-3.5, false, 0.468);
  ASSERT_LT(m.sigmoid.x_at_fraction_m(1.0 - kSigmoidEndFraction), 58.5);
  WorldSnapshot w;
  const auto complete_at = [&](double x_m, double y_m, double yaw_rad) {
    w.ego.x_m = x_m;
    w.ego.y_m = y_m;
    w.ego.yaw_rad = yaw_rad;
    return merge_complete(m, w);
  };
  EXPECT_FALSE(complete_at(62.0, -0.9, 0.2));
  EXPECT_FALSE(complete_at(62.0, -0.3, 0.17));
  EXPECT_TRUE(complete_at(62.0, -0.3, 0.02));
  EXPECT_FALSE(complete_at(55.0, -0.3, 0.02));  // before the end: by lateral progress only
  EXPECT_TRUE(complete_at(55.0, -0.05, 0.1));
}

// A Definition 1 merge into the gap ahead of vehicle 1, which has caught up and drives beside
// the ego 3 m/s faster: the P_c bounds cross. The ego (4.5 m x 1.8 m) is 0.65 m toward the main
// lane from its side lane's centre (W = 3.5 m), under a quarter of the lane change: not
// committed. Heading along the road its body is short of the lane line and the merge is aborted;
// turned 0.1 rad toward the lane its front corner is over the line, in the main lane where the
// rules judge the merge's entry, and the merge goes on under the RSS override, unless vehicle 1
// is seen braking beyond its declared b_max: then going back is the way out.
TEST(CommittedMerge, AMergeIsNotAbortedOnceACornerOfTheBodyIsInTheMainLane) {
  Scenario s;
  s.road.lane_width_m = 3.5;
  s.ego.size.length_m = 4.5;
  s.ego.size.width_m = 1.8;
  s.ego.x_m = 100.0;
  s.ego.y_m = s.road.side_lane_y_m() + 0.65;
  s.ego.speed_mps = 15.0;
  MainVehicle beside;
  beside.id = 1;
  beside.x_m = 100.0;
  beside.speed_mps = 18.0;
  s.vehicles = {beside};
  CommittedMerge m = merge_from(s.road.side_lane_y_m(), false);
  m.sigmoid.pc_m = 130.0;
  m.target_speed_mps = 15.0;
  m.decision.mode = DecisionMode::kDef1Merge;
  m.decision.gap = Gap{1, -1};
  ASSERT_FALSE(m.committed(s.ego.y_m));
  WorldSnapshot w = initial_snapshot(s);
  EXPECT_TRUE(merge_should_abort(m, w));
  w.ego.yaw_rad = 0.1;
  EXPECT_FALSE(merge_should_abort(m, w));
  w.others[0].state.accel_mps2 = -(beside.limits.brake_max_mps2 + 1.0);
  EXPECT_TRUE(merge_should_abort(m, w));
}

// A merge decided to overtake vehicle 1, slow ahead in the main lane, and to merge ahead of it
// (gap: follower 1). Vehicle 1 then accelerates at four times its a_accel^max: the gap is gone.
// The ego (b_min 2.4, b_max 3.0 m/s2) can no longer stop before the side lane's end at b_min, but
// still at b_max: the merge is aborted, and Def. 1.3's halt is the halt profile's at b_max. A few
// metres on, where b_max cannot stop it either, the merge goes on under the RSS override.
TEST(CommittedMerge, AMergeIntoAGapABreachClosedIsAbortedWhileTheEgoCanStillHaltAtBMax) {
  Scenario s;
  s.road.lane_width_m = 3.5;
  s.road.side_lane_end_x_m = 170.0;
  s.ego.size.length_m = 5.4;
  s.ego.limits.brake_min_mps2 = 2.4;
  s.ego.limits.brake_max_mps2 = 3.0;
  s.ego.x_m = 37.0;
  s.ego.y_m = s.road.side_lane_y_m();
  s.ego.speed_mps = 24.9;
  MainVehicle ahead;
  ahead.id = 1;
  ahead.x_m = 58.0;
  ahead.speed_mps = 9.5;
  ahead.limits.accel_max_mps2 = 1.9;
  s.vehicles = {ahead};
  CommittedMerge m;
  m.sigmoid = Sigmoid{3.5, 0.055, 134.5, -3.5};
  m.start_y_m = s.ego.y_m;
  m.target_speed_mps = 24.9;
  m.decision.mode = DecisionMode::kDef1Merge;
  m.decision.gap = Gap{1, -1};
  m.decision.merge_duration_s = 11.0;
  WorldSnapshot w = initial_snapshot(s);
  w.others[0].state.accel_mps2 = 7.9;
  ASSERT_FALSE(can_still_halt(w));
  ASSERT_TRUE(can_still_halt(w, s.ego.limits.brake_max_mps2));
  EXPECT_TRUE(merge_should_abort(m, w));
  w.ego.x_m = 65.0;
  ASSERT_FALSE(can_still_halt(w, s.ego.limits.brake_max_mps2));
  EXPECT_FALSE(merge_should_abort(m, w));
}

// Past P_c behind vehicle 1, 1 m beyond its RSS distance (less than the 2 m following buffer),
// the ego at 15 m/s. Vehicle 1 at 18 m/s opens the buffer by itself: the ego keeps its speed (it
// braked at b_min for it, and a Def. 2.1 partner behind closed in past its safe distance). At
// 12 m/s, or inside its RSS distance, vehicle 1 still caps the ego below its speed.
TEST(CommittedMerge, ALeaderPullingAwayOutsideItsRssDistanceIsNotAReasonToBrake) {
  Scenario s;
  s.road.lane_width_m = 3.5;
  s.ego.x_m = 100.0;
  s.ego.y_m = -1.0;
  s.ego.speed_mps = 15.0;
  const auto leader_at = [&](double beyond_d_lon_m, double speed_mps) {
    MainVehicle v;
    v.id = 1;
    v.speed_mps = speed_mps;
    v.x_m = s.ego.x_m + beyond_d_lon_m +
            rss_longitudinal_m({s.ego.speed_mps, speed_mps, s.ego.size.length_m, v.size.length_m,
                                s.params.rss.response_time_s, s.ego.limits.accel_max_mps2,
                                s.ego.limits.brake_min_mps2, v.limits.brake_max_mps2});
    Scenario with = s;
    with.vehicles = {v};
    return with;
  };
  CommittedMerge m = merge_from(-3.5, false);  // P_c at X = 50 m: the ego is past it
  m.target_speed_mps = 15.0;
  m.decision.mode = DecisionMode::kDef2Merge;
  m.decision.gap = Gap{-1, 1};
  const auto target = [&](const Scenario& sc) { return follow_merge(m, initial_snapshot(sc)).target_speed_mps; };
  EXPECT_EQ(target(leader_at(1.0, 18.0)), 15.0);
  EXPECT_LT(target(leader_at(1.0, 12.0)), 15.0);
  EXPECT_LT(target(leader_at(-0.5, 18.0)), 15.0);
  EXPECT_EQ(target(leader_at(3.0, 15.0)), 15.0);  // beyond the buffer: no cap either way
}

RC_GTEST_PROP(CommittedMerge, APathFromAHoldOnlyEverMovesTowardTheMainLane, ()) {
  const double start_y_m = -3.5 + *rc::gen::inRange(0, 175) / 100.0;  // up to the lane line
  const double kappa_per_m = *rc::gen::inRange(2, 50) / 100.0;
  const CommittedMerge m = merge_from(start_y_m, true, kappa_per_m);
  const auto path = merge_path_points(m, -50.0, 200.0, 0.5);
  for (std::size_t i = 0; i < path.size(); ++i) {
    RC_ASSERT(path[i].y_m >= start_y_m);
    RC_ASSERT(path[i].y_m == std::max(start_y_m, m.sigmoid.y_at_m(path[i].x_m)));
    if (i > 0) RC_ASSERT(path[i].y_m >= path[i - 1].y_m);
  }
}

}  // namespace
}  // namespace mg
