// A run's league metrics (src/league/league_metrics.cpp) on hand-built observed traces: an ego
// that waits at rest for a second, then drives at 10 m/s and changes lanes along a 4 s
// minimum-jerk profile, and one that never leaves the side lane.
#include "league/league_metrics.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/observed_trace.h"
#include "rules/merge_phases.h"

namespace mg::league {
namespace {

constexpr double kDt = 0.02;
constexpr double kLaneChangeStartS = 2.0, kLaneChangeS = 4.0, kSpeedMps = 10.0, kLaneWidthM = 3.5;

double blend(double u) { return u <= 0 ? 0 : u >= 1 ? 1 : u * u * u * (10 - 15 * u + 6 * u * u); }
double blend_rate(double u) { return u <= 0 || u >= 1 ? 0 : 30 * u * u * (1 - u) * (1 - u); }

// At rest for 1 s, then kSpeedMps; the lane change from the side lane's centre to the main lane's
// over [2 s, 6 s] when `change`; 10 s in all.
ObservedTrace trace(bool change) {
  ObservedTrace t;
  t.road.lane_width_m = kLaneWidthM;
  t.road.side_lane_end_x_m = 1000.0;
  t.vehicles.push_back(VehicleDeclaration{});
  double x = 0.0;
  for (int i = 0; i * kDt <= 10.0 + 1e-9; ++i) {
    const double time_s = i * kDt;
    const double vx = time_s < 1.0 ? 0.0 : kSpeedMps;
    const double u = (time_s - kLaneChangeStartS) / kLaneChangeS;
    ObservedState ego;
    ego.x_m = x;
    ego.y_m = -kLaneWidthM + (change ? kLaneWidthM * blend(u) : 0.0);
    ego.vx_mps = vx;
    ego.vy_mps = change ? kLaneWidthM * blend_rate(u) / kLaneChangeS : 0.0;
    ego.yaw_rad = vx > 0 ? std::atan2(ego.vy_mps, vx) : 0.0;
    t.steps.push_back({time_s, {ego}});
    x += vx * kDt;
  }
  return t;
}

TEST(LeagueMetrics, AMergeIsReadFromTheObservedMotion) {
  const ObservedTrace t = trace(true);
  const RuleParams rules;
  const RunMetrics m = run_metrics(t, rules);
  ASSERT_TRUE(m.merged);
  const auto complete = observe_merge_phases(t, rules).first(MergePhaseKind::kComplete);
  ASSERT_TRUE(complete.has_value());
  EXPECT_DOUBLE_EQ(*m.merge_time_s, complete->time_s);
  EXPECT_GT(*m.merge_time_s, kLaneChangeStartS + 0.5 * kLaneChangeS);
  EXPECT_LE(*m.merge_time_s, kLaneChangeStartS + kLaneChangeS + kDt);
  // The path from the attempt's start to its completion: at least its X distance, at most that
  // plus the lane width.
  const auto start = observe_merge_phases(t, rules).first(MergePhaseKind::kStart);
  ASSERT_TRUE(start.has_value());
  const double dx = kSpeedMps * (complete->time_s - start->time_s);
  EXPECT_GE(*m.path_length_m, dx - 1e-9);
  EXPECT_LE(*m.path_length_m, dx + kLaneWidthM);
  // Peak lateral acceleration of the minimum-jerk profile: 10 sqrt(3)/3 h / T^2.
  EXPECT_NEAR(m.peak_lat_accel_mps2, 10.0 * std::sqrt(3.0) / 3.0 * kLaneWidthM / (kLaneChangeS * kLaneChangeS), 0.02);
  EXPECT_NEAR(m.halted_s, 1.0, 1e-9);  // the first second, 50 steps of 0.02 s
}

TEST(LeagueMetrics, AnEgoThatStaysInTheSideLaneHasNoMerge) {
  const RunMetrics m = run_metrics(trace(false), RuleParams{});
  EXPECT_FALSE(m.merged);
  EXPECT_FALSE(m.merge_time_s.has_value());
  EXPECT_FALSE(m.path_length_m.has_value());
  EXPECT_EQ(m.peak_lat_accel_mps2, 0.0);
  EXPECT_NEAR(m.halted_s, 1.0, 1e-9);
}

TEST(LeagueMetrics, AnEmptyTraceMeasuresNothing) {
  const RunMetrics m = run_metrics(ObservedTrace{}, RuleParams{});
  EXPECT_FALSE(m.merged);
  EXPECT_EQ(m.halted_s, 0.0);
}

}  // namespace
}  // namespace mg::league
