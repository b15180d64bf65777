#include "sim/behaviour.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "sim/simulator.h"
#include "test_planners.h"

namespace mg {
namespace {

DriverInput free_road(double t, double speed) {
  DriverInput in;
  in.time_s = t;
  in.speed_mps = speed;
  return in;
}

// Drives one main-lane vehicle alone for duration_s; returns its speeds and applied accels.
struct Drive {
  std::vector<double> speed, accel;
};
Drive drive_alone(MainLaneDriver& driver, double v0, double duration_s, double dt = 0.02) {
  Drive r;
  VehicleState s;
  s.vx_mps = v0;
  for (int k = 0; k * dt < duration_s; ++k) {
    advance_on_lane(s, driver.accel_mps2(free_road(k * dt, s.vx_mps)), dt);
    r.speed.push_back(s.vx_mps);
    r.accel.push_back(s.accel_mps2);
  }
  return r;
}

TEST(Behaviour, IdmApproachesItsDesiredSpeedOnAFreeRoad) {
  MainVehicle v = test::vehicle(1, 0.0, 15.0, BehaviourType::kIdm);
  v.behaviour.desired_speed_mps = 25.0;
  MainLaneDriver driver(v, Road{}, Params{});
  const Drive r = drive_alone(driver, 15.0, 60.0);
  EXPECT_NEAR(r.speed.back(), 25.0, 0.5);
}

TEST(Behaviour, IdmBrakesBehindAStoppedLeader) {
  const Behaviour b;
  const Limits lim;
  const Leader stopped{2, 30.0, 0.0, 4.8, 8.0};
  EXPECT_LT(idm_accel_mps2(20.0, 20.0, stopped, 4.8, b, lim), -lim.brake_min_mps2);
}

TEST(Behaviour, AdvanceOnLaneNeverGoesBackwards) {
  VehicleState s;
  s.vx_mps = 1.0;
  advance_on_lane(s, -8.0, 0.5);
  EXPECT_EQ(s.vx_mps, 0.0);
  EXPECT_DOUBLE_EQ(s.x_m, 1.0 / 16.0);
  EXPECT_DOUBLE_EQ(s.accel_mps2, -2.0);
  advance_on_lane(s, -8.0, 0.5);
  EXPECT_DOUBLE_EQ(s.x_m, 1.0 / 16.0);
}

// Bounded-random traffic (and everyone around it) never applies more than it declares and
// never reverses, whatever the seed, limits and segment length.
RC_GTEST_PROP(Behaviour, BoundedRandomNeverExceedsItsDeclaredLimits, ()) {
  Scenario s = test::empty_scenario();
  s.params.sim.horizon_s = 40.0;
  const int n = *rc::gen::inRange(1, 5);
  for (int i = 0; i < n; ++i) {
    MainVehicle v = test::vehicle(i + 1, 30.0 * i, *rc::gen::inRange(0, 35), BehaviourType::kBoundedRandom);
    v.limits.accel_max_mps2 = *rc::gen::inRange(0, 60) / 10.0;
    v.limits.brake_max_mps2 = *rc::gen::inRange(10, 120) / 10.0;
    v.limits.brake_min_mps2 = v.limits.brake_max_mps2 * *rc::gen::inRange(1, 11) / 10.0;
    v.behaviour.seed = *rc::gen::arbitrary<std::uint32_t>();
    v.behaviour.segment_s = *rc::gen::inRange(1, 50) / 10.0;
    s.vehicles.push_back(v);
  }
  test::LaneKeepPlanner planner(-3.5, 20.0, 2.0);
  const Trace t = simulate(s, planner);
  for (const TraceStep& step : t.steps)
    for (std::size_t i = 0; i < step.others.size(); ++i) {
      const Limits& lim = s.vehicles[i].limits;
      RC_ASSERT(step.others[i].vx_mps >= 0.0);
      RC_ASSERT(step.others[i].accel_mps2 <= lim.accel_max_mps2 + 1e-12);
      RC_ASSERT(step.others[i].accel_mps2 >= -lim.brake_max_mps2 - 1e-12);
    }
}

TEST(Behaviour, BoundedRandomIsDrawnFromItsSeed) {
  MainVehicle v = test::vehicle(1, 0.0, 20.0, BehaviourType::kBoundedRandom);
  v.behaviour.seed = 7;
  MainLaneDriver a(v, Road{}, Params{}), b(v, Road{}, Params{});
  v.behaviour.seed = 8;
  MainLaneDriver c(v, Road{}, Params{});
  const Drive ra = drive_alone(a, 20.0, 20.0), rb = drive_alone(b, 20.0, 20.0), rd = drive_alone(c, 20.0, 20.0);
  EXPECT_EQ(ra.accel, rb.accel);
  EXPECT_NE(ra.accel, rd.accel);
}

V2vMessage request(CoopCase c, double vo_star_mps) {
  V2vMessage m;
  m.type = MessageType::kRequest;
  m.from_id = 0;
  m.to_id = 1;
  m.coop_case = c;
  m.target_speed_mps = vo_star_mps;
  return m;
}

// What a fresh driver of `v` answers to `r` delivered at time_s while at speed_mps behind
// `leader` (nothing when it does not answer).
std::optional<MessageType> answer_type(const MainVehicle& v, const Params& p, const V2vMessage& r, double time_s,
                                       double speed_mps, const std::optional<Leader>& leader) {
  MainLaneDriver driver(v, Road{}, p);
  const std::optional<V2vMessage> reply = driver.answer(r, time_s, speed_mps, leader);
  return reply ? std::optional<MessageType>(reply->type) : std::nullopt;
}

TEST(Behaviour, CooperativeResponderReachesRequestedSpeedWithinItsLimits) {
  const MainVehicle v = test::vehicle(1, 0.0, 20.0, BehaviourType::kCooperative);
  const Params p;  // rho_c = 1 s, b_min = 4, a_acc = 2
  {
    MainLaneDriver driver(v, Road{}, p);
    const auto reply = driver.answer(request(CoopCase::kEgoAhead, 16.5), 0.0, 20.0);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->type, MessageType::kAccept);
    EXPECT_EQ(reply->to_id, 0);
    const Drive r = drive_alone(driver, 20.0, 4.0);
    EXPECT_NEAR(r.speed.back(), 16.5, 0.05);
    for (double a : r.accel) EXPECT_GE(a, -v.limits.brake_min_mps2 - 1e-12) << "brakes at most b_min (Def. 2.1 B)";
  }
  {
    MainLaneDriver driver(v, Road{}, p);
    const auto reply = driver.answer(request(CoopCase::kEgoBehind, 21.5), 0.0, 20.0);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->type, MessageType::kAccept);
    const Drive r = drive_alone(driver, 20.0, 4.0);
    EXPECT_NEAR(r.speed.back(), 21.5, 0.05);
    for (double a : r.accel) EXPECT_LE(a, v.limits.accel_max_mps2 + 1e-12) << "accelerates at most a_acc (Def. 2.2 B)";
  }
}

