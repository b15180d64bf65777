// Hand-built scenarios and traces for the monitor tests: every vehicle moves with a constant
// acceleration unless a test edits the steps. Defaults: T = 0.5 s, a_acc = 2, b_min = 4,
// b_max = 8 m/s2, length 4.8 m, width 1.9 m, mu = 0.1 m, a_lat = 0.2, b_lat = 0.8 m/s2.
#pragma once

#include <functional>

#include "core/scenario.h"
#include "rules/check.h"
#include "rules/liability.h"
#include "rules/merge_phases.h"
#include "rules/monitor.h"
#include "sim/trace.h"

namespace mg::test {

inline Scenario base_scenario() {
  Scenario s;
  s.name = "hand_built";
  s.ego.x_m = 0.0;
  s.ego.y_m = -3.5;
  s.ego.speed_mps = 20.0;
  return s;
}

inline MainVehicle vehicle(int id, double x_m, double speed_mps) {
  MainVehicle v;
  v.id = id;
  v.x_m = x_m;
  v.speed_mps = speed_mps;
  return v;
}

// Steps every dt from 0 to duration (inclusive); each vehicle starts at its scenario state
// and integrates its accel (constant, from `accel` per vehicle index: 0 = ego).
inline Trace constant_accel_trace(const Scenario& s, double duration_s, std::vector<double> accel = {},
                                  double dt = 0.02) {
  accel.resize(s.vehicles.size() + 1, 0.0);
  Trace t;
  t.planner = "hand_built";
  VehicleState ego;
  ego.x_m = s.ego.x_m;
  ego.y_m = s.ego.y_m;
  ego.vx_mps = s.ego.speed_mps;
  std::vector<VehicleState> others;
  for (const auto& v : s.vehicles) {
    VehicleState o;
    o.x_m = v.x_m;
    o.y_m = v.lane * s.road.lane_width_m;
    o.vx_mps = v.speed_mps;
    others.push_back(o);
  }
  const int n = static_cast<int>(duration_s / dt + 0.5);
  for (int i = 0; i <= n; ++i) {
    TraceStep st;
    st.time_s = i * dt;
    st.ego = ego;
    st.ego.accel_mps2 = accel[0];
    st.others = others;
    for (std::size_t k = 0; k < others.size(); ++k) st.others[k].accel_mps2 = accel[k + 1];
    t.steps.push_back(st);
    auto advance = [dt](VehicleState& v, double a) {
      v.x_m += v.vx_mps * dt + a * dt * dt / 2.0;
      v.vx_mps = std::max(0.0, v.vx_mps + a * dt);
    };
    advance(ego, accel[0]);
    for (std::size_t k = 0; k < others.size(); ++k) advance(others[k], accel[k + 1]);
  }
  return t;
}

// Runs one monitor over a trace with the right of way derived from it.
inline MonitorOutput run(MonitorFn fn, const Scenario& s, const Trace& t) {
  const MergePhases phases = observe_merge_phases(s, t);
  const RightOfWay row = compute_right_of_way(s, t, phases);
  return fn(MonitorContext{s, t, row, catalog_params(), phases});
}

inline TraceEvent message_event(double time_s, MessageType type, int from, int to, CoopCase c, double pc_m,
                                double d_star_m, double target_mps) {
  V2vMessage m;
  m.type = type;
  m.from_id = from;
  m.to_id = to;
  m.sent_time_s = time_s;
  m.coop_case = c;
  m.pc_m = pc_m;
  m.d_lon_star_m = d_star_m;
  m.target_speed_mps = target_mps;
  return TraceEvent{time_s, EventKind::kMessageSent, from, "", m};
}

}  // namespace mg::test
