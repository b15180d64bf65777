#include "sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/collision.h"
#include "core/merge_phase_detector.h"
#include "sim/behaviour.h"
#include "sim/path_tracker.h"
#include "sim/single_track.h"
#include "sim/speed_controller.h"
#include "sim/v2v_channel.h"

namespace mg {
namespace {

constexpr double kHaltSpeedMps = 0.05;        // trace.h: stopped below this speed
constexpr double kInLaneOffsetM = 0.5;        // drivers treat the ego as merged within this

// Merge and halt events of the ego (trace.h EventKind), detected from consecutive states. The
// merge phases are core/merge_phase_detector.h's, with the scenario's rule parameters: the
// simulator's merge events are the merges the rules judge.
class EgoEventDetector {
 public:
  EgoEventDetector(const Scenario& s, const VehicleState& ego0) : merge_(s.road, s.params.rules, s.ego.size, ego0.y_m) {}

  void update(double t, const VehicleState& ego, std::vector<TraceEvent>& events) {
    const double speed = std::hypot(ego.vx_mps, ego.vy_mps);
    if (!halted_ && speed < kHaltSpeedMps) {
      halted_ = true;
      events.push_back({t, EventKind::kHalt, 0, "ego stopped", std::nullopt});
    } else if (halted_ && speed >= kHaltSpeedMps) {
      halted_ = false;
      events.push_back({t, EventKind::kResume, 0, "ego moving again", std::nullopt});
    }
    const MergePhaseStep phase = merge_.step(ego.y_m, ego.road_vy_mps(), ego.yaw_rad);
    if (phase.start) events.push_back({t, EventKind::kMergeStart, 0, "ego leaves the side lane centre", std::nullopt});
    if (phase.midpoint)
      events.push_back({t, EventKind::kMergeMidpoint, 0, "ego centre crosses the lane boundary", std::nullopt});
    if (phase.complete)
      events.push_back({t, EventKind::kMergeComplete, 0, "ego on the main lane centre, heading aligned", std::nullopt});
  }

 private:
  MergePhaseDetector merge_;
  bool halted_ = false;
};

class Run {
 public:
  Run(const Scenario& s, Planner& planner)
      : s_(s), planner_(planner), channel_(s), detector_(s, initial_ego(s)), ego_(initial_ego(s)) {
    for (const MainVehicle& v : s.vehicles) {
      VehicleState st;
      st.x_m = v.x_m;
      st.y_m = v.lane * s.road.lane_width_m;
      st.vx_mps = v.speed_mps;
      others_.push_back(st);
      drivers_.emplace_back(v, s.road, s.params);
      was_non_compliant_.push_back(false);
    }
    plan_.path = straight_path(ego_.x_m, ego_.y_m);
    plan_.target_speed_mps = ego_.vx_mps;
    trace_.planner = planner.name();
  }

  Trace execute() {
    const double dt = s_.params.sim.step_s;
    const long long cycle = std::max(1LL, std::llround(s_.params.sim.planner_cycle_s / dt));
    const long long n_steps = std::llround(s_.params.sim.horizon_s / dt);
    trace_.steps.reserve(static_cast<std::size_t>(n_steps) + 1);
    detector_.update(0.0, ego_, trace_.events);
    for (long long k = 0;; ++k) {
      const double t = static_cast<double>(k) * dt;
      deliver_messages(t);
      if (k % cycle == 0) run_planner(t);
      trace_.steps.push_back({t, ego_, others_, plan_.mode, plan_.proper_response});
      if (k == n_steps) break;
      // The simulator models no crash: vehicles that collided would drive on through each other,
      // and whatever came after would be judged against vehicles that cannot be where they are.
      // The run ends with the step of the first collision, which the collision rule judges
      // (docs/simulator.md).
      lane_order_.update(s_, others_);
      if (lane_order_.any_overlap(s_, others_) || ego_collides()) break;
      advance(t, dt);
      detector_.update(static_cast<double>(k + 1) * dt, ego_, trace_.events);
    }
    return std::move(trace_);
  }

 private:
  static VehicleState initial_ego(const Scenario& s) {
    VehicleState e;
    e.x_m = s.ego.x_m;
    e.y_m = s.ego.y_m;
    e.vx_mps = s.ego.speed_mps;
    return e;
  }

  // The ego's box overlaps a main-lane vehicle's (the collision rule's FCL test, core/collision.h).
  bool ego_collides() const {
    const BoxPose ego{ego_.x_m, ego_.y_m, ego_.yaw_rad, s_.ego.size.length_m, s_.ego.size.width_m, s_.ego.size.height_m};
    const Footprint ego_fp = footprint_of(ego);
    for (std::size_t i = 0; i < others_.size(); ++i) {
      const VehicleSize& z = s_.vehicles[i].size;
      const BoxPose other{others_[i].x_m, others_[i].y_m, others_[i].yaw_rad, z.length_m, z.width_m, z.height_m};
      if (clearance_m(ego_fp, footprint_of(other)) <= 0.0 && fcl_box_contact(ego, other).collide) return true;
    }
    return false;
  }

