#include "planner/merge_path.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/rss.h"
#include "planner/rcpp_params.h"

namespace mg {
namespace {

// Defaults: W = 3.5 m, T = 0.5 s, widths 1.9 m, lengths 4.8 m, a_acc 2, b_min 4, b_max 8 m/s2.
// At rest D_lat = 0.1 + 1.9 + 2 (0.2 0.5^2 / 2 + 0.1^2 / 1.6) = 2.0625 m.
Scenario road_only() {
  Scenario s;
  s.ego.x_m = 0.0;
  s.ego.y_m = -s.road.lane_width_m;
  return s;
}

MainLaneVehicle lane_vehicle(int id, double x_m, double speed_mps) {
  return MainLaneVehicle{id, x_m, speed_mps, 4.8, 1.9, Limits{}};
}

double no_accel(int) { return 0.0; }

// The ego merges at a constant 20 m/s with P_c at X = 60 m (t = 3 s) on a sharp sigmoid
// (kappa 0.3/m: within D_lat of the lane centre only for |X - P_c| < ~15 m, t in [2.25, 3.75] s).
//
//   t = 3 s:   ego (P_c) 60 m    slow vehicle 2: 5 + 20*3 = 65 m    fast vehicle 1: -10 + 40*3 = 110 m
//
// Vehicle 1 is the gap's leader, predicted at 40 m/s: alone it leaves the ego room at P_c. But it
// starts behind vehicle 2 (20 m/s) in the same lane, so its prediction "passes" vehicle 2, and the
// ego would merge 5 m behind vehicle 2, far inside D_lon (45.2 m at 20 m/s behind 20 m/s).
TEST(OccupancyClear, AMergeBehindALeaderIsCheckedAgainstTheVehiclesAheadOfIt) {
  const Scenario s = road_only();
  const std::vector<MainLaneVehicle> lane = {lane_vehicle(1, -10.0, 40.0), lane_vehicle(2, 5.0, 20.0)};
  const LaneGap gap{std::nullopt, lane[0]};
  const Sigmoid path{3.5, 0.3, 60.0, -3.5};
  const SpeedRamp ego{20.0, 20.0, 2.0, 4.0};

  const GapTracks tracks = gap_tracks(lane, gap, 6.0, no_accel);
  ASSERT_EQ(tracks.leaders.size(), 2u);
  EXPECT_TRUE(tracks.followers.empty());
  // Vehicle 1 at constant speed (as if vehicle 2 were not there) leaves the ego room.
  const GapTracks leader_only{{}, {leader_track(lane[0], 0.0)}, {}};
  EXPECT_TRUE(occupancy_clear(s, 0.0, -3.5, path, ego, OccupancyInstants::over(6.0), leader_only, 0.0));
  EXPECT_FALSE(occupancy_clear(s, 0.0, -3.5, path, ego, OccupancyInstants::over(6.0), tracks, 0.0));
}

TEST(OccupancyClear, GapTracksSplitTheLaneAtTheGap) {
  // Lane order (position, then id): 3 at -50, 1 at 0, 4 at 0, 2 at 40. Gap (follower 1, leader 4).
  const std::vector<MainLaneVehicle> lane = {lane_vehicle(2, 40.0, 20.0), lane_vehicle(1, 0.0, 20.0),
                                             lane_vehicle(4, 0.0, 20.0), lane_vehicle(3, -50.0, 20.0)};
  const GapTracks t = gap_tracks(lane, LaneGap{lane[1], lane[2]}, 4.0, no_accel);
  ASSERT_EQ(t.followers.size(), 2u);  // 1 and 3
  ASSERT_EQ(t.leaders.size(), 2u);    // 4 and 2
  EXPECT_DOUBLE_EQ(t.followers[0].x0_m + t.followers[1].x0_m, -50.0);
  EXPECT_DOUBLE_EQ(t.leaders[0].x0_m + t.leaders[1].x0_m, 40.0);
  // Followers accelerate at a_max for rho/2 = 2 s, then hold: 20 -> 24 m/s.
  EXPECT_DOUBLE_EQ(t.followers[0].v_at(1.0), 22.0);
  EXPECT_DOUBLE_EQ(t.followers[0].v_at(5.0), 24.0);
}

// The ego stands at X = 0 with a vehicle passing it at 30 m/s from X = -10 (the gap's leader: the
// ego merges behind it). The path starts on the side lane's centre (Y = -3.5, 3.5 m from the
// lane centre > D_lat), so at t = 0 the ego on its path is laterally safe and the vehicle behind
// it does not matter. An ego that is really at Y = -1.9 (1.9 m < D_lat) is not on its path yet:
// at t = 0 it is laterally unsafe with a vehicle 10 m behind, not D_lon ahead of it.
TEST(OccupancyClear, AnEgoNearerTheLaneThanThePathStartIsCheckedWhereItIs) {
  const Scenario s = road_only();
  const std::vector<MainLaneVehicle> lane = {lane_vehicle(1, -10.0, 30.0)};
  const GapTracks tracks = gap_tracks(lane, LaneGap{std::nullopt, lane[0]}, 6.0, no_accel);
  const Sigmoid path{3.5, 0.3, 30.0, -3.5};
  const SpeedRamp ego{5.0, 5.0, 2.0, 4.0};
  EXPECT_TRUE(occupancy_clear(s, 0.0, -3.5, path, ego, OccupancyInstants::over(6.0), tracks, 0.0));
  EXPECT_FALSE(occupancy_clear(s, 0.0, -1.9, path, ego, OccupancyInstants::over(6.0), tracks, 0.0));
}

// A committed merge's re-check takes kOccupancyRecheckLateralSlackM (0.1 m) of the tracking
// margin: the nearest a vehicle of the next lane over may drive to the ego's sharp merge of
// AMergeKeepsDLatFromAVehicleAheadInTheNextLane (its lane's centre, found by bisection) is 0.1 m
// nearer for the re-check than for a new candidate.
TEST(OccupancyClear, TheRecheckOfACommittedMergeTakesItsLateralSlackOfTheTrackingMargin) {
  Scenario s = road_only();
  s.params.rss.response_time_s = 0.8;
  s.ego.limits.lat_brake_min_mps2 = 0.8;
  const SpeedRamp ego{25.0, 25.0, 2.0, 4.0};
  const Sigmoid sharp{3.5, 0.08, 50.0, -3.5};
  const auto clear_with = [&](double lane_y_m, double slack_m) {
    GapTracks tracks;
    tracks.beside = {beside_track(lane_vehicle(2, 90.0, 20.0), lane_y_m, 0.0, 0.0)};
    return occupancy_clear(s, 0.0, -3.5, sharp, ego, OccupancyInstants::over(4.0), tracks, 0.0, nullptr, slack_m);
  };
  const auto nearest_clear_m = [&](double slack_m) {
    double blocked = 3.5, clear = 10.0;
    EXPECT_FALSE(clear_with(blocked, slack_m));
    EXPECT_TRUE(clear_with(clear, slack_m));
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (blocked + clear);
      (clear_with(mid, slack_m) ? clear : blocked) = mid;
    }
    return clear;
  };
  const double planned_m = nearest_clear_m(0.0), rechecked_m = nearest_clear_m(kOccupancyRecheckLateralSlackM);
  EXPECT_NEAR(planned_m - rechecked_m, 0.1, 1e-9);
  EXPECT_FALSE(clear_with(planned_m - 0.05, 0.0));
  EXPECT_TRUE(clear_with(planned_m - 0.05, kOccupancyRecheckLateralSlackM));
}


// Ego at 25 m/s, P_c at X = 50 m (t = 2 s, rho = 4 s); a vehicle in the next lane over (centre
// Y = 3.5) starts 90 m ahead at 20 m/s, so at P_c it is 80 m ahead, not D_lon (88.9 m with
// T = 0.8 s) ahead. With a weak lateral brake (0.8 m/s2) the ego's lateral speed at P_c on a
// kappa = 0.08 sigmoid (25 * 3.5 * 0.08 / 4 = 1.75 m/s) makes D_lat 5.8 m, more than the 5.25 m
// to that lane's centre: an RSS-dangerous situation with the ego as the rear vehicle (a campaign
// finding: the ego's proper response then left its merge). A flat sigmoid (kappa 0.03: 0.66 m/s,
// D_lat 3.1 m) stays clear.
TEST(OccupancyClear, AMergeKeepsDLatFromAVehicleAheadInTheNextLane) {
  Scenario s = road_only();
  s.params.rss.response_time_s = 0.8;
  s.ego.limits.lat_brake_min_mps2 = 0.8;
  const SpeedRamp ego{25.0, 25.0, 2.0, 4.0};
  GapTracks tracks;  // an empty target lane
  const Sigmoid sharp{3.5, 0.08, 50.0, -3.5}, flat{3.5, 0.03, 50.0, -3.5};
  EXPECT_TRUE(occupancy_clear(s, 0.0, -3.5, sharp, ego, OccupancyInstants::over(4.0), tracks, 0.0));
  tracks.beside.push_back(beside_track(lane_vehicle(2, 90.0, 20.0), 3.5, 0.0, 0.0));
  EXPECT_FALSE(occupancy_clear(s, 0.0, -3.5, sharp, ego, OccupancyInstants::over(4.0), tracks, 0.0));
  EXPECT_TRUE(occupancy_clear(s, 0.0, -3.5, flat, ego, OccupancyInstants::over(4.0), tracks, 0.0));
  // Behind the ego it is the rear vehicle of any such situation: no constraint on the merge.
  tracks.beside = {beside_track(lane_vehicle(2, -30.0, 20.0), 3.5, 0.0, 0.0)};
  EXPECT_TRUE(occupancy_clear(s, 0.0, -3.5, sharp, ego, OccupancyInstants::over(4.0), tracks, 0.0));
}

// A leader behind a fast vehicle that must stop for a stopped one further ahead (a campaign
// finding, 1: 29 m/s, 2: 36.6 m/s, 3 stopped 198 m ahead of 2):
//
//   [1] 29 m/s -- 29.3 m -- [2] 36.6 m/s ---------------- 197.75 m ---------------- [3] stopped
//
// Vehicle 2 needs 36.6^2 / (2 (197.75 - 4.8 - 2)) = 3.51 m/s2 to stop 2 m behind vehicle 3, so it
// is predicted braking, and vehicle 1 is predicted to stop behind it, never past vehicle 3: with
// vehicle 2 at constant speed, vehicle 1 was predicted at 29 m/s until vehicle 2 was seen braking,
// and the merge planned behind vehicle 1 was aborted then.
TEST(LeaderTrack, ALeaderIsPredictedBehindEveryVehicleAheadOfIt) {
  const std::vector<MainLaneVehicle> lane = {lane_vehicle(1, -20.0, 29.0), lane_vehicle(2, 9.3, 36.6),
                                             lane_vehicle(3, 207.05, 0.0)};
  EXPECT_NEAR(chained_accel_mps2(lane, lane[1], no_accel), -36.6 * 36.6 / (2.0 * (197.75 - 4.8 - 2.0)), 1e-9);
  EXPECT_DOUBLE_EQ(chained_accel_mps2(lane, lane[2], no_accel), 0.0);
  const Track t = leader_track(lane[0], 0.0, &lane[1], chained_accel_mps2(lane, lane[1], no_accel));
  EXPECT_DOUBLE_EQ(t.v_at(60.0), 0.0);
  EXPECT_LE(t.x_at(60.0), 207.05 - 2.0 * (4.8 + 2.0) + 1e-9);
  // The tracks of a merge behind vehicle 1 (gap_tracks) predict it the same way.
  const GapTracks tracks = gap_tracks(lane, LaneGap{std::nullopt, lane[0]}, 4.0, no_accel);
  ASSERT_EQ(tracks.leaders.size(), 3u);
  EXPECT_DOUBLE_EQ(tracks.leaders[0].x_at(60.0), t.x_at(60.0));
}

// A vehicle of the next lane may be anywhere between its hardest braking and its nominal
// motion, so a check a cycle later, when it has kept its acceleration, is no harder than the
// first: its hardest braking from then on stops it farther ahead, at a higher speed, and its
// nominal position is where it was predicted. With a weak lateral brake and a long response time
// (D_lat reaches across a lane), a merge clear of the next lane at its decision stays clear at
// every later re-check while the ego follows its plan and the other lane's vehicles keep their
// speed or their acceleration (up to the speed limit). (The braking position alone decided
// "ahead": a vehicle the ego passed once stopped, but not when it kept braking a little later,
// aborted each merge a second after its decision; smoothness_oscillation. A vehicle accelerating
// beside the ego, predicted at constant speed, came out ahead of it a cycle after each decision.)
RC_GTEST_PROP(OccupancyClear, AMergeClearOfTheNextLaneStaysClearWhileItsVehiclesKeepTheirAcceleration, ()) {
  Scenario s = road_only();
  s.params.rss.response_time_s = *rc::gen::inRange(5, 15) / 10.0;
  s.ego.limits.lat_brake_min_mps2 = *rc::gen::inRange(3, 10) / 10.0;
  const double v0 = *rc::gen::inRange(0, 300) / 10.0;
  const SpeedRamp ego{v0, *rc::gen::inRange(0, 300) / 10.0, 2.0, 4.0};
  const double rho_s = *rc::gen::inRange(20, 100) / 10.0;
  const Sigmoid path{3.5, *rc::gen::inRange(5, 30) / 100.0, ego.distance_at_m(0.5 * rho_s), -3.5};
  const double cap_mps = 35.0;
  struct Beside {
    MainLaneVehicle v;
    double accel_mps2;
  };
  std::vector<Beside> beside;
  for (int i = 0, n = *rc::gen::inRange(1, 3); i < n; ++i)
    beside.push_back({lane_vehicle(10 + i, *rc::gen::inRange(-300, 1500) / 10.0, *rc::gen::inRange(0, 350) / 10.0),
                      *rc::gen::element(0, 0, 1, 5, 10, 20) / 10.0});
  const auto tracks_at = [&](double dt_s) {
    GapTracks tracks;
    for (Beside b : beside) {
      const SpeedRamp kept{b.v.speed_mps, std::max(b.v.speed_mps, cap_mps), std::max(b.accel_mps2, 1e-9), 1.0};
      b.v.x_m += kept.distance_at_m(dt_s);
      b.v.speed_mps = kept.speed_at_mps(dt_s);
      const bool accelerating = b.accel_mps2 > 0.0 && b.v.speed_mps < cap_mps;
      tracks.beside.push_back(beside_track(b.v, 3.5, accelerating ? b.accel_mps2 : 0.0, cap_mps));
    }
    return tracks;
  };
  const OccupancyInstants decision = OccupancyInstants::over(rho_s);
  RC_PRE(occupancy_clear(s, 0.0, -3.5, path, ego, decision, tracks_at(0.0), 0.0));
  for (int cycle = 1; cycle * 0.1 < rho_s; ++cycle) {
    const double dt_s = cycle * 0.1;
    const double x_m = ego.distance_at_m(dt_s);
    const SpeedRamp rest{ego.speed_at_mps(dt_s), ego.v_target_mps, 2.0, 4.0};
    const OccupancyInstants recheck{decision.step_s, dt_s, rho_s - dt_s};
    RC_ASSERT(occupancy_clear(s, x_m, path.y_at_m(x_m), path, rest, recheck, tracks_at(dt_s), 0.0));
  }
}

// One of the lane's gaps, open ends included (a RapidCheck draw).
LaneGap any_gap_of(const std::vector<MainLaneVehicle>& lane) {
  const std::vector<LaneGap> gaps = enumerate_gaps(lane);
  return gaps[static_cast<std::size_t>(*rc::gen::inRange(0, static_cast<int>(gaps.size())))];
}

// The memo (per-instant D_lon blocking shared by the kappa candidates of one speed profile, and
// the hint that visits the last blocking instant first) saves work only: over a run of checks
// like the planner's (several speed profiles, several kappa each, one memo throughout) every
// answer equals the plain check's.
// A leader cannot drive through the vehicle ahead of it. Leader at X = 0, 25 m/s; a vehicle
// stopped at X = 200 (both 4.8 m long): the leader is predicted to brake uniformly,
// 25^2 / (2 (200 - 4.8 - 2)) = 1.62 m/s2, and to stop 2 m (kLeaderStandoffM) behind it.
//
//   leader 25 m/s ->  . . . . . . . . . . . . . . [stops at 193.2] 2 m [stopped 200]
TEST(LeaderTrack, ALeaderBehindAStoppedVehicleIsPredictedToStopBehindIt) {
  const MainLaneVehicle leader = lane_vehicle(1, 0.0, 25.0), stopped = lane_vehicle(2, 200.0, 0.0);
  EXPECT_NEAR(braking_behind_mps2(leader, stopped), 625.0 / (2.0 * 193.2), 1e-9);
  const Track t = leader_track(leader, 0.0, &stopped);
  EXPECT_NEAR(t.x_at(60.0), 193.2, 1e-6);
  EXPECT_DOUBLE_EQ(t.v_at(60.0), 0.0);
  // Alone, or seen braking harder than that, it is predicted as before.
  EXPECT_DOUBLE_EQ(leader_track(leader, 0.0).x_at(10.0), 250.0);
  EXPECT_NEAR(leader_track(leader, -5.0, &stopped).x_at(60.0), 62.5, 1e-6);
}

// A vehicle crawling to a stop, seen braking hard for an instant (a stopped driver's controller
// jitters at a few cm/s), asks of the vehicle behind it only the braking that stops it behind
// where the crawler stops, not the crawler's own rate: leader at X = 0, 16 m/s; the crawler at
// X = 150, 0.05 m/s, seen braking at 3.5 m/s2 (stops within 0.4 mm). Room to its stop:
// 150 - 4.8 - 2 + 0.05^2 / 7 m, so 16^2 / (2 * that) = 0.894 m/s2, not 3.5 + 15.95^2 / (2 * 143.2).
TEST(LeaderTrack, BehindAVehicleCrawlingToAStopTheBrakingIsWhatStoppingBehindItNeeds) {
  const MainLaneVehicle leader = lane_vehicle(1, 0.0, 16.0), crawler = lane_vehicle(2, 150.0, 0.05);
  const double room_m = 150.0 - 4.8 - kLeaderStandoffM + 0.05 * 0.05 / 7.0;
  EXPECT_NEAR(braking_behind_mps2(leader, crawler, -3.5), 256.0 / (2.0 * room_m), 1e-9);
  const Track t = leader_track(leader, 0.0, &crawler, -3.5);
  EXPECT_NEAR(t.x_at(60.0), room_m, 1e-6);
}

// A leader far behind a faster vehicle seen braking need not brake for it within the merge: at
// its speed it is still RCPP eq. (1)'s D_lon behind it at the horizon (LeaderHorizon). Leader at
// X = 0, 20.7 m/s; the vehicle ahead at X = 82.4, 26.4 m/s, seen braking at 2.1 m/s2 (a campaign's
// bounded-random driver braking in bursts, remembered). Over 8 s it covers 26.4 * 8 - 2.1 * 64 / 2
// = 144 m, the leader 165.6 m: 60.8 m apart, D_lon (T = 0.1 s) is 17.9 m. Predicted to its
// stop, it asks the leader to brake from now on.
TEST(LeaderTrack, ALeaderThatKeepsDLonBehindTheVehicleAheadUntilTheHorizonHoldsItsSpeed) {
  const MainLaneVehicle leader = lane_vehicle(1, 0.0, 20.7), ahead = lane_vehicle(2, 82.4, 26.4);
  const LeaderHorizon merge{8.0, 0.1};
  EXPECT_DOUBLE_EQ(braking_behind_mps2(leader, ahead, -2.1, merge), 0.0);
  EXPECT_DOUBLE_EQ(leader_track(leader, 0.0, &ahead, -2.1, merge).x_at(8.0), 165.6);
  EXPECT_GT(braking_behind_mps2(leader, ahead, -2.1), 0.5);  // no horizon: braking to a stop behind it
  EXPECT_GT(braking_behind_mps2(leader, ahead, -2.1, LeaderHorizon{30.0, 0.1}), 0.5);
  // Braking the leader is seen doing is predicted whatever the horizon.
  EXPECT_LT(leader_track(leader, -3.0, &ahead, -2.1, merge).x_at(8.0), 165.6 - 90.0);
}

// Two vehicles following at the same speed a little closer than kLeaderStandoffM (bumpers 1.8 m
// apart): the one behind is not braking, and a leader behind it is not predicted to stop. (Taken
// as "no room left", 1e3 m/s2, it stopped every vehicle behind at once: a campaign's gap two
// vehicles back stayed closed for seconds while `progress` offered it.) One closing in, or behind
// a vehicle seen braking, still has no room.
TEST(LeaderTrack, AVehicleFollowingInsideTheStandoffAtTheSameSpeedIsNotBraking) {
  const MainLaneVehicle truck = lane_vehicle(3, 140.0, 19.8), close = lane_vehicle(2, 140.0 - 4.8 - 1.8, 19.8);
  EXPECT_DOUBLE_EQ(braking_behind_mps2(close, truck), 0.0);
  const std::vector<MainLaneVehicle> lane = {lane_vehicle(1, 76.5, 15.8), close, truck};
  EXPECT_DOUBLE_EQ(chained_accel_mps2(lane, lane[1], no_accel), 0.0);
  EXPECT_DOUBLE_EQ(leader_track(lane[0], 0.0, &lane[1], chained_accel_mps2(lane, lane[1], no_accel)).v_at(5.0), 15.8);
  EXPECT_DOUBLE_EQ(braking_behind_mps2(lane_vehicle(2, close.x_m, 20.0), truck), 1e3);
  EXPECT_DOUBLE_EQ(braking_behind_mps2(close, truck, -2.0), 1e3);
}

// Predicted at its speed under a horizon, a leader never comes within kLeaderStandoffM of the
// vehicle ahead (braking as seen) before the horizon, and is RCPP eq. (1)'s D_lon (with the
// speeds of now) behind it at the horizon: the gap between them is concave in time, so it is
// smallest now or at the horizon.
RC_GTEST_PROP(LeaderTrack, ALeaderHoldingItsSpeedUnderAHorizonKeepsTheStandoffUntilIt, ()) {
  const MainLaneVehicle leader = lane_vehicle(1, 0.0, *rc::gen::inRange(0, 400) / 10.0);
  const MainLaneVehicle ahead = lane_vehicle(2, *rc::gen::inRange(50, 3000) / 10.0, *rc::gen::inRange(0, 400) / 10.0);
  const double ahead_accel_mps2 = -*rc::gen::inRange(0, 100) / 10.0;
  const LeaderHorizon h{*rc::gen::inRange(0, 300) / 10.0, *rc::gen::inRange(0, 20) / 10.0};
  RC_PRE(ahead.x_m - leader.x_m > 4.8 + kLeaderStandoffM);  // outside the standoff now
  RC_PRE(braking_behind_mps2(leader, ahead, ahead_accel_mps2, h) == 0.0);
  const Track l = leader_track(leader, 0.0, &ahead, ahead_accel_mps2, h);
  const Track a = leader_track(ahead, ahead_accel_mps2);
  for (int k = 0; k <= 100; ++k) {
    const double t_s = h.horizon_s * k / 100.0;
    RC_ASSERT(a.x_at(t_s) - l.x_at(t_s) >= 4.8 + kLeaderStandoffM - 1e-9);
  }
  if (braking_behind_mps2(leader, ahead, ahead_accel_mps2) == 0.0) return;  // no braking needed anyway
  const Limits lim{};
  const double d_lon_m = rss_longitudinal_m({leader.speed_mps, ahead.speed_mps, 4.8, 4.8, h.response_time_s,
                                             lim.accel_max_mps2, lim.brake_min_mps2, lim.brake_max_mps2});
  RC_ASSERT(a.x_at(h.horizon_s) - l.x_at(h.horizon_s) >= d_lon_m - 1e-9);
}

// The braking predicted behind a vehicle (at constant speed, or braking to a stop at the rate
// seen) is the least uniform braking that keeps the standoff: 2 % less and the track comes closer
// to that vehicle than the standoff at some instant.
RC_GTEST_PROP(LeaderTrack, TheBrakingBehindIsTheLeastThatKeepsTheStandoff, ()) {
  const MainLaneVehicle leader = lane_vehicle(1, 0.0, *rc::gen::inRange(0, 400) / 10.0);
  const MainLaneVehicle ahead = lane_vehicle(2, *rc::gen::inRange(100, 3000) / 10.0, *rc::gen::inRange(0, 400) / 10.0);
  const double ahead_accel_mps2 = -*rc::gen::inRange(0, 100) / 10.0;
  const double need_mps2 = braking_behind_mps2(leader, ahead, ahead_accel_mps2);
  RC_PRE(need_mps2 > 0.05 && need_mps2 < 1e3);
  const double to_mps = ahead_accel_mps2 < -kLeaderBrakingMps2 ? 0.0 : ahead.speed_mps;
  const Track a = leader_track(ahead, ahead_accel_mps2);
  const auto least_room_m = [&](double brake_mps2) {
    const SpeedRamp motion{leader.speed_mps, to_mps, 1.0, brake_mps2};
    double least = std::numeric_limits<double>::infinity();
    // Until both have stopped, or the one ahead has reached its speed.
    const double until_s = leader.speed_mps / brake_mps2 + 1.0;
    for (double time_s = 0.0; time_s <= until_s; time_s += 0.01)
      least = std::min(least, a.x_at(time_s) - motion.distance_at_m(time_s) - ahead.length_m);
    return least;
  };
  RC_ASSERT(least_room_m(need_mps2) >= kLeaderStandoffM - 1e-6);
  RC_ASSERT(least_room_m(0.98 * need_mps2) < kLeaderStandoffM);
}

// Whatever the two vehicles' places, speeds and braking (the one ahead at least two car lengths
// ahead, at constant speed or braking to a stop at the rate seen), the leader's predicted track
// never comes closer to it than the standoff, bumper to bumper.
RC_GTEST_PROP(LeaderTrack, APredictedLeaderNeverPassesTheVehicleAheadOfIt, ()) {
  const MainLaneVehicle leader = lane_vehicle(1, 0.0, *rc::gen::inRange(0, 400) / 10.0);
  const MainLaneVehicle ahead = lane_vehicle(2, *rc::gen::inRange(100, 3000) / 10.0, *rc::gen::inRange(0, 400) / 10.0);
  const double observed_accel_mps2 = -*rc::gen::inRange(0, 100) / 10.0;
  const double ahead_accel_mps2 = -*rc::gen::inRange(0, 100) / 10.0;
  const Track t = leader_track(leader, observed_accel_mps2, &ahead, ahead_accel_mps2);
  const Track a = leader_track(ahead, ahead_accel_mps2);  // as seen: constant, or braking to a stop
  for (double time_s = 0.0; time_s <= 60.0; time_s += 0.05) {
    const double room_m = a.x_at(time_s) - t.x_at(time_s) - ahead.length_m;
    RC_ASSERT(room_m >= kLeaderStandoffM - 1e-6);
  }
}

// A merge drawn from an ego off its side lane's centre (merge_sigmoid) starts where the ego may
// still be moving: its tracking margin grows with the path's progress from the side lane's
// centre, not from its own start. With T = 1 s, D_lat at rest is 0.1 + 1.9 + 2 (0.2 / 2 +
// 0.2^2 / 1.6) = 2.25 m. Ego at Y = -2.9 (0.65 m outside it, its corner 0.1 m short of the lane
// line's margin), 10 m/s, P_c 150 m ahead; the gap's leader 60 m behind at 30 m/s, not D_lon
// clear of it while it passes: held at its offset the ego lies inside the 0.75 m margin.
TEST(OccupancyClear, APathFromOffTheCentreKeepsTheTrackingMarginOfItsOffset) {
  Scenario s = road_only();
  s.params.rss.response_time_s = 1.0;
  const std::vector<MainLaneVehicle> lane = {lane_vehicle(1, -60.0, 30.0)};
  const GapTracks tracks = gap_tracks(lane, LaneGap{std::nullopt, lane[0]}, 8.0, no_accel);
  const SpeedRamp ego{10.0, 10.0, 2.0, 4.0};
  const OccupancyInstants when = OccupancyInstants::over(8.0);
  EXPECT_FALSE(occupancy_clear(s, 0.0, -2.9, merge_sigmoid(3.5, -2.9, 0.2, 150.0), ego, when, tracks, 1.5));
  EXPECT_TRUE(occupancy_clear(s, 0.0, -3.5, merge_sigmoid(3.5, -3.5, 0.2, 150.0), ego, when, tracks, 1.5));
}

RC_GTEST_PROP(OccupancyClear, TheMemoNeverChangesTheAnswer, ()) {
  const Scenario s = road_only();
  std::vector<MainLaneVehicle> lane;
  const int n = *rc::gen::inRange(1, 4);
  for (int i = 0; i < n; ++i)
    lane.push_back(lane_vehicle(i + 1, *rc::gen::inRange(-800, 1200) / 10.0, *rc::gen::inRange(0, 350) / 10.0));
  const LaneGap gap = any_gap_of(lane);
  const double rho_s = *rc::gen::inRange(20, 120) / 10.0;
  GapTracks tracks = gap_tracks(lane, gap, rho_s, no_accel);
  const int n_beside = *rc::gen::inRange(0, 3);
  for (int i = 0; i < n_beside; ++i)
    tracks.beside.push_back(beside_track(
        lane_vehicle(10 + i, *rc::gen::inRange(-800, 1200) / 10.0, *rc::gen::inRange(0, 350) / 10.0), 3.5, 0.0, 0.0));
  const double v0 = *rc::gen::inRange(0, 300) / 10.0;
  OccupancyMemo memo;
  for (int speed = 0; speed < 3; ++speed) {
    const SpeedRamp ego{v0, *rc::gen::inRange(0, 300) / 10.0, 2.0, 4.0};
    const double pc_m = ego.distance_at_m(0.5 * rho_s);
    memo.forget_ramp();
    for (int k = 0; k < 4; ++k) {
      const Sigmoid path{3.5, *rc::gen::inRange(5, 150) / 100.0, pc_m, -3.5};
      const bool plain = occupancy_clear(s, 0.0, -3.5, path, ego, OccupancyInstants::over(rho_s), tracks, 1.5);
      RC_ASSERT(occupancy_clear(s, 0.0, -3.5, path, ego, OccupancyInstants::over(rho_s), tracks, 1.5, &memo) == plain);
    }
  }
}

// The same with vehicles of mixed widths (each track's extra lateral room differs, so the two parts
// of an instant's Blocking and the widest extra over all tracks differ), an ego off its lane's
// centre on the merge path drawn from there (merge_sigmoid: its midpoint differs by kappa, its
// lane-line crossing does not), and a re-check's instants (elapsed since the decision): the
// memo's shortcuts (an instant clear of every vehicle skips the path; a known Blocking decides
// without the widest extra) agree with the plain check.
RC_GTEST_PROP(OccupancyClear, TheMemoNeverChangesTheAnswerWithMixedWidths, ()) {
  const Scenario s = road_only();
  const auto vehicle = [](int id) {
    MainLaneVehicle v = lane_vehicle(id, *rc::gen::inRange(-800, 1200) / 10.0, *rc::gen::inRange(0, 350) / 10.0);
    v.width_m = *rc::gen::inRange(15, 30) / 10.0;
    return v;
  };
  std::vector<MainLaneVehicle> lane;
  const int n = *rc::gen::inRange(1, 4);
  for (int i = 0; i < n; ++i) lane.push_back(vehicle(i + 1));
  const LaneGap gap = any_gap_of(lane);
  const double rho_s = *rc::gen::inRange(20, 120) / 10.0;
  GapTracks tracks = gap_tracks(lane, gap, rho_s, no_accel);
  const int n_beside = *rc::gen::inRange(0, 3);
  for (int i = 0; i < n_beside; ++i) tracks.beside.push_back(beside_track(vehicle(10 + i), 3.5, 0.0, 0.0));
  const double ego_y_m = -3.5 + *rc::gen::inRange(0, 15) / 10.0;
  const double step_s = rho_s / kOccupancySamples;
  const OccupancyInstants when{step_s, *rc::gen::inRange(0, 20) * step_s * 0.5, rho_s * *rc::gen::inRange(5, 15) / 10.0};
  const double v0 = *rc::gen::inRange(0, 300) / 10.0;
  OccupancyMemo memo;
  for (int speed = 0; speed < 3; ++speed) {
    const SpeedRamp ego{v0, *rc::gen::inRange(0, 300) / 10.0, 2.0, 4.0};
    const double pc_m = ego.distance_at_m(0.5 * rho_s);
    memo.forget_ramp();
    for (int k = 0; k < 6; ++k) {
      const Sigmoid path = merge_sigmoid(3.5, ego_y_m, *rc::gen::inRange(5, 150) / 100.0, pc_m);
      const bool plain = occupancy_clear(s, 0.0, ego_y_m, path, ego, when, tracks, 1.5);
      RC_ASSERT(occupancy_clear(s, 0.0, ego_y_m, path, ego, when, tracks, 1.5, &memo) == plain);
    }
  }
}

// Defaults: sideslip judged from 2 m/s, so a crawl is up to 1.4 m/s; l_r 1.6 m, L 2.8 m, steering
// 0.5 rad. Above a crawl the path's curvature is capped at tan(0.025)/1.6 = 0.0156/m (kappa 0.215/m
// on W = 3.5 m), at a crawl at tan(0.5)/5.6 = 0.0975/m (kappa 0.538/m).
TEST(KappaCap, ACrawlIsCappedByHalfTheSteeringAbilityAlone) {
  const Scenario s = road_only();
  const double crawl_mps = crawl_speed_mps(s);
  EXPECT_DOUBLE_EQ(crawl_mps, 1.4);
  EXPECT_DOUBLE_EQ(path_curvature_cap_per_m(s, crawl_mps + 0.01), path_curvature_cap_per_m(s));
  EXPECT_NEAR(path_curvature_cap_per_m(s, crawl_mps), std::tan(0.5) / 5.6, 1e-12);
  EXPECT_NEAR(kappa_cap_per_m(s, crawl_mps), 0.538, 1e-3);
  EXPECT_NEAR(kappa_cap_per_m(s, 10.0), 0.215, 1e-3);
}

// The sharpest merge curves as far as the path tracker steers (a kinematic sideslip of 0.035 rad
// with the ego's l_r: tan(0.035)/1.6 = 0.0219/m, kappa 0.255/m), never beyond half the steering
// ability, and never less than the cap; at a crawl the crawl's cap.
TEST(KappaCap, TheSharpestMergeCurvesWithinThePathTrackersEnvelope) {
  Scenario s = road_only();
  EXPECT_NEAR(merge_curvature_cap_per_m(s), std::tan(kPathTrackerSideslipRad) / s.ego.dynamics.cg_to_rear_m, 1e-12);
  EXPECT_NEAR(kappa_sharpest_per_m(s, 10.0), 0.255, 1e-3);
  EXPECT_DOUBLE_EQ(kappa_sharpest_per_m(s, crawl_speed_mps(s)), kappa_cap_per_m(s, crawl_speed_mps(s)));
  s.ego.dynamics.steer_max_rad = 0.05;  // half the steering binds
  EXPECT_NEAR(merge_curvature_cap_per_m(s), std::tan(0.05) / (2.0 * s.ego.dynamics.wheelbase_m()), 1e-12);
  EXPECT_DOUBLE_EQ(kappa_sharpest_per_m(s, 10.0), kappa_cap_per_m(s, 10.0));
}

// An ego at rest with 16 m to P_c (the defaults' ramp reaches it in 4 s) needs kappa >= ln(49)/16
// = 0.243/m: above the cap (0.215/m), within the tracker's envelope (0.255/m). The range then
// reaches up to the envelope; where the cap fits, the range ends at it.
TEST(KappaCap, OnlyAMergeThatDoesNotFitUnderTheCapMayCurveUpToTheTrackersEnvelope) {
  Scenario s = road_only();
  s.road.side_lane_end_x_m = 200.0;
  const SpeedRamp from_rest{0.0, 8.0, 2.0, 4.0};
  const KappaRange tight = kappa_range_for(s, 16.0, 0.0, 40.0, from_rest, 0.0);
  ASSERT_TRUE(tight.has_value());
  EXPECT_NEAR(tight->first, std::log(49.0) / 16.0, 1e-9);
  EXPECT_GT(tight->first, kappa_cap_per_m(s, 8.0));
  EXPECT_LE(tight->second, kappa_sharpest_per_m(s, 8.0));
  const KappaRange roomy = kappa_range_for(s, 30.0, 0.0, 70.0, SpeedRamp{8.0, 8.0, 2.0, 4.0}, 0.0);
  ASSERT_TRUE(roomy.has_value());
  EXPECT_LE(roomy->second, kappa_cap_per_m(s, 8.0));
}

// An ego at rest 22 m before the side lane's end (its front 19.6 m): a sigmoid with P_c 8 m ahead,
// complete 17 m ahead, needs kappa >= ln(49)/8 = 0.486/m. Driven at a crawl it is admissible; at
// 5 m/s the sideslip cap (0.215/m) rules it out.
TEST(KappaCap, AnEgoAtRestNearTheSideLaneEndCanMergeAtACrawl) {
  Scenario s = road_only();
  s.road.side_lane_end_x_m = 22.0;
  const KappaRange crawl = kappa_range_for(s, 8.0, 0.0, 17.0, SpeedRamp{0.0, 1.3, 2.0, 4.0}, 0.0);
  ASSERT_TRUE(crawl.has_value());
  EXPECT_NEAR(crawl->first, std::log(49.0) / 8.0, 1e-9);
  EXPECT_LE(crawl->first, crawl->second);
  EXPECT_FALSE(kappa_range_for(s, 8.0, 0.0, 17.0, SpeedRamp{0.0, 5.0, 2.0, 4.0}, 0.0).has_value());
}

// An ego at rest with 10 m to P_c, a quarter of the lane change (the defaults' W = 3.5 m) toward
// the main lane: from the 2 % point kappa >= ln(49)/10 = 0.389/m, beyond the tracker's envelope
// (0.255/m at 8 m/s); from its own progress, kappa >= ln(3)/10 = 0.110/m. A ramp that stays at a
// crawl, and one that starts at speed, keep the 2 % point, and the own start stays under the cap.
TEST(KappaCap, AnEgoStartingAtRestMayStartItsSigmoidAtItsOwnLateralProgress) {
  Scenario s = road_only();
  s.road.side_lane_end_x_m = 200.0;
  const double quarter = 0.25;
  const SpeedRamp from_rest{0.0, 8.0, 2.0, 4.0};
  EXPECT_FALSE(kappa_range_for(s, 10.0, 0.0, 60.0, from_rest, 0.0).has_value());
  const KappaRange own = kappa_range_for(s, 10.0, 0.0, 60.0, from_rest, 0.0, 0.0, quarter);
  ASSERT_TRUE(own.has_value());
  EXPECT_NEAR(own->first, std::max(rcpp_params(s).kappa_min_per_m, std::log(3.0) / 10.0), 1e-9);
  const KappaRange crawl = kappa_range_for(s, 10.0, 0.0, 60.0, SpeedRamp{0.0, 1.3, 2.0, 4.0}, 0.0, 0.0, quarter);
  ASSERT_TRUE(crawl.has_value());
  EXPECT_NEAR(crawl->first, std::log(49.0) / 10.0, 1e-9);
  EXPECT_FALSE(kappa_range_for(s, 10.0, 0.0, 60.0, SpeedRamp{8.0, 8.0, 2.0, 4.0}, 0.0, 0.0, quarter).has_value());
  // With P_c 5 m ahead the own start needs ln(3)/5 = 0.220/m: above the cap (0.215/m), where a
  // path is tracked behind it; not granted (from the 2 % point it would need 0.778/m).
  ASSERT_GT(std::log(3.0) / 5.0, kappa_cap_per_m(s, from_rest));
  EXPECT_LT(std::log(3.0) / 5.0, kappa_sharpest_per_m(s, 8.0));
  EXPECT_FALSE(kappa_range_for(s, 5.0, 0.0, 60.0, from_rest, 0.0, 0.0, quarter).has_value());
}

// Vehicle 2, the gap's follower, stands at X = 90 m; vehicle 1 approaches it at 10 m/s from X = 0.
// As a follower alone vehicle 1 would be predicted past vehicle 2 (accelerating at 2 m/s2 for
// rho/2 = 3 s: 39 m at 3 s, 79 m at 6 s, 115 m at 9 s); behind it, it stays 6.8 m (half both
// lengths and the 2 m standoff) behind vehicle 2's own follower prediction, and at its speed there.
TEST(FollowerTrack, AVehicleBehindTheFollowerIsPredictedBehindIt) {
  const std::vector<MainLaneVehicle> lane = {lane_vehicle(1, 0.0, 10.0), lane_vehicle(2, 90.0, 0.0)};
  const LaneGap gap{lane[1], std::nullopt};
  const GapTracks tracks = gap_tracks(lane, gap, 6.0, no_accel);
  ASSERT_EQ(tracks.followers.size(), 2u);
  const Track& follower = tracks.followers[0].x0_m == 90.0 ? tracks.followers[0] : tracks.followers[1];
  const Track& behind = tracks.followers[0].x0_m == 90.0 ? tracks.followers[1] : tracks.followers[0];
  EXPECT_NEAR(follower.x_at(3.0), 99.0, 1e-9);
  EXPECT_NEAR(behind.x_at(3.0), 39.0, 1e-9);  // not yet at the follower: its own prediction
  EXPECT_NEAR(behind.v_at(3.0), 16.0, 1e-9);
  EXPECT_NEAR(behind.x_at(9.0), follower.x_at(9.0) - 6.8, 1e-9);
  EXPECT_NEAR(behind.v_at(9.0), follower.v_at(9.0), 1e-9);
  EXPECT_LT(behind.x_at(20.0), follower.x_at(20.0));
}

}  // namespace
}  // namespace mg
