// The `frenet` baseline (src/planner/frenet*.cpp): the polynomials' boundary conditions
// (Werling et al. 2010 §III), the jerk integral, the discarding of candidates that break the
// limits or reach the side lane's end, and the chosen trajectory free of collisions with the
// obstacles predicted at constant velocity, checked at a far finer step than the planner's.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/scenario.h"
#include "planner/frenet.h"
#include "planner/frenet_planner.h"
#include "planner/mobil_planner.h"
#include "planner/planner.h"

#include "baseline_fixtures.h"

namespace mg {
namespace {

using test::ramp;
using test::real_in;

bool near(double a, double b, double scale) { return std::abs(a - b) <= 1e-9 * (1.0 + scale); }

RC_GTEST_PROP(Frenet, TheQuinticMeetsBothEndStates, ()) {
  const double x0 = real_in(-1000, 1000), v0 = real_in(-50, 50), a0 = real_in(-50, 50);
  const double x1 = real_in(-1000, 1000), v1 = real_in(-50, 50), a1 = real_in(-50, 50), T = real_in(5, 100);
  const QuinticPolynomial q = quintic_between(x0, v0, a0, x1, v1, a1, T);
  const double scale = 100.0 + std::abs(x0) + std::abs(x1);
  RC_ASSERT(q.at(0.0) == x0 && q.d1(0.0) == v0 && near(q.d2(0.0), a0, 0.0));
  RC_ASSERT(near(q.at(T), x1, scale));
  RC_ASSERT(near(q.d1(T), v1, scale));
  RC_ASSERT(near(q.d2(T), a1, scale));
}

RC_GTEST_PROP(Frenet, TheQuarticMeetsTheStartStateAndTheEndSpeed, ()) {
  const double x0 = real_in(-1000, 1000), v0 = real_in(0, 400), a0 = real_in(-80, 30);
  const double v1 = real_in(0, 400), a1 = real_in(-10, 10), T = real_in(5, 100);
  const QuarticPolynomial q = quartic_velocity_keeping(x0, v0, a0, v1, a1, T);
  RC_ASSERT(q.at(0.0) == x0 && q.d1(0.0) == v0 && near(q.d2(0.0), a0, 0.0));
  RC_ASSERT(near(q.d1(T), v1, 100.0));
  RC_ASSERT(near(q.d2(T), a1, 100.0));
}

TEST(Frenet, RestToRestIsTheMinimumJerkProfileAndItsJerkIntegral) {
  // From rest at 0 to rest at h in T: h (10 u^3 - 15 u^4 + 6 u^5), squared jerk integral 720 h^2 / T^5.
  const double h = 3.5, T = 4.0;
  const QuinticPolynomial q = quintic_between(0.0, 0.0, 0.0, h, 0.0, 0.0, T);
  for (double u : {0.1, 0.25, 0.5, 0.9}) EXPECT_NEAR(q.at(u * T), h * min_jerk_blend(u), 1e-12);
  EXPECT_NEAR(squared_jerk_integral(q, T, 0.001), 720.0 * h * h / std::pow(T, 5), 1e-5);  // midpoint rule
  const QuarticPolynomial constant_speed = quartic_velocity_keeping(0.0, 20.0, 0.0, 20.0, 0.0, T);
  EXPECT_DOUBLE_EQ(squared_jerk_integral(constant_speed, T, 0.1), 0.0);
}

TEST(Frenet, TheCostAddsJerkTimeAndDeviations) {
  const FrenetStart start{0.0, 20.0, 0.0, -3.5, 0.0, 0.0};
  const FrenetTrajectory stay = frenet_trajectory(start, -3.5, 20.0, 4.0);
  FrenetCostWeights k;
  // No jerk, end offset 3.5 m from the main lane, 5 m/s below the desired speed.
  EXPECT_NEAR(frenet_cost(stay, 0.0, 25.0, k, 0.1), k.lateral * (k.time * 4.0 + k.deviation * 3.5 * 3.5) + k.longitudinal * (k.time * 4.0 + k.speed * 25.0), 1e-12);
}

FrenetScene open_road() {
  FrenetScene sc;
  sc.ego_length_m = 4.8;
  sc.ego_width_m = 1.9;
  sc.accel_max_mps2 = 2.0;
  sc.brake_max_mps2 = 8.0;
  sc.lat_accel_max_mps2 = 2.0;
  sc.curvature_max_per_m = 0.2;
  sc.lane_width_m = 3.5;
  sc.side_lane_end_x_m = 1e6;
  sc.margin_m = 0.5;
  sc.horizon_s = 6.0;
  sc.step_s = 0.1;
  return sc;
}

TEST(Frenet, DiscardsWhatBreaksTheLimits) {
  const FrenetScene sc = open_road();
  // A lane change in 2 s from 2 m/s: 3.5 m sideways over about 4 m.
  EXPECT_NE(check_trajectory(frenet_trajectory({0.0, 2.0, 0.0, -3.5, 0.0, 0.0}, 0.0, 2.0, 2.0), sc), FrenetVerdict::kValid);
  // From 30 m/s to rest in 2 s: 15 m/s2 and more, past b_max.
  EXPECT_EQ(check_trajectory(frenet_trajectory({0.0, 30.0, 0.0, 0.0, 0.0, 0.0}, 0.0, 0.0, 2.0), sc), FrenetVerdict::kAccel);
  // A lane change in 4 s at 20 m/s is fine.
  EXPECT_EQ(check_trajectory(frenet_trajectory({0.0, 20.0, 0.0, -3.5, 0.0, 0.0}, 0.0, 20.0, 4.0), sc), FrenetVerdict::kValid);
}

TEST(Frenet, TheSideLaneEndIsAStaticObstacle) {
  FrenetScene sc = open_road();
  sc.side_lane_end_x_m = 100.0;
  // Keeping the side lane at 20 m/s reaches its end within the horizon; merging does not.
  EXPECT_EQ(check_trajectory(frenet_trajectory({0.0, 20.0, 0.0, -3.5, 0.0, 0.0}, -3.5, 20.0, 4.0), sc), FrenetVerdict::kSideLaneEnd);
  EXPECT_EQ(check_trajectory(frenet_trajectory({0.0, 20.0, 0.0, -3.5, 0.0, 0.0}, 0.0, 20.0, 4.0), sc), FrenetVerdict::kValid);
}

// Whether the ego's box (no margin) meets an obstacle's at any time of [0, horizon] sampled at 1 ms.
bool collides_finely(const FrenetTrajectory& t, const FrenetScene& sc) {
  for (int i = 0; i * 0.001 <= sc.horizon_s; ++i) {
    const double time_s = i * 0.001;
    for (const PredictedObstacle& o : sc.obstacles)
      if (boxes_meet(t.s_at(time_s), t.d_at(time_s), o, time_s, 0.5 * (sc.ego_length_m + o.length_m),
                     0.5 * (sc.ego_width_m + o.width_m)))
        return true;
  }
  return false;
}

RC_GTEST_PROP(Frenet, TheChosenTrajectoryMeetsNoPredictedObstacle, ()) {
  FrenetScene sc = open_road();
  sc.side_lane_end_x_m = real_in(500, 3000);
  const FrenetStart start{0.0, real_in(0, 300), 0.0, -3.5 + real_in(-5, 5), 0.0, 0.0};
  const int n = *rc::gen::inRange(0, 6);
  for (int i = 0; i < n; ++i)
    sc.obstacles.push_back({i + 1, real_in(-800, 1200), *rc::gen::element(0.0, -3.5), real_in(0, 350), 4.8, 1.9});
  FrenetPlannerParams p;
  const FrenetChoice choice = choose_frenet_trajectory(start, {-3.5, 0.0}, 25.0, sc, p);
  RC_ASSERT(choice.candidates.size() == 2u * 5u * 7u);
  if (!choice.best) return;
  RC_ASSERT(check_trajectory(*choice.best, sc) == FrenetVerdict::kValid);
  RC_ASSERT(!collides_finely(*choice.best, sc));
  for (const FrenetCandidate& c : choice.candidates) {  // the cheapest of the valid: every cheaper one is invalid
    if (c.trajectory.cost < choice.best->cost) RC_ASSERT(check_trajectory(c.trajectory, sc) != FrenetVerdict::kValid);
    if (c.verdict != FrenetVerdict::kNotChecked) RC_ASSERT(c.verdict == check_trajectory(c.trajectory, sc));
  }
}

TEST(FrenetPlanner, MergesIntoAnEmptyMainLane) {
  const Scenario s = ramp();
  FrenetPlanner planner;
  const PlanOutput out = planner.plan(initial_snapshot(s));
  EXPECT_EQ(out.mode, "merge") << out.reason;
  EXPECT_NEAR(out.path.back().y_m, 0.0, 1e-9);
  ASSERT_TRUE(planner.memory().driving.has_value());
}

TEST(FrenetPlanner, KeepsItsLaneBesideAVehicleAndBrakesWhenBoxedIn) {
  Scenario s = ramp();
  MainVehicle beside;
  beside.id = 1;
  beside.x_m = 0.0;
  beside.speed_mps = 20.0;
  s.vehicles = {beside};
  FrenetPlanner planner;
  EXPECT_EQ(planner.plan(initial_snapshot(s)).mode, "keep_side_lane");
  // At the side lane's end at speed, beside the vehicle: nothing is valid.
  s.ego.x_m = 190.0;
  s.vehicles[0].x_m = 190.0;
  FrenetPlanner boxed;
  const PlanOutput out = boxed.plan(initial_snapshot(s));
  EXPECT_EQ(out.mode, "no_valid_trajectory") << out.reason;
  EXPECT_EQ(out.target_speed_mps, std::max(0.0, 20.0 - s.ego.limits.brake_max_mps2));
  EXPECT_DOUBLE_EQ(out.accel_limit_mps2, s.ego.limits.brake_max_mps2);
}

TEST(FrenetPlanner, ItsDefaultsLieInTheirRanges) {
  const FrenetPlannerParams defaults;
  EXPECT_TRUE(params_in_range(frenet_parameter_table(), defaults));
  FrenetPlannerParams bad;
  bad.speed_samples = 1;
  EXPECT_NE(first_out_of_range(frenet_parameter_table(), bad).find("speed_samples"), std::string::npos);
}

TEST(FrenetPlanner, EveryParameterIsDocumentedWithItsDefault) {
  const FrenetPlannerParams defaults;
  for (const auto& row : frenet_parameter_table()) {
    const std::optional<double> documented = test::documented_default(row.name);
    ASSERT_TRUE(documented.has_value()) << row.name << " is not in docs/baselines.md";
    EXPECT_DOUBLE_EQ(*documented, row.value(defaults)) << row.name;
  }
}

}  // namespace
}  // namespace mg
