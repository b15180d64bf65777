// The shared harness every planner of planner_names() passes through: the same
// scenarios, a small closed-loop kinematic rollout (point-mass ego on the returned path,
// constant-speed traffic, an ideal V2V channel with cooperative responders that accept), and the
// same sanity thresholds. RCPP planners additionally must respect the side lane's end and their
// own bounds. Also: planner determinism, and planner-level properties on random scenarios.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/merge_phase_detector.h"
#include "core/scenario.h"
#include "planner/definition1.h"
#include "planner/definition1_search.h"
#include "planner/merge_path.h"
#include "planner/planner.h"
#include "planner/rcpp_planner.h"
#include "planner/rcpp_world.h"

#include "rcpp_decision_of.h"

namespace mg {
namespace {

Scenario load(const std::string& name) {
  return load_scenario(std::string(MG_SOURCE_DIR) + "/corpus/scenarios/" + name + ".json");
}

const std::vector<std::string> kScenarios = {"fig2_s1_ahead_noncoop", "fig2_s2_behind_noncoop", "fig2_s3_ahead_coop",
                                             "fig2_s4_behind_coop",   "no_feasible_gap_halt",   "paper_merge"};

struct Rollout {
  std::vector<PlanOutput> outputs;
  std::vector<VehicleState> egos;   // ego state each output was planned for
  bool left_road = false;           // the ego passed the side lane's end while still in the side lane
  bool merged = false;              // the merge completed (core/merge_phase_detector.h)
  std::vector<std::size_t> phases;  // an RCPP planner's phase after each cycle (RcppPhase's index)
};

double path_y(const std::vector<PathPoint>& path, double x) {
  if (x <= path.front().x_m) return path.front().y_m;
  for (std::size_t i = 1; i < path.size(); ++i)
    if (x <= path[i].x_m) {
      const double f = (x - path[i - 1].x_m) / (path[i].x_m - path[i - 1].x_m);
      return path[i - 1].y_m + f * (path[i].y_m - path[i - 1].y_m);
    }
  return path.back().y_m;
}

Rollout roll_out(const Scenario& s, const std::string& planner_name, double horizon_s) {
  auto planner = make_planner(planner_name);
  WorldSnapshot w = initial_snapshot(s);
  const double dt = s.params.sim.planner_cycle_s;
  std::vector<double> responder_target(w.others.size(), -1.0);
  std::vector<std::pair<double, V2vMessage>> in_flight;
  Rollout r;
  MergePhaseDetector merge(s.road, s.params.rules, s.ego.size, w.ego.y_m);
  double v = s.ego.speed_mps;
  for (int k = 0; k * dt < horizon_s; ++k) {
    w.time_s = k * dt;
    w.inbox.clear();
    for (auto it = in_flight.begin(); it != in_flight.end();) {
      if (it->first <= w.time_s) {
        w.inbox.push_back(it->second);
        it = in_flight.erase(it);
      } else {
        ++it;
      }
    }
    PlanOutput out = planner->plan(w);
    if (const auto* rcpp = dynamic_cast<const RcppPlanner*>(planner.get())) r.phases.push_back(rcpp->phase().index());
    r.egos.push_back(w.ego);
    for (const V2vMessage& m : out.outbox) {  // cooperative responders accept after 2 latencies
      const int idx = s.index_of(m.to_id);
      if (idx < 0 || !s.vehicles[idx].v2v.capable || s.vehicles[idx].behaviour.type != BehaviourType::kCooperative)
        continue;
      V2vMessage reply{MessageType::kAccept, m.to_id, 0, w.time_s + s.vehicles[idx].v2v.latency_s};
      in_flight.emplace_back(w.time_s + 2 * s.vehicles[idx].v2v.latency_s, reply);
      for (std::size_t i = 0; i < w.others.size(); ++i)
        if (w.others[i].id == m.to_id) responder_target[i] = m.target_speed_mps;
    }
    // Ego: speed toward the target within the limits; position along the path.
    const Limits& lim = s.ego.limits;
    double a = std::clamp((out.target_speed_mps - v) / dt, -out.accel_limit_mps2, out.accel_limit_mps2);
    if (out.proper_response) a = std::min(a, -lim.brake_min_mps2);
    a = std::clamp(a, -lim.brake_max_mps2, lim.accel_max_mps2);
    v = std::max(0.0, v + a * dt);
    const double x_new = w.ego.x_m + v * dt;
    const double y_new = path_y(out.path, x_new);
    w.ego.yaw_rad = v > 0 ? std::atan2(y_new - w.ego.y_m, v * dt) : 0.0;
    w.ego.vx_mps = v * dt > 0 ? std::hypot(v * dt, y_new - w.ego.y_m) / dt : 0.0;
    w.ego.x_m = x_new;
    w.ego.y_m = y_new;
    w.ego.accel_mps2 = a;
    if (w.ego.y_m < -0.5 * s.road.lane_width_m && w.ego.x_m > s.road.side_lane_end_x_m - 0.5 * s.ego.size.length_m)
      r.left_road = true;
    merge.step(w.ego.y_m, w.ego.road_vy_mps(), w.ego.yaw_rad);
    for (std::size_t i = 0; i < w.others.size(); ++i) {  // traffic: constant speed, responders track v_o*
      ObservedVehicle& o = w.others[i];
      if (responder_target[i] >= 0) {
        const double dv = std::clamp(responder_target[i] - o.state.vx_mps, -o.limits.brake_min_mps2 * dt,
                                     o.limits.accel_max_mps2 * dt);
        o.state.vx_mps += dv;
      }
      o.state.x_m += o.state.vx_mps * dt;
    }
    r.outputs.push_back(std::move(out));
  }
  r.merged = merge.completed();
  return r;
}

void expect_sane(const Scenario& s, const Rollout& r, const std::string& where) {
  for (std::size_t k = 0; k < r.outputs.size(); ++k) {
    const PlanOutput& out = r.outputs[k];
    const VehicleState& ego = r.egos[k];
    SCOPED_TRACE(where + " cycle " + std::to_string(k));
    ASSERT_GE(out.path.size(), 2u);
    for (std::size_t i = 0; i < out.path.size(); ++i) {
      ASSERT_TRUE(std::isfinite(out.path[i].x_m) && std::isfinite(out.path[i].y_m));
      if (i > 0) {
        ASSERT_GT(out.path[i].x_m, out.path[i - 1].x_m);  // path monotone in X
      }
    }
    EXPECT_LE(out.path.front().x_m, ego.x_m);  // covers the current position
    // ... and enough ahead to be tracked until the next cycle's path: where the ego can get by
    // then, plus 10 m and half a second for the tracker's lookahead.
    const double cycle_s = s.params.sim.planner_cycle_s;
    const double reach_speed_mps = std::max(0.0, ego.road_vx_mps()) + s.ego.limits.accel_max_mps2 * cycle_s;
    EXPECT_GE(out.path.back().x_m, ego.x_m + 10.0 + reach_speed_mps * (cycle_s + 0.5));
    ASSERT_TRUE(std::isfinite(out.target_speed_mps));
    EXPECT_GE(out.target_speed_mps, 0.0);
    EXPECT_LE(out.target_speed_mps, s.road.speed_limit_mps + 1e-9);
    EXPECT_TRUE(std::isfinite(out.accel_limit_mps2));
    EXPECT_GT(out.accel_limit_mps2, 0.0);
    EXPECT_FALSE(out.reason.empty());
    EXPECT_FALSE(out.mode.empty());
    const RcppDecision* d = rcpp_decision(out.annotation);  // the baseline gives no record
    if (d && !std::isnan(d->pc_m)) {
      EXPECT_GE(d->pc_m, d->pc_min_m);
      EXPECT_LE(d->pc_m, d->pc_max_m);
    }
    if (d && !std::isnan(d->ve_min_mps)) {
      EXPECT_GE(d->ve_star_mps, d->ve_min_mps);
      EXPECT_LE(d->ve_star_mps, d->ve_max_mps);
    }
  }
}

std::string digest(const Rollout& r) {
  std::string out;
  for (const PlanOutput& o : r.outputs) {
    out += plan_record_to_json({0.0, o.mode, o.reason, o.annotation}).dump();
    for (const PathPoint& p : o.path) out += std::to_string(p.x_m) + "," + std::to_string(p.y_m) + ";";
    out += std::to_string(o.target_speed_mps) + std::to_string(o.outbox.size());
  }
  return out;
}

TEST(PlannerHarness, EveryPlannerIsRegisteredAndNamed) {
  for (const std::string& name : planner_names()) {
    auto p = make_planner(name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_EQ(p->name(), name);
  }
  EXPECT_EQ(make_planner("no-such-planner"), nullptr);
}

TEST(PlannerHarness, EveryPlannerIsSaneOnEveryScenario) {
  for (const std::string& scenario : kScenarios) {
    const Scenario s = load(scenario);
    for (const std::string& name : planner_names()) {
      const Rollout r = roll_out(s, name, 25.0);
      expect_sane(s, r, scenario + " / " + name);
    }
  }
}

TEST(PlannerHarness, EveryPlannerIsDeterministic) {
  for (const std::string scenario : {"fig2_s3_ahead_coop", "no_feasible_gap_halt"}) {
    const Scenario s = load(scenario);
    for (const std::string& name : planner_names())
      EXPECT_EQ(digest(roll_out(s, name, 15.0)), digest(roll_out(s, name, 15.0))) << scenario << " / " << name;
  }
}

TEST(PlannerHarness, RcppPlannersMergeInTheFig2SituationsAndNeverLeaveTheRoad) {
  // Non-cooperative situations merge with both RCPP planners; cooperative ones merge with
  // rcpp-coop (the responder accepts); every RCPP run stays on the road.
  const std::vector<std::pair<std::string, std::string>> merges = {
      {"fig2_s1_ahead_noncoop", "rcpp"}, {"fig2_s2_behind_noncoop", "rcpp"}, {"fig2_s1_ahead_noncoop", "rcpp-coop"},
      {"fig2_s3_ahead_coop", "rcpp-coop"}, {"fig2_s4_behind_coop", "rcpp-coop"}};
  for (const auto& [scenario, planner] : merges) {
    const Rollout r = roll_out(load(scenario), planner, 25.0);
    EXPECT_TRUE(r.merged) << scenario << " / " << planner;
    EXPECT_FALSE(r.left_road) << scenario << " / " << planner;
  }
  for (const std::string& scenario : kScenarios)
    for (const std::string planner : {"rcpp", "rcpp-coop"})
      EXPECT_FALSE(roll_out(load(scenario), planner, 25.0).left_road) << scenario << " / " << planner;
}

TEST(PlannerHarness, Definition13HaltsThenMergesFromStandstill) {
  // no_feasible_gap_halt: the ego must halt before x = 150 and merge behind the platoon.
  const Scenario s = load("no_feasible_gap_halt");
  const Rollout r = roll_out(s, "rcpp", s.params.sim.horizon_s);
  bool halted = false;
  for (std::size_t k = 0; k < r.egos.size(); ++k)
    halted = halted || (decision_of(r.outputs[k]).mode == DecisionMode::kDef1Halt && r.egos[k].vx_mps < 0.05);
  EXPECT_TRUE(halted);
  EXPECT_TRUE(r.merged);
  EXPECT_FALSE(r.left_road);
}

// The same platoon with the ego 15 m/s fast, 0.8 of b_min's stopping distance before its halt
// point: braking at b_min it comes to rest about 5 m past it, short of the room a merge from
// standstill needs. It brakes harder (within b_max), rests at the halt point and merges from there.
TEST(PlannerHarness, AnEgoTooFastToHaltAtTheHaltPointWithBMinBrakesHarderToHaltThere) {
  Scenario s = load("no_feasible_gap_halt");
  const double halt_x_m =
      halt_point_x_m(s.road, s.params.planner.halt_margin_m, s.ego.size.length_m, standstill_merge_length_m(s));
  const double v0_mps = s.ego.speed_mps;
  s.ego.x_m = halt_x_m - 0.8 * v0_mps * v0_mps / (2.0 * s.ego.limits.brake_min_mps2);
  const Rollout r = roll_out(s, "rcpp", s.params.sim.horizon_s);
  std::optional<double> rest_x_m;
  for (const VehicleState& ego : r.egos)
    if (!rest_x_m && ego.vx_mps < 0.05) rest_x_m = ego.x_m;
  ASSERT_TRUE(rest_x_m.has_value());
  EXPECT_LE(*rest_x_m, halt_x_m + 0.1);
  EXPECT_GT(*rest_x_m, halt_x_m - 2.0);
  EXPECT_TRUE(r.merged);
  EXPECT_FALSE(r.left_road);
}

TEST(PlannerHarness, SilentResponderFallsBackToDefinition1) {
  // Def. 2.3: the same Fig. 2 situation 3 with a non-responsive vehicle: the request times out
  // after rho_c and the ego falls back to Definition 1 (here the longer merge behind vehicle 1),
  // never merging by Definition 2 without an answer.
  Scenario s = load("fig2_s3_ahead_coop");
  s.vehicles[0].behaviour.type = BehaviourType::kNonResponsive;
  const Rollout r = roll_out(s, "rcpp-coop", 3.0);
  ASSERT_EQ(decision_of(r.outputs[0]).mode, DecisionMode::kDef2Request);
  bool fell_back = false;
  for (const PlanOutput& o : r.outputs) {
    const DecisionMode mode = decision_of(o).mode;
    EXPECT_NE(mode, DecisionMode::kDef2Merge);
    fell_back = fell_back || ((mode == DecisionMode::kDef1Halt || mode == DecisionMode::kDef1Merge) &&
                              o.reason.find("Def. 2.3") != std::string::npos);
  }
  EXPECT_TRUE(fell_back);
}

// Vehicle 1 alongside the ego; vehicle 2 stopped 83 m ahead of it. Definition 2.2 would ask
// vehicle 1 to speed up and merge behind it, onto the stopped vehicle: no request is sound, and
// the ego (weak brakes, 3.3 m/s2) must not plan one (a campaign finding: it asked, vehicle 1
// could not comply, and the ego merged at 16 m/s 29 m behind vehicle 2).
//
//   main lane   [1] 21.2 m/s ----------------- 83 m ---------------- [2] stopped
//   side lane   [ego] 21.7 m/s  -----------------------------------------------> end at 320 m
TEST(PlannerHarness, NoCooperativeRequestAsksTheResponderToDriveOntoAVehicleAheadOfIt) {
  Scenario s;
  s.road.speed_limit_mps = 25.3;
  s.road.side_lane_end_x_m = 320.0;
  s.params.rss.response_time_s = 0.2;
  s.params.planner.comm_threshold_s = 1.8;
  s.ego.size.length_m = 4.0;
  s.ego.size.width_m = 2.1;
  s.ego.v2v.latency_s = 0.19;
  s.ego.x_m = 146.7;
  s.ego.y_m = -s.road.lane_width_m;
  s.ego.speed_mps = 21.7;
  s.ego.limits.brake_min_mps2 = s.ego.limits.brake_max_mps2 = 3.3;
  s.ego.v2v.capable = true;
  MainVehicle v1, v2;
  v1.id = 1;
  v1.x_m = 144.9;
  v1.speed_mps = 21.2;
  v1.v2v.capable = true;
  v1.v2v.latency_s = 0.32;
  v1.size.length_m = 4.1;
  v1.size.width_m = 1.75;
  v1.limits = Limits{3.4, 5.0, 6.3, 0.5, 0.7};
  v1.behaviour.type = BehaviourType::kCooperative;
  v2.id = 2;
  v2.x_m = 228.2;
  v2.speed_mps = 0.0;
  s.vehicles = {v1, v2};
  WorldSnapshot w = initial_snapshot(s);
  w.others[0].state.accel_mps2 = -1.8;
  w.ego.accel_mps2 = -1.3;
  const RcppDecision d = decision_of(make_planner("rcpp-coop")->plan(w));
  EXPECT_FALSE(d.mode == DecisionMode::kDef2Request && d.coop_partner_id == 1 && d.vo_star_mps > 21.2) << d.reason;
}

// RCPP's state machine on a plain merge: in the side lane until Definition 1 finds the gap, then
// merging along the committed sigmoid, then in the main lane for good; no way back.
TEST(PlannerHarness, RcppsPhasesRunFromTheSideLaneThroughTheMergeIntoTheMainLane) {
  const Rollout r = roll_out(load("fig2_s1_ahead_noncoop"), "rcpp", 20.0);
  ASSERT_FALSE(r.phases.empty());
  EXPECT_TRUE(std::holds_alternative<InSideLane>(RcppPhase{}));  // the phase a planner starts in
  EXPECT_TRUE(std::is_sorted(r.phases.begin(), r.phases.end()));  // InSideLane < Merging < InMainLane
  EXPECT_NE(std::find(r.phases.begin(), r.phases.end(), RcppPhase(Merging{}).index()), r.phases.end());
  EXPECT_EQ(r.phases.back(), RcppPhase(InMainLane{}).index());
  EXPECT_TRUE(r.merged);
}

// An abort: the ego decides to merge behind vehicle 1; a cycle later vehicle 1 brakes at its
// b_max and its P_c bound crosses while the ego can still stop, so the ego is back in the side
// lane. Having moved toward the lane, it holds the side lane for a second before it plans again
// (re-planning at once against a leader that keeps braking would weave); not having moved, it
// plans again at once: there is nothing to weave, and a hold would let the gap go.
//
//   main lane          [1] 25 m/s --> brakes at 8 m/s2
//   side lane  [ego] 25 m/s                                  (end 300 m)
struct AbortAfterOneCycle {
  PlanOutput next;
  std::optional<InSideLane> side;
};
AbortAfterOneCycle abort_after_one_cycle(double moved_toward_lane_m) {
  Scenario s;
  s.road.side_lane_end_x_m = 300.0;
  s.ego.x_m = 100.0;
  s.ego.speed_mps = 25.0;
  MainVehicle leader;
  leader.id = 1;
  leader.x_m = 160.0;
  leader.speed_mps = 25.0;
  s.vehicles = {leader};
  RcppPlanner planner(false);
  WorldSnapshot w = initial_snapshot(s);
  const PlanOutput first = planner.plan(w);
  EXPECT_EQ(first.mode, "def1_merge") << first.reason;
  EXPECT_TRUE(std::holds_alternative<Merging>(planner.phase()));
  const double dt = s.params.sim.planner_cycle_s;
  w.time_s = dt;
  w.ego.x_m += w.ego.vx_mps * dt;
  w.ego.y_m += moved_toward_lane_m;
  w.others[0].state.x_m += w.others[0].state.vx_mps * dt;
  w.others[0].state.accel_mps2 = -leader.limits.brake_max_mps2;
  AbortAfterOneCycle out{planner.plan(w), std::nullopt};
  if (const auto* side = std::get_if<InSideLane>(&planner.phase())) out.side = *side;
  return out;
}

TEST(PlannerHarness, AnAbortAfterMovingTowardTheLaneHoldsTheSideLaneBeforeANewMerge) {
  const AbortAfterOneCycle r = abort_after_one_cycle(0.1);
  ASSERT_TRUE(r.side) << r.next.reason;
  EXPECT_EQ(r.next.mode, "def1_halt");
  EXPECT_EQ(r.next.reason.rfind("merge aborted", 0), 0u) << r.next.reason;
  EXPECT_DOUBLE_EQ(r.side->no_merge_before_s, 0.1 + 1.0);
  EXPECT_FALSE(r.side->pending);
}

TEST(PlannerHarness, AnAbortBeforeMovingTowardTheLanePlansAgainAtOnce) {
  const AbortAfterOneCycle r = abort_after_one_cycle(0.0);
  ASSERT_TRUE(r.side) << r.next.reason;
  EXPECT_EQ(r.next.reason.rfind("merge aborted", 0), 0u) << r.next.reason;
  EXPECT_DOUBLE_EQ(r.side->no_merge_before_s, 0.1);
  EXPECT_EQ(r.next.reason.find("holding the side lane after an aborted merge"), std::string::npos) << r.next.reason;
}

// The ego overtakes vehicles 2 (braking) and 3 (stopped) in the side lane and merges ahead of
// vehicle 3. Vehicle 2, braking ahead of the ego but behind the gap's follower, is being passed:
// it must not cap the ego's speed as a braking leader would (a campaign finding: the cap slowed
// the ego, its P_c bounds crossed, and the merge was aborted a cycle after its decision).
//
//   main lane   [1] 13.8 m/s     [2] 9.2 m/s, braking 4 m/s2    [3] stopped      P_c 259 m
//   side lane          [ego] 19.7 m/s ------------------------------------------>  (end 300 m)
TEST(PlannerHarness, AMergeAheadOfAStoppedFollowerIsNotSlowedByTheVehiclesItPasses) {
  Scenario s;
  s.road.speed_limit_mps = 33.3;
  s.road.side_lane_end_x_m = 300.0;
  s.params.rss.response_time_s = 0.1;
  s.ego.x_m = 171.17;
  s.ego.y_m = -s.road.lane_width_m;
  s.ego.speed_mps = 19.74;
  const auto vehicle = [](int id, double x_m, double speed_mps) {
    MainVehicle v;
    v.id = id;
    v.x_m = x_m;
    v.speed_mps = speed_mps;
    return v;
  };
  s.vehicles = {vehicle(1, 161.33, 13.85), vehicle(2, 190.37, 9.16), vehicle(3, 207.05, 0.0)};
  WorldSnapshot w = initial_snapshot(s);
  w.others[0].state.accel_mps2 = -3.27;
  w.others[1].state.accel_mps2 = -4.0;
  auto planner = make_planner("rcpp");
  const RcppDecision first = decision_of(planner->plan(w));
  ASSERT_EQ(first.mode, DecisionMode::kDef1Merge) << first.reason;
  ASSERT_EQ(first.gap, (Gap{3, -1})) << first.reason;
  // A cycle on, everything as predicted: the ego at v_e*, vehicle 2 still braking.
  const double dt = s.params.sim.planner_cycle_s;
  w.time_s = dt;
  w.ego.x_m += w.ego.vx_mps * dt;
  w.others[0].state.x_m += w.others[0].state.vx_mps * dt;
  w.others[1].state.x_m += (w.others[1].state.vx_mps - 2.0 * dt) * dt;
  w.others[1].state.vx_mps -= 4.0 * dt;
  const PlanOutput next = planner->plan(w);
  EXPECT_EQ(decision_of(next).mode, DecisionMode::kDef1Merge) << next.reason;
  EXPECT_GE(next.target_speed_mps, first.ve_star_mps - 1e-9) << next.reason;
}

// The ego merges behind vehicle 1, a 16 m truck still alongside it, braking at 1.4 m/s2 for
// vehicle 2, nearly stopped 195 m ahead. A cycle after the decision the ego is still alongside:
// "D_lon behind it now" would mean speed 0 and P_c never reached. The ego slows instead just
// enough to reach P_c D_lon behind where vehicle 1 is predicted then (a campaign finding: the
// merge was aborted a cycle after each of seven decisions, smoothness_oscillation).
//
//   main lane      [====== 1 ======] 24.1 m/s, -1.4 m/s2 ...... 195 m ...... [2] 1.5 m/s
//   side lane   [ego] 26.6 m/s
TEST(PlannerHarness, AMergeBehindABrakingLeaderStillAlongsideSlowsToReachPcBehindIt) {
  Scenario s;
  s.road.speed_limit_mps = 33.3;
  s.road.side_lane_end_x_m = 300.0;
  s.params.rss.response_time_s = 0.3;
  s.params.planner.merge_duration_s = s.params.rules.merge_duration_s = 4.5;
  s.ego.x_m = 49.292;
  s.ego.y_m = -3.424;
  s.ego.speed_mps = 26.593;
  s.ego.limits = Limits{2.0, 5.9, 9.9, 0.2, 0.8};
  MainVehicle truck, slow;
  truck.id = 1;
  truck.x_m = 54.966;
  truck.speed_mps = 24.115;
  truck.size.length_m = 16.0;
  truck.size.width_m = 2.5;
  truck.limits = Limits{2.0, 2.6, 4.2, 0.5, 0.9};
  slow.id = 2;
  slow.x_m = 250.546;
  slow.speed_mps = 1.494;
  s.vehicles = {truck, slow};
  WorldSnapshot w = initial_snapshot(s);
  w.ego.vy_mps = -0.384;
  w.others[0].state.accel_mps2 = -1.438;
  w.others[1].state.accel_mps2 = -0.504;
  auto planner = make_planner("rcpp");
  const RcppDecision first = decision_of(planner->plan(w));
  ASSERT_EQ(first.mode, DecisionMode::kDef1Merge) << first.reason;
  ASSERT_EQ(first.gap, (Gap{-1, 1})) << first.reason;
  // A cycle on (the states the simulator gave): the truck still ahead of the ego's centre by 5.4 m.
  w.time_s = 0.1;
  w.ego.x_m = 51.922;
  w.ego.y_m = -3.457;
  w.ego.vx_mps = 26.004;
  w.ego.vy_mps = -0.277;
  w.others[0].state.x_m = 57.371;
  w.others[0].state.vx_mps = 23.973;
  w.others[0].state.accel_mps2 = -1.412;
  w.others[1].state.x_m = 250.693;
  w.others[1].state.vx_mps = 1.446;
  w.others[1].state.accel_mps2 = -0.455;
  const PlanOutput next = planner->plan(w);
  EXPECT_EQ(decision_of(next).mode, DecisionMode::kDef1Merge) << next.reason;
  EXPECT_GT(next.target_speed_mps, 5.0) << next.reason;
  EXPECT_LE(next.target_speed_mps, first.ve_star_mps) << next.reason;
}

// ---- planner-level properties on random scenarios ----
Scenario gen_scenario() {
  Scenario s;
  s.road.side_lane_start_x_m = 0;
  s.road.side_lane_end_x_m = *rc::gen::inRange(150, 500);
  s.ego.x_m = *rc::gen::inRange(0, 100);
  s.ego.y_m = -s.road.lane_width_m;
  s.ego.speed_mps = *rc::gen::inRange(0, 300) / 10.0;
  s.ego.v2v.capable = *rc::gen::arbitrary<bool>();
  const int n = *rc::gen::inRange(0, 4);
  for (int i = 0; i < n; ++i) {
    MainVehicle v;
    v.id = i + 1;
    v.x_m = s.ego.x_m + *rc::gen::inRange(-100, 100) + 12.0 * i;
    v.speed_mps = *rc::gen::inRange(0, 300) / 10.0;
    v.v2v.capable = *rc::gen::arbitrary<bool>();
    s.vehicles.push_back(v);
  }
  return s;
}

RC_GTEST_PROP(PlannerProperties, ChosenMergeSpeedSatisfiesDefinition1ForItsGap, ()) {
  const Scenario s = gen_scenario();
  const WorldSnapshot w = initial_snapshot(s);
  const PlanOutput out = make_planner(*rc::gen::element<std::string>("rcpp", "rcpp-coop"))->plan(w);
  const RcppDecision d = decision_of(out);
  RC_PRE(d.mode == DecisionMode::kDef1Merge);
  RC_ASSERT(d.gap.has_value());
  const Def1Context c{s.ego.x_m, s.ego.speed_mps, s.ego.size.length_m, s.ego.limits,
                      s.params.rss.response_time_s, d.merge_duration_s, s.road.speed_limit_mps};
  for (const MainVehicle& v : s.vehicles) {
    const MainLaneVehicle o{v.id, v.x_m, v.speed_mps, v.size.length_m, v.size.width_m, v.limits};
    if (v.id == d.gap->follower_id) RC_ASSERT(def1_1_margin_m(c, o, d.ve_star_mps) >= -1e-9);
    if (v.id == d.gap->leader_id) RC_ASSERT(def1_2_margin_m(c, o, d.ve_star_mps) >= -1e-9);
  }
  RC_ASSERT(d.pc_min_m <= d.pc_m && d.pc_m <= d.pc_max_m);
  RC_ASSERT(d.ve_min_mps <= d.ve_star_mps && d.ve_star_mps <= d.ve_max_mps);
  RC_ASSERT(d.pc_m < s.road.side_lane_end_x_m);
}

RC_GTEST_PROP(PlannerProperties, SamePlannerSameSnapshotSameOutput, ()) {
  const Scenario s = gen_scenario();
  const WorldSnapshot w = initial_snapshot(s);
  for (const std::string& name : planner_names()) {
    const PlanOutput a = make_planner(name)->plan(w);
    const PlanOutput b = make_planner(name)->plan(w);
    RC_ASSERT(plan_record_to_json({0.0, a.mode, a.reason, a.annotation}) ==
              plan_record_to_json({0.0, b.mode, b.reason, b.annotation}));
    RC_ASSERT(a.target_speed_mps == b.target_speed_mps);
    RC_ASSERT(a.path.size() == b.path.size());
    for (std::size_t i = 0; i < a.path.size(); ++i)
      RC_ASSERT(a.path[i].x_m == b.path[i].x_m && a.path[i].y_m == b.path[i].y_m);
  }
}

// An ego that starts 0.6 m off its lane centre toward the main lane, with the lane empty, merges at
// once: its path never takes it back toward the side lane's centre first (progress; a campaign
// finding: the return took seconds while the gap stayed open).
TEST(PlannerHarness, AnEgoStartingOffItsLaneCentreTowardTheMainLaneKeepsThatOffsetWhenItMerges) {
  Scenario s;
  s.ego.x_m = 0.0;
  s.ego.y_m = -s.road.lane_width_m + 0.6;
  s.ego.speed_mps = 15.0;
  const Rollout r = roll_out(s, "rcpp", 2.0);
  ASSERT_EQ(decision_of(r.outputs.front()).mode, DecisionMode::kDef1Merge) << r.outputs.front().reason;
  for (std::size_t k = 0; k < r.outputs.size(); ++k) {
    for (const PathPoint& p : r.outputs[k].path) {
      if (p.x_m >= r.egos[k].x_m) {
        EXPECT_GE(p.y_m, s.ego.y_m - 1e-9) << "cycle " << k << " at X = " << p.x_m;
      }
    }
  }
}


// A 15 m truck 35 m behind the ego, 3 m/s faster: the only gap is behind it. At t = 0 only a long
// merge (3 rho_m) is feasible, its sigmoid starting tens of metres ahead; once the truck has come
// alongside, a merge at rho_m starts sooner and replaces it before the ego has begun the first.
TEST(PlannerHarness, ACommittedMergeNotYetBegunGivesWayToOneThatBeginsSooner) {
  Scenario s;
  s.road.lane_width_m = 3.3;
  s.road.speed_limit_mps = 28.1;
  s.road.side_lane_end_x_m = 350.0;
  s.params.rss.response_time_s = 0.75;
  s.params.planner.merge_duration_s = 7.3;
  s.params.rules.merge_duration_s = 7.3;
  s.ego.x_m = 54.0;
  s.ego.y_m = -s.road.lane_width_m;
  s.ego.speed_mps = 9.1;
  MainVehicle truck;
  truck.id = 1;
  truck.x_m = 19.5;
  truck.speed_mps = 12.0;
  truck.size.length_m = 15.2;
  truck.size.width_m = 2.5;
  s.vehicles = {truck};
  const Rollout r = roll_out(s, "rcpp", 30.0);
  ASSERT_EQ(decision_of(r.outputs.front()).mode, DecisionMode::kDef1Merge) << r.outputs.front().reason;
  const bool replaced = std::any_of(r.outputs.begin(), r.outputs.end(), [](const PlanOutput& o) {
    return o.reason.find("a sooner merge replaces") != std::string::npos;
  });
  EXPECT_TRUE(replaced);
  EXPECT_TRUE(r.merged);
  EXPECT_FALSE(r.left_road);
}

// An ego at rest 24 m before the side lane's end of an empty road (speed limit 35.5 m/s: the
// shared speed grid's steps are 0.74 m/s, so it holds 0.74 and 1.48 m/s, too slow to reach a P_c
// the sigmoid can turn in to, and faster than a crawl). The longer merges find a merge at the
// crawl speed, 1.4 m/s.
TEST(PlannerHarness, AnEgoAtRestNearTheSideLaneEndMergesAtTheCrawlSpeed) {
  Scenario s;
  s.road.speed_limit_mps = 35.5;
  s.road.side_lane_end_x_m = 24.0;
  s.ego.x_m = 0.0;
  s.ego.y_m = -s.road.lane_width_m;
  s.ego.speed_mps = 0.0;
  const WorldSnapshot w = initial_snapshot(s);
  EXPECT_FALSE(plan_definition1(w, MergeDurations::kRhoM, nullptr).has_value());
  const auto plan = plan_definition1(w, MergeDurations::kLonger, nullptr);
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->ve_star_mps, crawl_speed_mps(s), 1e-12) << plan->decision.reason;
}

}  // namespace
}  // namespace mg