// The speed-up of Def. 2.2 B is promised only where the vehicle ahead lets the responder reach
// it: a responder 170 m behind a stopped vehicle would be held back by its own gap keeping.
TEST(Behaviour, CooperativeResponderRefusesASpeedUpTheVehicleAheadWillNotLetItReach) {
  const MainVehicle v = test::vehicle(1, 0.0, 20.5, BehaviourType::kCooperative);
  const Params p;
  const Leader stopped{.id = 2, .distance_m = 173.0, .speed_mps = 0.0, .length_m = 4.8, .brake_max_mps2 = 8.0};
  const V2vMessage speed_up = request(CoopCase::kEgoBehind, 22.35);
  EXPECT_EQ(answer_type(v, p, speed_up, 0.0, 20.5, stopped), MessageType::kRefuse);
  EXPECT_EQ(answer_type(v, p, speed_up, 0.0, 20.5, std::nullopt), MessageType::kAccept)
      << "the same request with nobody ahead";
}

// Def. 2's responder rules read the promise as a position profile from the acceptance on, not
// only as a speed from t_r + rho_c + T: a responder whose gap keeping (a long time headway, 10 m
// behind a faster vehicle) brakes it at once falls behind that profile, though it is back at
// v_o* in time, so it refuses.
TEST(Behaviour, CooperativeResponderRefusesWhatItsGapKeepingWouldBreakAtOnce) {
  MainVehicle v = test::vehicle(1, 0.0, 22.0, BehaviourType::kCooperative);
  v.behaviour.time_headway_s = 2.3;
  v.behaviour.comfort_brake_mps2 = 4.0;
  Params p;
  p.planner.comm_threshold_s = 2.0;
  const Leader pulling_away{.id = 2, .distance_m = 14.8, .speed_mps = 30.0, .length_m = 4.8, .brake_max_mps2 = 4.0};
  const V2vMessage hold = request(CoopCase::kEgoBehind, 22.0);
  EXPECT_EQ(answer_type(v, p, hold, 0.1, 22.0, pulling_away), MessageType::kRefuse);
  Leader far = pulling_away;
  far.distance_m = 200.0;
  EXPECT_EQ(answer_type(v, p, hold, 0.1, 22.0, far), MessageType::kAccept)
      << "the same request with the vehicle ahead far away";
}