  void deliver_messages(double t) {
    for (const V2vMessage& m : channel_.deliver_due(t, trace_.events)) {
      if (m.to_id == 0) {
        inbox_.push_back(m);
        continue;
      }
      const std::size_t i = static_cast<std::size_t>(s_.index_of(m.to_id));
      const std::optional<V2vMessage> reply =
          drivers_[i].answer(m, t, others_[i].vx_mps, find_leaders(s_, others_, i, ego_).main_only);
      note_non_compliance(i, t);
      if (reply) channel_.send(*reply, t, trace_.events);
    }
  }

  void run_planner(double t) {
    WorldSnapshot world;
    world.time_s = t;
    world.ego = ego_;
    world.setup = &s_;
    world.inbox = std::move(inbox_);
    inbox_.clear();
    for (std::size_t i = 0; i < s_.vehicles.size(); ++i) {
      const MainVehicle& v = s_.vehicles[i];
      world.others.push_back({v.id, others_[i], v.size, v.limits, v.v2v.capable});
    }
    std::sort(world.others.begin(), world.others.end(),
              [](const ObservedVehicle& a, const ObservedVehicle& b) { return a.id < b.id; });
    PlanOutput out = planner_.plan(world);
    // Repeated points carry no direction: drop them; a path that turns back is a planner bug.
    out.path.erase(std::unique(out.path.begin(), out.path.end(),
                               [](const PathPoint& a, const PathPoint& b) { return a.x_m == b.x_m && a.y_m == b.y_m; }),
                   out.path.end());
    if (out.path.size() < 2) out.path = plan_.path;  // no new path: keep following the last one
    auto contract_broken = [&](const std::string& what) {
      return std::logic_error("planner '" + planner_.name() + "' returned " + what + " at t = " + std::to_string(t) + " s");
    };
    for (std::size_t i = 0; i < out.path.size(); ++i) {
      if (!std::isfinite(out.path[i].x_m) || !std::isfinite(out.path[i].y_m)) throw contract_broken("a non-finite path point");
      if (i > 0 && !(out.path[i].x_m > out.path[i - 1].x_m)) throw contract_broken("a path with non-increasing X");
    }
    if (!std::isfinite(out.target_speed_mps) || !std::isfinite(out.accel_limit_mps2))
      throw contract_broken("a non-finite speed command");
    const bool first = trace_.decisions.empty();
    if (first || out.mode != plan_.mode)
      trace_.events.push_back({t, EventKind::kDecision, 0, out.mode + ": " + out.reason, std::nullopt});
    trace_.decisions.push_back({t, out.mode, out.reason, out.annotation});
    for (V2vMessage m : out.outbox) {
      m.from_id = 0;
      m.sent_time_s = t;
      channel_.send(m, t, trace_.events);
    }
    out.outbox.clear();
    plan_ = std::move(out);
  }

  void note_non_compliance(std::size_t i, double t) {
    const bool now = drivers_[i].non_compliant(t);
    if (now && !was_non_compliant_[i])
      trace_.events.push_back({t, EventKind::kNonCompliance, s_.vehicles[i].id,
                               to_string(s_.vehicles[i].noncompliance.type), std::nullopt});
    was_non_compliant_[i] = now;
  }

  void advance(double t, double dt) {
    // Every driver decides on the states at t before anyone moves.
    std::vector<double>& accel = accel_scratch_;
    accel.resize(others_.size());  // lane_order_ is up to date: execute() updated it at t
    for (std::size_t i = 0; i < others_.size(); ++i) {
      DriverInput in;
      in.time_s = t;
      in.speed_mps = others_[i].vx_mps;
      const Leaders leaders = lane_order_.leaders(s_, others_, i, ego_);
      in.leader = leaders.with_ego;
      in.leader_main_only = leaders.main_only;
      in.ego_in_lane = std::abs(ego_.y_m - s_.vehicles[i].lane * s_.road.lane_width_m) < kInLaneOffsetM;
      accel[i] = drivers_[i].accel_mps2(in);
      note_non_compliance(i, t);
    }
    EgoCommand cmd;
    cmd.steer_rad = stanley_steering_rad(plan_.path, ego_, s_.ego.dynamics, {},
                                         {s_.params.rules.sideslip_min_speed_mps, s_.ego.limits.accel_max_mps2, dt});
    cmd.accel_mps2 = speed_command_mps2(plan_, ego_.vx_mps, s_.ego.limits);
    ego_ = step_single_track(ego_, cmd, s_.ego.dynamics, s_.ego.limits, dt);
    for (std::size_t i = 0; i < others_.size(); ++i) advance_on_lane(others_[i], accel[i], dt);
  }

  const Scenario& s_;
  Planner& planner_;
  V2vChannel channel_;
  EgoEventDetector detector_;
  VehicleState ego_;
  std::vector<VehicleState> others_;
  std::vector<MainLaneDriver> drivers_;
  std::vector<bool> was_non_compliant_;
  std::vector<V2vMessage> inbox_;
  std::vector<double> accel_scratch_;  // advance()'s, kept to avoid an allocation every step
  LaneOrder lane_order_;
  PlanOutput plan_;
  Trace trace_;
};

}  // namespace

Trace simulate(const Scenario& scenario, Planner& planner) { return Run(scenario, planner).execute(); }

}  // namespace mg
