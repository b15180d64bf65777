#include "rules/smoothness_monitor.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "planner/reversal_ledger.h"
#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;

Trace with_lateral_speed(Trace t, double (*vy)(double)) {
  for (auto& st : t.steps) st.ego.vy_mps = vy(st.time_s);
  return t;
}

TEST(SmoothnessMonitor, OneLateralHumpHasNoSignChange) {
  // vy = 0.5 sin(pi t / 4) for 4 s, then 0: positive only. Margin 2 - 0 = 2.
  const Scenario s = base_scenario();
  const MonitorOutput out = test::run(
      monitor_smoothness_oscillation, s,
      with_lateral_speed(constant_accel_trace(s, 6.0), [](double t) { return t < 4.0 ? 0.5 * std::sin(std::numbers::pi * t / 4.0) : 0.0; }));
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 2.0, 1e-12);
}

TEST(SmoothnessMonitor, WeavingPathViolates) {
  // vy = 0.5 sin(pi t) over 6 s changes sign at t = 1, 2, 3, 4, 5 (|vy| > 0.1 between them):
  // 5 changes, no merge event: allowed 2. Margin 2 - 5 = -3.
  const Scenario s = base_scenario();
  const MonitorOutput out = test::run(
      monitor_smoothness_oscillation, s,
      with_lateral_speed(constant_accel_trace(s, 6.0), [](double t) { return 0.5 * std::sin(std::numbers::pi * t); }));
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -3.0, 1e-12);
}

// The ego's lateral speed vy(t), its Y integrated from the side-lane centre: what an observer
// sees of a lateral path.
Trace with_lateral_path(Trace t, double (*vy)(double)) {
  double y = t.steps.front().ego.y_m;
  for (auto& st : t.steps) {
    st.ego.y_m = y;
    st.ego.vy_mps = vy(st.time_s);
    y += st.ego.vy_mps * 0.02;
  }
  return t;
}

// A merge, an abort and a second merge: out at 0.5 m/s for 1.5 s (Y -3.5 -> -2.75, short of the
// line), back at 0.5 m/s to the side-lane centre (the abort), out again and back again: vy = +0.5,
// -0.5, +0.5, -0.5 over four 1.5 s phases, three sign changes from the first start. Two observed
// attempts allow 4 changes: margin 4 - 3 = 1.
TEST(SmoothnessMonitor, AMergeAbortedBackToTheSideLaneIsAnAttemptOfItsOwn) {
  const Scenario s = base_scenario();
  const Trace t = with_lateral_path(constant_accel_trace(s, 6.0), [](double t) {
    return t < 1.5 ? 0.5 : t < 3.0 ? -0.5 : t < 4.5 ? 0.5 : -0.5;
  });
  ASSERT_EQ(test::judge(s, t)->phases.count(MergePhaseKind::kStart), 2);
  const MonitorOutput out = test::run(monitor_smoothness_oscillation, s, t);
  EXPECT_TRUE(out.result.holds);
  EXPECT_NEAR(out.result.min_margin, 1.0, 1e-12);
}