// A responder already on the side of v_o* the ego counts on holds its speed: speeding back up to
// a Def. 2.1 v_o* (or slowing to a Def. 2.2 one) would leave the profile ineq. (3)/(4) assume.
TEST(Behaviour, CooperativeResponderAlreadyOnTheRightSideOfTheSpeedHoldsIt) {
  const MainVehicle v = test::vehicle(1, 0.0, 20.0, BehaviourType::kCooperative);
  const Params p;
  for (const auto& [c, target] : {std::pair{CoopCase::kEgoAhead, 21.0}, std::pair{CoopCase::kEgoBehind, 19.0}}) {
    MainLaneDriver driver(v, Road{}, p);
    const auto reply = driver.answer(request(c, target), 0.0, 20.0);
    ASSERT_TRUE(reply);
    ASSERT_EQ(reply->type, MessageType::kAccept);
    const Drive r = drive_alone(driver, 20.0, 3.0);
    for (double speed : r.speed) EXPECT_DOUBLE_EQ(speed, 20.0) << to_string(c);
  }
}

TEST(Behaviour, CooperativeResponderRefusesAnUnreachableSpeed) {
  const MainVehicle v = test::vehicle(1, 0.0, 20.0, BehaviourType::kCooperative);
  MainLaneDriver driver(v, Road{}, Params{});
  const auto reply = driver.answer(request(CoopCase::kEgoAhead, 10.0), 0.0, 20.0);  // needs 10 m/s in 1 s
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->type, MessageType::kRefuse);
}

TEST(Behaviour, NonResponsiveVehicleNeverAnswers) {
  MainVehicle v = test::vehicle(1, 40.0, 20.0, BehaviourType::kNonResponsive);
  v.v2v.capable = true;
  MainLaneDriver driver(v, Road{}, Params{});
  EXPECT_FALSE(driver.answer(request(CoopCase::kEgoAhead, 19.0), 0.0, 20.0));

  Scenario s = test::empty_scenario();
  s.ego.v2v.capable = true;
  s.vehicles.push_back(v);
  test::RequestingPlanner planner(-3.5, 20.0, 1, 19.0, CoopCase::kEgoBehind);
  const Trace t = simulate(s, planner);
  EXPECT_TRUE(planner.received.empty());
  int delivered_to_vehicle = 0;
  for (const TraceEvent& e : t.events) {
    EXPECT_NE(e.kind == EventKind::kMessageSent ? e.vehicle_id : 0, 1) << "vehicle 1 sent a message";
    if (e.kind == EventKind::kMessageDelivered && e.vehicle_id == 1) ++delivered_to_vehicle;
  }
  EXPECT_EQ(delivered_to_vehicle, 1) << "the request did arrive";
}

TEST(Behaviour, ExceedBrakeAppliesItsMagnitudeOnlyInItsWindow) {
  MainVehicle v = test::vehicle(1, 0.0, 25.0, BehaviourType::kIdm);
  v.noncompliance = {NonComplianceType::kExceedBrake, 1.0, 0.5, 11.0};
  MainLaneDriver driver(v, Road{}, Params{});
  EXPECT_EQ(driver.accel_mps2(free_road(0.9, 25.0)), 0.0);
  EXPECT_EQ(driver.accel_mps2(free_road(1.0, 25.0)), -11.0);
  EXPECT_TRUE(driver.non_compliant(1.2));
  EXPECT_EQ(driver.accel_mps2(free_road(1.5, 25.0)), 0.0);
}

