// Test-only planners for driving the simulator without the real planner: lane keeping at a
// constant speed, a fixed sigmoid lane change, and one that sends a cooperation request.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "core/scenario.h"
#include "planner/planner.h"

namespace mg::test {

inline std::vector<PathPoint> line_at(double x0_m, double y_m) {
  return {{x0_m - 50.0, y_m}, {x0_m + 1000.0, y_m}};
}

// Keeps lane y_m at target_speed_mps, changing speed at most accel_limit_mps2.
class LaneKeepPlanner : public Planner {
 public:
  LaneKeepPlanner(double y_m, double target_speed_mps, double accel_limit_mps2)
      : y_m_(y_m), speed_(target_speed_mps), accel_(accel_limit_mps2) {}
  std::string name() const override { return "test-lane-keep"; }
  PlanOutput plan(const WorldSnapshot& w) override {
    PlanOutput out;
    out.path = line_at(w.ego.x_m, y_m_);
    out.target_speed_mps = speed_;
    out.accel_limit_mps2 = accel_;
    out.mode = "keep_lane";
    out.reason = "test: keep lane";
    return out;
  }

 private:
  double y_m_, speed_, accel_;
};

// y(X) = W / (1 + exp(-kappa (X - P_c))) + b at a constant speed.
class SigmoidPlanner : public Planner {
 public:
  SigmoidPlanner(double pc_m, double kappa_per_m, double width_m, double offset_m, double speed_mps)
      : pc_(pc_m), kappa_(kappa_per_m), w_(width_m), b_(offset_m), speed_(speed_mps) {}
  std::string name() const override { return "test-sigmoid"; }
  PlanOutput plan(const WorldSnapshot& w) override {
    PlanOutput out;
    for (double x = w.ego.x_m - 20.0; x <= w.ego.x_m + 300.0; x += 1.0)
      out.path.push_back({x, w_ / (1.0 + std::exp(-kappa_ * (x - pc_))) + b_});
    out.target_speed_mps = speed_;
    out.accel_limit_mps2 = 2.0;
    out.mode = w.ego.y_m > -0.2 ? "merged" : "def1_merge";
    out.reason = "test: fixed sigmoid";
    return out;
  }

 private:
  double pc_, kappa_, w_, b_, speed_;
};

// Keeps its lane and sends one request to `to_id` at the first cycle; remembers its inbox.
class RequestingPlanner : public LaneKeepPlanner {
 public:
  RequestingPlanner(double y_m, double speed_mps, int to_id, double vo_star_mps, CoopCase c)
      : LaneKeepPlanner(y_m, speed_mps, 2.0), to_id_(to_id), vo_star_(vo_star_mps), case_(c) {}
  PlanOutput plan(const WorldSnapshot& w) override {
    PlanOutput out = LaneKeepPlanner::plan(w);
    for (const V2vMessage& m : w.inbox) received.push_back({w.time_s, m});
    if (!sent_) {
      V2vMessage m;
      m.type = MessageType::kRequest;
      m.to_id = to_id_;
      m.coop_case = case_;
      m.target_speed_mps = vo_star_;
      out.outbox.push_back(m);
      out.mode = "def2_request";
      sent_ = true;
    }
    return out;
  }
  std::vector<std::pair<double, V2vMessage>> received;

 private:
  int to_id_;
  double vo_star_;
  CoopCase case_;
  bool sent_ = false;
};

// Ego in the side lane at x = 0, 20 m/s, no traffic, 10 s horizon.
inline Scenario empty_scenario() {
  Scenario s;
  s.name = "test";
  s.road.side_lane_start_x_m = -100.0;
  s.road.side_lane_end_x_m = 1000.0;
  s.ego.x_m = 0.0;
  s.ego.y_m = -3.5;
  s.ego.speed_mps = 20.0;
  s.params.sim.horizon_s = 10.0;
  return s;
}

inline MainVehicle vehicle(int id, double x_m, double speed_mps, BehaviourType type) {
  MainVehicle v;
  v.id = id;
  v.x_m = x_m;
  v.speed_mps = speed_mps;
  v.behaviour.type = type;
  return v;
}

}  // namespace mg::test
