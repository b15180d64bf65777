// Hand-built scenarios and traces for the monitor tests: every vehicle moves with a constant
// acceleration unless a test edits the steps. Defaults: T = 0.5 s, a_acc = 2, b_min = 4,
// b_max = 8 m/s2, length 4.8 m, width 1.9 m, mu = 0.1 m, a_lat = 0.2, b_lat = 0.8 m/s2.
//
// A test builds a simulator Trace (sim/trace.h) of a Scenario, as a run would produce; the rules
// judge only its observable trace (check/observed_run.h), exactly as rules/check.cpp does: the
// merge phases and attempts are read from the ego's observed motion, the right of way from them
// and from the V2V channel. Planner decisions in a Trace are annotations, never read by a rule.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "check/checked_run.h"
#include "check/observed_run.h"
#include "core/scenario.h"
#include "rules/check.h"
#include "rules/liability.h"
#include "rules/merge_attempts.h"
#include "rules/merge_phases.h"
#include "rules/monitor.h"
#include "rules/situation.h"
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

// The ego's observed lateral motion: in the side lane (Y = -W) until from_s, then toward the main
// lane at vy_mps (the road-frame lateral speed an observer measures) until it is on the main-lane
// centre (Y = 0), where it stays. With W = 3.5 m an observer sees
//
//   start    (Y > -3.4, vy > 0.1) at from_s + 0.1 / vy (the first step after),
//   midpoint (Y >= -1.75)         at from_s + 1.75 / vy,
//   complete (|Y| < 0.2)          at from_s + 3.3 / vy (the first step after).
inline Trace with_lateral_move(Trace t, double from_s, double vy_mps, double lane_width_m = 3.5) {
  for (TraceStep& st : t.steps) {
    const double y = std::min(0.0, -lane_width_m + vy_mps * std::max(0.0, st.time_s - from_s));
    st.ego.y_m = y;
    st.ego.vy_mps = st.time_s >= from_s && y < 0.0 ? vy_mps : 0.0;
  }
  return t;
}

// An aborted attempt: toward the main lane at vy_mps from from_s for out_s seconds, then back at
// the same speed to the side-lane centre (before the lane line when vy_mps * out_s < W/2).
inline Trace with_aborted_move(Trace t, double from_s, double vy_mps, double out_s, double lane_width_m = 3.5) {
  for (TraceStep& st : t.steps) {
    const double dt = st.time_s - from_s;
    double y = -lane_width_m, vy = 0.0;
    if (dt >= 0.0 && dt < out_s) {
      y += vy_mps * dt;
      vy = vy_mps;
    } else if (dt >= out_s && dt < 2.0 * out_s) {
      y += vy_mps * (2.0 * out_s - dt);
      vy = -vy_mps;
    }
    st.ego.y_m = y;
    st.ego.vy_mps = vy;
  }
  return t;
}

// The observable trace of a hand-built run, its channel in time order (tests append messages in
// any order; the simulator records them in order).
inline ObservedTrace observed(const Scenario& s, const Trace& t) {
  ObservedTrace o = observed_trace_of(s, t);
  std::stable_sort(o.channel.begin(), o.channel.end(),
                   [](const ChannelEvent& a, const ChannelEvent& b) { return a.time_s < b.time_s; });
  return o;
}

// What rules/check.cpp infers from an observable trace before it runs the monitors.
struct Judged {
  ObservedTrace trace;
  RuleParams params;
  Situation situation;
  const MergePhases& phases = situation.phases;
  const MergeAttempts& attempts = situation.attempts;
  const RightOfWay& row = situation.row;
  MonitorContext context() const {
    return MonitorContext{trace, row, params, phases, attempts, situation.exchanges};
  }
};

inline std::unique_ptr<Judged> judge(const Scenario& s, const Trace& t) {
  auto j = std::make_unique<Judged>();
  j->trace = observed(s, t);
  j->params = j->trace.params.rules;
  j->situation = observe_situation(j->trace, j->params);
  return j;
}

// Runs one monitor over a trace with the phases, attempts and right of way observed in it.
inline MonitorOutput run(MonitorFn fn, const Scenario& s, const Trace& t) {
  const auto j = judge(s, t);
  return fn(j->context());
}

// A message as its sender put it on the channel (EventKind::kMessageSent) ...
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

// ... and as the channel delivered it at delivered_s.
inline TraceEvent delivered_event(TraceEvent sent, double delivered_s) {
  sent.time_s = delivered_s;
  sent.kind = EventKind::kMessageDelivered;
  return sent;
}

}  // namespace mg::test