TEST(Behaviour, RenegingResponderAcceptsAndDoesNotYield) {
  MainVehicle v = test::vehicle(1, 0.0, 20.0, BehaviourType::kCooperative);
  v.noncompliance.type = NonComplianceType::kRenege;
  MainLaneDriver driver(v, Road{}, Params{});
  const auto reply = driver.answer(request(CoopCase::kEgoAhead, 17.0), 0.0, 20.0);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->type, MessageType::kAccept);
  EXPECT_TRUE(driver.non_compliant(0.0));
  const Drive r = drive_alone(driver, 20.0, 3.0);
  EXPECT_NEAR(r.speed.back(), 20.0, 0.01);
}

// The ego merged 25 m ahead of an RSS follower at a lower speed: the follower falls back to
// at least D_lon behind it and keeps that distance.
TEST(Behaviour, RssFollowerKeepsSafeDistanceBehindTheMergedEgo) {
  Scenario s = test::empty_scenario();
  s.ego.y_m = 0.0;
  s.ego.x_m = 25.0;
  s.ego.speed_mps = 15.0;
  s.params.sim.horizon_s = 30.0;
  s.vehicles.push_back(test::vehicle(1, 0.0, 20.0, BehaviourType::kRssFollower));
  test::LaneKeepPlanner planner(0.0, 15.0, 2.0);
  const Trace t = simulate(s, planner);
  const TraceStep& last = t.steps.back();
  const Leader ego_ahead{0, last.ego.x_m - last.others[0].x_m, last.ego.vx_mps, s.ego.size.length_m,
                         s.ego.limits.brake_max_mps2};
  EXPECT_FALSE(rss_unsafe_behind(last.others[0].vx_mps, 4.8, s.vehicles[0].limits, ego_ahead, s.params.rss));
  EXPECT_NEAR(last.others[0].vx_mps, 15.0, 0.3);
  for (const TraceStep& step : t.steps) EXPECT_LT(step.others[0].x_m + 4.8, step.ego.x_m) << "no collision";
}

// LaneOrder finds the same leaders as find_leaders' scan, ties and the ego included, as the
// vehicles move (and overtake) from one update to the next.
RC_GTEST_PROP(Behaviour, LaneOrderFindsTheSameLeadersAsTheScan, ()) {
  Scenario s;
  s.road.main_lanes = *rc::gen::inRange(1, 4);
  const int n = *rc::gen::inRange(1, 20);
  std::vector<VehicleState> others(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    MainVehicle v;
    v.id = k + 1;
    v.lane = *rc::gen::inRange(0, s.road.main_lanes);
    v.size.length_m = *rc::gen::element(4.8, 12.0);
    s.vehicles.push_back(v);
  }
  LaneOrder order;
  for (int step = 0; step < 4; ++step) {
    for (VehicleState& o : others) {
      o.x_m = *rc::gen::inRange(-20, 20) * 5.0;  // coarse: equal positions and distances happen
      o.vx_mps = *rc::gen::inRange(0, 30);
    }
    VehicleState ego;
    ego.x_m = *rc::gen::inRange(-20, 20) * 5.0;
    ego.y_m = *rc::gen::inRange(-2, 2 * s.road.main_lanes) * 0.5 * s.road.lane_width_m;
    ego.vx_mps = 20.0;
    order.update(s, others);
    for (std::size_t i = 0; i < others.size(); ++i) {
      const Leaders a = find_leaders(s, others, i, ego), b = order.leaders(s, others, i, ego);
      for (const auto& [x, y] : {std::pair{a.main_only, b.main_only}, std::pair{a.with_ego, b.with_ego}}) {
        RC_ASSERT(x.has_value() == y.has_value());
        if (!x) continue;
        RC_ASSERT(x->id == y->id);
        RC_ASSERT(x->distance_m == y->distance_m);
        RC_ASSERT(x->speed_mps == y->speed_mps);
        RC_ASSERT(x->length_m == y->length_m);
        RC_ASSERT(x->brake_max_mps2 == y->brake_max_mps2);
      }
    }
  }
}