TEST(SmoothnessMonitor, ThreeSignChangesInOneMergeViolate) {
  // Three reversals too small to be aborts: 0.1 s at vy = -0.3 takes the ego back 0.03 m, under
  // the 0.05 m reversal hysteresis (merge_abort_reversal_m). One observed attempt allows 2 sign
  // changes; by t = 3.1 s it has made 3: margin -1 (a fourth at 3.1 s gives -2).
  const Scenario s = base_scenario();
  const Trace t = with_lateral_path(constant_accel_trace(s, 6.0), [](double t) {
    return t < 1.5 ? 0.5 : t < 1.6 ? -0.3 : t < 3.0 ? 0.5 : t < 3.1 ? -0.3 : 0.5;
  });
  ASSERT_EQ(test::judge(s, t)->phases.count(MergePhaseKind::kStart), 1);
  const MonitorOutput out = test::run(monitor_smoothness_oscillation, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(out.result.min_margin, -2.0, 1e-12);
}

TEST(SmoothnessMonitor, TurningBackByMoreThanTheReversalHysteresisIsAnAbort) {
  // vy = +0.5 for 1.5 s, then -0.3 for 0.5 s: 0.15 m back toward the side lane, an abort; the
  // next departure is a second attempt.
  const Scenario s = base_scenario();
  const Trace t = with_lateral_path(constant_accel_trace(s, 6.0), [](double t) {
    return t < 1.5 ? 0.5 : t < 2.0 ? -0.3 : 0.5;
  });
  const auto j = test::judge(s, t);
  EXPECT_EQ(j->phases.count(MergePhaseKind::kAbort), 1);
  EXPECT_EQ(j->phases.count(MergePhaseKind::kStart), 2);
}

// RCPP keeps its weaving within this rule by counting its own approaches and reversals
// (planner/reversal_ledger.h) from what it observes every cycle. On any lateral motion observed at
// the planner's cycle, the ledger's count is the rule's: allowance minus changes is the margin.
RC_GTEST_PROP(SmoothnessMonitor, ThePlannersReversalLedgerCountsAsTheRuleDoes, ()) {
  // (vy / 0.05 m/s, steps of 0.1 s): a departure (a start) first, then anything.
  auto segments = *rc::gen::container<std::vector<std::pair<int, int>>>(
      *rc::gen::inRange<std::size_t>(0, 12), rc::gen::pair(rc::gen::inRange(-12, 13), rc::gen::inRange(1, 20)));
  segments.insert(segments.begin(), *rc::gen::pair(rc::gen::inRange(4, 13), rc::gen::inRange(6, 20)));
  const Scenario s = base_scenario();
  Trace t;
  t.planner = "hand_built";
  ReversalLedger ledger;
  WorldSnapshot w;
  w.setup = &s;
  w.ego.y_m = s.ego.y_m;
  w.ego.vx_mps = s.ego.speed_mps;
  for (const auto& [vy_steps, n] : segments) {
    for (int k = 0; k < n; ++k) {
      w.ego.vy_mps = 0.05 * vy_steps;
      ledger.observe(w);
      t.steps.push_back(TraceStep{});
      t.steps.back().time_s = w.time_s;
      t.steps.back().ego = w.ego;
      w.ego.x_m += w.ego.vx_mps * 0.1;
      w.ego.y_m += w.ego.vy_mps * 0.1;
      w.time_s += 0.1;
    }
  }
  RC_PRE(t.steps.size() >= 2u);
  // With no start the rule counts the weave from the first step, the ledger nothing (no merge).
  RC_CLASSIFY(ledger.approaches() > 0, "with a start");
  if (ledger.approaches() == 0) return;
  const MonitorOutput out = test::run(monitor_smoothness_oscillation, s, t);
  const int allowed = s.params.rules.max_lat_speed_sign_changes_per_merge * ledger.approaches();
  RC_ASSERT(out.result.min_margin == static_cast<double>(allowed - ledger.changes()));
}

TEST(SmoothnessMonitor, SideslipMarginIsBoundMinusAbsoluteSideslip) {
  // vx = 20, vy = 0.5: beta = atan(0.025) = 0.024995; margin 0.05 - 0.024995 = 0.025005 rad.
  // vy = 2: beta = atan(0.1) = 0.099669; margin -0.049669 rad.
  const Scenario s = base_scenario();
  const MonitorOutput ok =
      test::run(monitor_sideslip, s, with_lateral_speed(constant_accel_trace(s, 0.5), [](double) { return 0.5; }));
  EXPECT_NEAR(ok.result.min_margin, 0.05 - std::atan(0.025), 1e-12);
  const MonitorOutput bad =
      test::run(monitor_sideslip, s, with_lateral_speed(constant_accel_trace(s, 0.5), [](double) { return 2.0; }));
  ASSERT_FALSE(bad.result.holds);
  EXPECT_NEAR(bad.result.min_margin, 0.05 - std::atan(0.1), 1e-12);
}

}  // namespace
}  // namespace mg
