#include "sim/single_track.h"

#include <cmath>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "planner/merge_path.h"
#include "sim/simulator.h"
#include "test_egos.h"
#include "test_planners.h"

namespace mg {
namespace {

VehicleState moving(double speed_mps) {
  VehicleState s;
  s.vx_mps = speed_mps;
  return s;
}

TEST(SingleTrack, StraightDrivingWithZeroSteeringKeepsLateralPositionAndYaw) {
  const EgoDynamics d;
  const Limits lim;
  VehicleState s = moving(25.0);
  s.y_m = -3.5;
  for (int i = 0; i < 1000; ++i) s = step_single_track(s, {0.0, 0.5}, d, lim, 0.02);
  EXPECT_EQ(s.y_m, -3.5);
  EXPECT_EQ(s.yaw_rad, 0.0);
  EXPECT_EQ(s.vy_mps, 0.0);
  EXPECT_NEAR(s.vx_mps, 25.0 + 0.5 * 20.0, 1e-9);
  EXPECT_NEAR(s.x_m, 25.0 * 20.0 + 0.25 * 400.0, 1e-6);
}

TEST(SingleTrack, SteadyStateYawRateMatchesLinearSingleTrackGain) {
  const EgoDynamics d;  // understeering: l_r C_r > l_f C_f
  ASSERT_GT(understeer_gradient(d), 0.0);
  const Limits lim;
  for (double speed : {8.0, 15.0, 25.0}) {
    const double steer = 0.01;
    VehicleState s = moving(speed);
    s.steer_rad = steer;
    for (int i = 0; i < 1500; ++i) s = step_single_track(s, {steer, 0.0}, d, lim, 0.02);
    const double expected = steady_state_yaw_rate_gain(d, speed) * steer;  // r/delta = v/(L + K v^2)
    EXPECT_NEAR(s.yaw_rate_radps, expected, 0.02 * expected) << "speed " << speed;
  }
}

// The planner's steady-state sideslip per unit curvature (planner/merge_path.h), which bounds the
// return path's curvature, is this simulator's: beta / (r / v) at a held steering angle, for an
// understeering and a soft neutral-steer ego (the generator's boundary, where it is largest).
TEST(SingleTrack, SteadySideslipPerCurvatureMatchesThePlannersFormula) {
  const EgoDynamics soft = test::soft_neutral_steer_ego();
  const Limits lim;
  for (const EgoDynamics& d : {EgoDynamics{}, soft}) {
    for (double speed : {8.0, 15.0, 25.0, 33.0}) {
      const double steer = 0.005;
      VehicleState s = moving(speed);
      s.steer_rad = steer;
      for (int i = 0; i < 2000; ++i) s = step_single_track(s, {steer, 0.0}, d, lim, 0.02);
      const double per_curvature_m = sideslip_rad(s) / (s.yaw_rate_radps / s.vx_mps);
      EXPECT_NEAR(per_curvature_m, steady_sideslip_per_curvature_m(d, s.vx_mps),
                  0.02 * std::abs(steady_sideslip_per_curvature_m(d, s.vx_mps)))
          << "speed " << speed << " mass " << d.mass_kg;
    }
  }
}

TEST(SingleTrack, FullBrakingStopsWithinBrakingDistance) {
  const EgoDynamics d;
  const Limits lim;
  const double v0 = 30.0;
  VehicleState s = moving(v0);
  for (int i = 0; i < 1000; ++i) s = step_single_track(s, {0.0, -100.0}, d, lim, 0.02);
  EXPECT_EQ(s.vx_mps, 0.0);
  EXPECT_LE(s.x_m, v0 * v0 / (2.0 * lim.brake_max_mps2) + 1e-9);
  EXPECT_GE(s.x_m, v0 * v0 / (2.0 * lim.brake_max_mps2) - 1e-6);
}

// Closed loop: the planner commands a stop at t = 1 s; the ego reacts at the next planner
// cycle, so it stops within v^2/(2 b_max) plus the response distance v * planner_cycle.
class BrakeAtPlanner : public Planner {
 public:
  std::string name() const override { return "test-brake"; }
  PlanOutput plan(const WorldSnapshot& w) override {
    PlanOutput out;
    out.path = test::line_at(w.ego.x_m, -3.5);
    const bool brake = w.time_s >= 1.0 - 1e-9;
    out.target_speed_mps = brake ? 0.0 : w.ego.vx_mps;
    out.accel_limit_mps2 = brake ? 100.0 : 0.0;
    out.proper_response = brake;
    return out;
  }
};

TEST(SingleTrack, ClosedLoopFullBrakingStopsWithinBrakingPlusResponseDistance) {
  Scenario s = test::empty_scenario();
  s.ego.speed_mps = 25.0;
  s.params.sim.planner_cycle_s = 0.1;
  BrakeAtPlanner planner;
  const Trace t = simulate(s, planner);
  const double x_at_command = 25.0 * 1.0;
  const double v = 25.0;
  const double bound = v * v / (2.0 * s.ego.limits.brake_max_mps2) + v * s.params.sim.planner_cycle_s;
  EXPECT_EQ(t.steps.back().ego.vx_mps, 0.0);
  EXPECT_LE(t.steps.back().ego.x_m - x_at_command, bound);
}

TEST(SingleTrack, HaltsAndStartsAgainThroughTheKinematicRegime) {
  const EgoDynamics d;
  const Limits lim;
  VehicleState s = moving(12.0);
  s.steer_rad = 0.05;
  for (int i = 0; i < 400; ++i) s = step_single_track(s, {0.05, -6.0}, d, lim, 0.02);
  EXPECT_EQ(s.vx_mps, 0.0);
  const double x_halt = s.x_m;
  for (int i = 0; i < 50; ++i) s = step_single_track(s, {0.05, -6.0}, d, lim, 0.02);
  EXPECT_EQ(s.x_m, x_halt) << "a halted ego does not creep or reverse";
  for (int i = 0; i < 400; ++i) s = step_single_track(s, {0.0, 2.0}, d, lim, 0.02);
  EXPECT_NEAR(std::hypot(s.vx_mps, s.vy_mps), 16.0, 0.05);
  EXPECT_GT(s.x_m, x_halt + 50.0);
}

TEST(SingleTrack, SteeringRespectsRateAndAngleLimits) {
  const EgoDynamics d;
  EXPECT_DOUBLE_EQ(limit_steering(0.0, 1.0, d, 0.1), d.steer_rate_max_radps * 0.1);
  EXPECT_DOUBLE_EQ(limit_steering(0.49, 1.0, d, 0.1), d.steer_max_rad);
  EXPECT_DOUBLE_EQ(limit_steering(0.0, -1.0, d, 0.1), -d.steer_rate_max_radps * 0.1);
}

RC_GTEST_PROP(SingleTrack, StaysFiniteAndNeverReversesUnderRandomCommands, ()) {
  const EgoDynamics d;
  const Limits lim;
  VehicleState s = moving(*rc::gen::inRange(0, 45));
  const auto segments = *rc::gen::container<std::vector<std::tuple<int, int, int>>>(
      20, rc::gen::tuple(rc::gen::inRange(-600, 601), rc::gen::inRange(-1500, 600), rc::gen::inRange(1, 100)));
  for (const auto& [steer_mrad, accel_cmps2, steps] : segments) {
    const EgoCommand cmd{steer_mrad / 1000.0, accel_cmps2 / 100.0};
    for (int i = 0; i < steps; ++i) {
      s = step_single_track(s, cmd, d, lim, 0.02);
      for (double v : {s.x_m, s.y_m, s.yaw_rad, s.vx_mps, s.vy_mps, s.yaw_rate_radps, s.accel_mps2, s.steer_rad})
        RC_ASSERT(std::isfinite(v));
      RC_ASSERT(s.vx_mps >= 0.0);
      RC_ASSERT(std::abs(s.steer_rad) <= d.steer_max_rad);
      RC_ASSERT(s.accel_mps2 >= -lim.brake_max_mps2 - 1e-9);
      RC_ASSERT(s.accel_mps2 <= lim.accel_max_mps2);
    }
  }
}

TEST(SingleTrack, SideslipIsZeroAtStandstillAndSignedWithLateralSpeed) {
  VehicleState s;
  EXPECT_EQ(sideslip_rad(s), 0.0);
  s.vx_mps = 10.0;
  s.vy_mps = 0.1;
  EXPECT_NEAR(sideslip_rad(s), std::atan2(0.1, 10.0), 1e-15);
}

}  // namespace
}  // namespace mg