// The Intelligent Driver Model as Treiber, Hennecke and Helbing (2000) write it, for a follower
// at speed v behind a leader at bumper gap s closing at dv:
// a [1 - (v/v0)^4 - (s*/s)^2], s* = s0 + max(0, v T + v dv / (2 sqrt(a b))); free road without
// the interaction term. Written here from the paper, not from the simulator's code.
double treiber_idm_mps2(double v, double v0, double a, double b, double s0, double T, std::optional<std::pair<double, double>> gap_dv) {
  double free = 1.0 - std::pow(v / v0, 4.0);
  if (!gap_dv) return a * free;
  const auto [s, dv] = *gap_dv;
  const double s_star = s0 + std::max(0.0, v * T + v * dv / (2.0 * std::sqrt(a * b)));
  return a * (free - (s_star / s) * (s_star / s));
}

// Every IDM vehicle of a simulated platoon applies, at every step, the IDM acceleration of its
// state and its leader's at the step before (the model's gap and acceleration laws), clamped
// to its declared limits, or stops within the step.
RC_GTEST_PROP(Behaviour, IdmVehiclesFollowTheModelsLawsInTheSimulator, ()) {
  Scenario s = test::empty_scenario();
  s.params.sim.horizon_s = 8.0;
  const int n = *rc::gen::inRange(1, 5);
  double x = 0.0;
  for (int i = 0; i < n; ++i) {
    x += *rc::gen::inRange(8, 80);  // metres between centres, ahead of the previous vehicle
    MainVehicle v = test::vehicle(i + 1, x, *rc::gen::inRange(0, 35), BehaviourType::kIdm);
    v.behaviour.desired_speed_mps = *rc::gen::inRange(5, 35);
    v.behaviour.time_headway_s = *rc::gen::inRange(5, 30) / 10.0;
    v.behaviour.min_gap_m = *rc::gen::inRange(1, 6);
    v.behaviour.comfort_brake_mps2 = *rc::gen::inRange(10, 40) / 10.0;
    v.limits.accel_max_mps2 = *rc::gen::inRange(5, 40) / 10.0;
    v.limits.brake_max_mps2 = *rc::gen::inRange(40, 100) / 10.0;
    s.vehicles.push_back(v);
  }
  test::LaneKeepPlanner stay(-3.5, 20.0, 2.0);  // the ego never reaches the main lane
  const Trace trace = simulate(s, stay);
  const double dt = s.params.sim.step_s;
  for (std::size_t k = 1; k < trace.steps.size(); ++k) {
    const auto& before = trace.steps[k - 1].others;
    for (std::size_t i = 0; i < before.size(); ++i) {
      const MainVehicle& v = s.vehicles[i];
      std::optional<std::pair<double, double>> gap_dv;
      for (std::size_t j = 0; j < before.size(); ++j) {  // the nearest vehicle ahead
        if (before[j].x_m <= before[i].x_m) continue;
        const double gap = before[j].x_m - before[i].x_m - 0.5 * (v.size.length_m + s.vehicles[j].size.length_m);
        if (!gap_dv || gap < gap_dv->first) gap_dv = std::pair{gap, before[i].vx_mps - before[j].vx_mps};
      }
      const double a = std::max(v.limits.accel_max_mps2, 0.5);
      double expected = gap_dv && gap_dv->first <= 0.01
                            ? -v.limits.brake_max_mps2
                            : treiber_idm_mps2(before[i].vx_mps, v.behaviour.desired_speed_mps, a,
                                               v.behaviour.comfort_brake_mps2, v.behaviour.min_gap_m,
                                               v.behaviour.time_headway_s, gap_dv);
      expected = std::clamp(expected, -v.limits.brake_max_mps2, v.limits.accel_max_mps2);
      const VehicleState& now = trace.steps[k].others[i];
      if (before[i].vx_mps + expected * dt < 0.0) {  // stops within the step
        RC_ASSERT(now.vx_mps == 0.0);
        continue;
      }
      RC_ASSERT(std::abs(now.accel_mps2 - expected) <= 1e-9 * (1.0 + std::abs(expected)));
      RC_ASSERT(std::abs(now.vx_mps - (before[i].vx_mps + expected * dt)) <= 1e-9);
    }
  }
}

}  // namespace
}  // namespace mg
