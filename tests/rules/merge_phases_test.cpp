// The merge phases the rules observe (rules/merge_phases.h): on the curated scenarios with the
// planners that drive them, read from the run's observable trace with the default thresholds
// they fall on the simulator's merge events; on hand-built motions, a start needs lateral motion
// toward the main lane, a return to the side lane before the line is an abort.
#include "rules/merge_phases.h"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "check/observed_run.h"
#include "planner/planner.h"
#include "sim/simulator.h"
#include "trace_builder.h"

namespace mg {
namespace {

std::optional<double> first_event_s(const Trace& t, EventKind k) {
  for (const TraceEvent& e : t.events)
    if (e.kind == k && e.vehicle_id == 0) return e.time_s;
  return std::nullopt;
}

TEST(MergePhases, ObservedFromTheRunsTraceTheyFallOnTheSimulatorsMergeEvents) {
  int merged = 0;
  for (const auto& [name, planner] : {std::pair{"responder_reneges", "rcpp-coop"}, {"leader_overbrakes", "rcpp"},
                                      {"fig2_s3_ahead_coop", "rcpp-coop"}, {"fig2_s2_behind_noncoop", "tripfield"}}) {
    const Scenario s = load_scenario(std::string(MG_SOURCE_DIR) + "/corpus/scenarios/" + name + ".json");
    const Trace t = simulate(s, *make_planner(planner));
    const MergePhases from_run = observe_merge_phases(observed_trace_of(s, t), s.params.rules);
    for (const MergePhaseEvent& e : from_run.events) EXPECT_EQ(e.time_s, t.steps[e.step].time_s) << name;
    const auto time_of = [&](MergePhaseKind k) -> std::optional<double> {
      const auto e = from_run.first(k);
      return e ? std::optional(e->time_s) : std::nullopt;
    };
    EXPECT_EQ(time_of(MergePhaseKind::kStart), first_event_s(t, EventKind::kMergeStart)) << name;
    EXPECT_EQ(time_of(MergePhaseKind::kMidpoint), first_event_s(t, EventKind::kMergeMidpoint)) << name;
    EXPECT_EQ(time_of(MergePhaseKind::kComplete), first_event_s(t, EventKind::kMergeComplete)) << name;
    merged += time_of(MergePhaseKind::kComplete).has_value();
  }
  EXPECT_GE(merged, 3) << "most of these scenarios end with a completed merge";
}

TEST(MergePhases, AnEgoThatStartsInTheMainLaneNeverMerges) {
  Scenario s = load_scenario(std::string(MG_SOURCE_DIR) + "/corpus/scenarios/fig2_s1_ahead_noncoop.json");
  s.ego.y_m = 0.0;
  s.params.sim.horizon_s = 3.0;
  const Trace t = simulate(s, *make_planner("rcpp"));
  EXPECT_TRUE(observe_merge_phases(observed_trace_of(s, t), s.params.rules).events.empty());
}

MergePhases phases_of(const Scenario& s, const Trace& t) { return test::judge(s, t)->phases; }

std::vector<MergePhaseKind> kinds(const MergePhases& p) {
  std::vector<MergePhaseKind> out;
  for (const MergePhaseEvent& e : p.events) out.push_back(e.kind);
  return out;
}

TEST(MergePhases, AStraightMergeIsStartMidpointComplete) {
  // From the side-lane centre (Y = -3.5) toward the main lane at 1 m/s from t = 1 s: Y passes
  // -3.4 at 1.1 s (start, the first step after), the line -1.75 at 2.75 s (midpoint, exact on the
  // 0.02 s grid) and -0.2 at 4.3 s (complete, heading 0).
  const Scenario s = test::base_scenario();
  const MergePhases p = phases_of(s, test::with_lateral_move(test::constant_accel_trace(s, 6.0), 1.0, 1.0));
  ASSERT_EQ(kinds(p), (std::vector{MergePhaseKind::kStart, MergePhaseKind::kMidpoint, MergePhaseKind::kComplete}));
  EXPECT_NEAR(p.events[0].time_s, 1.1, 0.021);
  EXPECT_NEAR(p.events[1].time_s, 2.75, 0.011);
  EXPECT_NEAR(p.events[2].time_s, 4.3, 0.021);
}

TEST(MergePhases, AnOffsetWithoutLateralMotionIsNoStart) {
  // An ego placed 0.3 m off its lane centre toward the main lane and driving straight has not
  // started merging; neither has one drifting back to its lane centre.
  Scenario s = test::base_scenario();
  s.ego.y_m = -3.2;
  EXPECT_TRUE(phases_of(s, test::constant_accel_trace(s, 2.0)).events.empty());
  Trace back = test::constant_accel_trace(s, 2.0);
  for (TraceStep& st : back.steps) {
    st.ego.y_m = std::max(-3.5, -3.2 - 0.5 * st.time_s);
    st.ego.vy_mps = st.ego.y_m > -3.5 ? -0.5 : 0.0;
  }
  EXPECT_TRUE(phases_of(s, back).events.empty());
}

// A crawl merge: off its lane centre toward the main lane at 0.15 m/s for 0.4 s (6 cm), then on at
// 0.03 m/s, within the hysteresis (0.1 m/s), past the start offset (0.1 m) at about 1.9 s. It is
// the approach it was, and starts there; one that never moved faster than the hysteresis (a
// drift), or whose last motion beyond it was back toward the side lane, does not.
TEST(MergePhases, AnApproachThatSlowsWithinTheHysteresisStartsWhereItPassesTheOffset) {
  const Scenario s = test::base_scenario();
  const auto moving = [&](double first_vy_mps, double then_vy_mps) {
    Trace t = test::constant_accel_trace(s, 4.0);
    for (TraceStep& st : t.steps) {
      const double first_s = std::min(st.time_s, 0.4), then_s = std::max(0.0, st.time_s - 0.4);
      st.ego.y_m = -3.5 + first_vy_mps * first_s + then_vy_mps * then_s;
      st.ego.vy_mps = st.time_s < 0.4 ? first_vy_mps : then_vy_mps;
    }
    return phases_of(s, t);
  };
  const MergePhases crawl = moving(0.15, 0.03);
  ASSERT_EQ(kinds(crawl), (std::vector{MergePhaseKind::kStart}));
  EXPECT_NEAR(crawl.events[0].time_s, 0.4 + 0.04 / 0.03, 0.021);
  EXPECT_TRUE(moving(0.05, 0.05).events.empty()) << "a drift within the hysteresis all along";
  Scenario off = s;
  off.ego.y_m = -3.2;  // placed off the centre, moving back to it fast, then creeping outward
  Trace back = test::constant_accel_trace(off, 4.0);
  for (TraceStep& st : back.steps) {
    st.ego.y_m = st.time_s < 0.4 ? -3.2 - 0.15 * st.time_s : -3.26 + 0.03 * (st.time_s - 0.4);
    st.ego.vy_mps = st.time_s < 0.4 ? -0.15 : 0.03;
  }
  EXPECT_TRUE(phases_of(off, back).events.empty());
}

TEST(MergePhases, BackInTheSideLaneBeforeTheLineIsAnAbortAndTheNextDepartureANewStart) {
  // Out at 1 m/s for 1 s (to Y = -2.5, short of the line) and back, twice: start, abort, start,
  // abort. A rest of the motion leaves the ego on its lane centre.
  const Scenario s = test::base_scenario();
  Trace t = test::with_aborted_move(test::constant_accel_trace(s, 6.0), 0.5, 1.0, 1.0);
  const Trace second = test::with_aborted_move(test::constant_accel_trace(s, 6.0), 3.0, 1.0, 1.0);
  for (std::size_t i = 0; i < t.steps.size(); ++i)
    if (t.steps[i].time_s >= 3.0) t.steps[i].ego = second.steps[i].ego;
  const MergePhases p = phases_of(s, t);
  ASSERT_EQ(kinds(p), (std::vector{MergePhaseKind::kStart, MergePhaseKind::kAbort, MergePhaseKind::kStart,
                                   MergePhaseKind::kAbort}));
  EXPECT_EQ(p.count(MergePhaseKind::kStart), 2);
  EXPECT_LT(p.events[1].time_s, 2.5 + 1e-9);  // back within 0.05 m of the centre before 2.5 s
  EXPECT_GT(p.events[2].time_s, 3.0);
}

}  // namespace
}  // namespace mg
