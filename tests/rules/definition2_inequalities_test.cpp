// Inequalities (3) and (4) of Definition 2 as the rules judge them (rules/definition2_inequalities.h):
// the soundness of the ego's requests at their send, and the responder's positions after it
// accepted.
#include "rules/definition2_inequalities.h"

#include <algorithm>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "trace_builder.h"

namespace mg {
namespace {

using test::base_scenario;
using test::constant_accel_trace;
using test::message_event;
using test::vehicle;

// The ego at X = 0 and vehicle 1 at vehicle_x, both 20 m/s; rho_c = 1 s, rho_m = 4 s, T = 0.5 s;
// default limits (a_acc 2, b_min 4, b_max 8 m/s2, length 4.8 m).
Scenario coop_scenario(double vehicle_x) {
  Scenario s = base_scenario();
  s.vehicles = {vehicle(1, vehicle_x, 20.0)};
  return s;
}

Trace with_request(Trace t, CoopCase c, double target, double d_star, double pc, bool accepted = false) {
  t.events.push_back(message_event(0.0, MessageType::kRequest, 0, 1, c, pc, d_star, target));
  if (accepted) t.events.push_back(message_event(0.1, MessageType::kAccept, 1, 0, c, pc, d_star, target));
  return t;
}

TEST(Def2Inequalities, RampDistanceRampsThenHolds) {
  EXPECT_DOUBLE_EQ(ramp_distance_m(20.0, 16.0, 1.0, 1.0), 18.0);
  EXPECT_DOUBLE_EQ(ramp_distance_m(20.0, 16.0, 1.0, 3.0), 18.0 + 32.0);
  EXPECT_DOUBLE_EQ(ramp_distance_m(20.0, 16.0, 0.0, 2.0), 32.0);
}

// Def. 2.1, vehicle 1 25 m behind, v_o* = 16 m/s (reachable: 20 - 4 x 1), ineq. (3):
//   X_o + (v_o + v_o*)/2 rho_c + v_o* rho_m/2 = -25 + 18 + 32 = 25 m <= P_c - D*_lon,
// and eq. (1) with o at 16 m/s behind the ego at 20 m/s: 24.175 m <= D*_lon.
// P_c = 50, D* = 24.175: margins 0.825, 0 and 0. D* = 30: ineq. (3) fails by 5 m. v_o* = 15:
// beyond b_min,o within rho_c by 1 m/s, i.e. 0.5 m.
TEST(Def2Inequalities, A21RequestIsSoundExactlyWhenIneq3Eq1AndTheReachHold) {
  const Scenario s = coop_scenario(-25.0);
  const Trace base = constant_accel_trace(s, 1.0);
  const MonitorOutput ok = test::run(monitor_def2_request_sound, s, with_request(base, CoopCase::kEgoAhead, 16.0, 24.175, 50.0));
  EXPECT_TRUE(ok.result.holds) << ok.result.detail;
  EXPECT_NEAR(ok.result.min_margin, 0.0, 1e-9);
  const MonitorOutput late = test::run(monitor_def2_request_sound, s, with_request(base, CoopCase::kEgoAhead, 16.0, 30.0, 50.0));
  ASSERT_FALSE(late.result.holds);
  EXPECT_EQ(late.result.liable_id, Party::ego());
  EXPECT_NEAR(late.result.min_margin, -5.0, 1e-9);
  const MonitorOutput deep = test::run(monitor_def2_request_sound, s, with_request(base, CoopCase::kEgoAhead, 15.0, 24.175, 60.0));
  ASSERT_FALSE(deep.result.holds);
  EXPECT_NEAR(deep.result.min_margin, -0.5, 1e-9);
}

// Def. 2.2, v_o* = 22 m/s (reachable: 20 + 2 x 1). The ego brakes at b_min for rho_c: 18 m, to
// 16 m/s; D_lon(rear ego at 16, front o at 22) = 18.925 m. Ineq. (4): 18 <= X_o + 21 - 18.925,
// so vehicle 1 must be at least 15.925 m ahead: at 20 m the request is sound, at 10 m it fails by
// 5.925 m.
TEST(Def2Inequalities, A22RequestIsSoundExactlyWhenIneq4Holds) {
  const Scenario far = coop_scenario(20.0), near = coop_scenario(10.0);
  const MonitorOutput ok =
      test::run(monitor_def2_request_sound, far, with_request(constant_accel_trace(far, 1.0), CoopCase::kEgoBehind, 22.0, 0.0, 0.0));
  EXPECT_TRUE(ok.result.holds) << ok.result.detail;
  const MonitorOutput bad =
      test::run(monitor_def2_request_sound, near, with_request(constant_accel_trace(near, 1.0), CoopCase::kEgoBehind, 22.0, 0.0, 0.0));
  ASSERT_FALSE(bad.result.holds);
  EXPECT_EQ(bad.result.liable_id, Party::ego());
  EXPECT_NEAR(bad.result.min_margin, -5.925, 1e-9);
}

// Vehicle 1 accepts a Def. 2.1 request (v_o* = 16 m/s) at t = 0.1 s and keeps 20 m/s. Its accepted
// profile ramps from 20 to 16 m/s by t_r + rho_c + T = 1.5 s: by tau = t - 0.1 it is ahead of it
// by 1.43 tau^2 m, beyond the tolerance 0.5 tau from tau = 0.35 s (t = 0.45 s). Braking at b_min
// from the acceptance to 16 m/s it stays behind the profile.
TEST(Def2Inequalities, AResponderAheadOfItsAccepted21ProfileIsLiable) {
  const Scenario s = coop_scenario(-25.0);
  const MonitorOutput kept = test::run(
      monitor_def2_positions, s, with_request(constant_accel_trace(s, 3.0), CoopCase::kEgoAhead, 16.0, 24.175, 50.0, true));
  ASSERT_FALSE(kept.result.holds);
  EXPECT_EQ(kept.result.liable_id, Party::vehicle(1));
  EXPECT_GT(*kept.result.first_violation_time_s, 0.44);
  EXPECT_LT(*kept.result.first_violation_time_s, 0.5);
  // Braking at b_min = 4 m/s2 for 1 s from t = 0.1 s (20 -> 16 m/s), then holding.
  Trace braked = constant_accel_trace(s, 3.0);
  for (std::size_t i = 1; i < braked.steps.size(); ++i) {
    TraceStep& st = braked.steps[i];
    const double t = st.time_s, dt = std::clamp(t - 0.1, 0.0, 1.0);
    st.others[0].vx_mps = 20.0 - 4.0 * dt;
    st.others[0].x_m = -25.0 + 20.0 * t - 2.0 * dt * dt - (t > 1.1 ? 4.0 * (t - 1.1) : 0.0);
    st.others[0].accel_mps2 = t > 0.1 && t <= 1.1 ? -4.0 : 0.0;
  }
  const MonitorOutput ok =
      test::run(monitor_def2_positions, s, with_request(braked, CoopCase::kEgoAhead, 16.0, 24.175, 50.0, true));
  EXPECT_TRUE(ok.result.holds) << ok.result.detail;
}

// A request without a number is not skipped: it fails, -1 m, naming what it lacks.
TEST(Def2Inequalities, ARequestWithoutANumberIsUnsound) {
  const Scenario s = coop_scenario(-25.0);
  const Trace t =
      with_request(constant_accel_trace(s, 1.0), CoopCase::kEgoBehind, 22.0, 30.0, std::numeric_limits<double>::quiet_NaN());
  const MonitorOutput out = test::run(monitor_def2_request_sound, s, t);
  ASSERT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_EQ(out.result.min_margin, -1.0);
  EXPECT_NE(out.result.detail.find("carries no P_c"), std::string::npos) << out.result.detail;
}

// def2_request_truthful, the order clause: with vehicle 1 25 m behind the ego (both 4.8 m long,
// so 20.2 m between their bodies), a 2.1 request ("ego ahead") holds by 29.8 m and a 2.2 request
// ("ego behind") fails by 20.2 m, whether or not it was accepted or merged on.
TEST(Def2Inequalities, ARequestsCaseIsHeldToTheOrderObservedAtItsSend) {
  const Scenario s = coop_scenario(-25.0);
  const Trace base = constant_accel_trace(s, 1.0);
  const MonitorOutput ahead =
      test::run(monitor_def2_request_truthful, s, with_request(base, CoopCase::kEgoAhead, 16.0, 24.175, 50.0));
  EXPECT_TRUE(ahead.result.holds);
  EXPECT_NEAR(ahead.result.min_margin, 29.8, 1e-9);
  const MonitorOutput behind =
      test::run(monitor_def2_request_truthful, s, with_request(base, CoopCase::kEgoBehind, 22.0, 30.0, 50.0));
  ASSERT_FALSE(behind.result.holds);
  EXPECT_EQ(behind.result.liable_id, Party::ego());
  EXPECT_NEAR(behind.result.min_margin, -20.2, 1e-9);
  EXPECT_NE(behind.result.detail.find("says the ego is behind it"), std::string::npos) << behind.result.detail;
}

// The profile a responder accepted, which sigmoid_pc_bounds predicts it on, and def2_positions'
// bound around it (the profile plus its tolerance).
TEST(Def2Inequalities, TheAcceptedProfileAndItsBound) {
  const Scenario s = coop_scenario(-25.0);
  const auto j = test::judge(s, with_request(constant_accel_trace(s, 6.0), CoopCase::kEgoAhead, 16.0, 24.175, 50.0, true));
  ASSERT_EQ(j->situation.exchanges.size(), 1u);
  const CoopExchange& x = j->situation.exchanges[0];
  // From -23 m at 20 m/s (t_a = 0.1 s) linearly to 16 m/s by t_r + rho_c = 1 s, then 16: at 3.1 s,
  // 16.2 + 16 x 2.1 = 49.8 m past -23 at 16 m/s. The bound: the same by t_r + rho_c + T = 1.5 s,
  // 25.2 + 16 x 1.6 = 50.8 m, and 0.5 m/s x 3 s farther, at 16.5 m/s.
  const ProfileBound b = accepted_profile_bound(j->context(), x, 1, 3.1);
  ASSERT_TRUE(b.valid);
  EXPECT_NEAR(b.profile_x_m, -23.0 + 16.2 + 33.6, 1e-9);
  EXPECT_NEAR(b.profile_v_mps, 16.0, 1e-9);
  EXPECT_NEAR(b.bound_x_m, -23.0 + 25.2 + 25.6 + 1.5, 1e-9);
  EXPECT_NEAR(b.bound_v_mps, 16.5, 1e-9);
  EXPECT_FALSE(accepted_profile_bound(j->context(), x, 1, 5.1).valid);  // past t_r + rho_c + rho_m
}

}  // namespace
}  // namespace mg
