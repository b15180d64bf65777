#include "paper/paper_claims.h"

#include <cmath>

#include <gtest/gtest.h>

namespace mg {
namespace {

// A trace of `steps` steps 0.1 s apart: ego at 20 m/s, the obstacle at 18 m/s, both steady.
Trace steady_trace(int steps) {
  Trace t;
  for (int k = 0; k < steps; ++k) {
    TraceStep s;
    s.time_s = 0.1 * k;
    s.ego.vx_mps = 20.0;
    VehicleState o;
    o.vx_mps = 18.0;
    s.others.push_back(o);
    t.steps.push_back(s);
  }
  return t;
}

TraceEvent delivered(double time_s, MessageType type, int from, int to) {
  V2vMessage m;
  m.type = type;
  m.from_id = from;
  m.to_id = to;
  return TraceEvent{time_s, EventKind::kMessageDelivered, to, "", m};
}

// Metrics in the paper's ranges (§IV): every claim holds.
std::vector<PaperRun> paper_like_runs() {
  PaperMetrics tf, nc, co;
  tf.merged = nc.merged = co.merged = true;
  tf.merge_start_time_s = 5.0, tf.merge_time_s = 10.0, tf.path_length_m = 100.0, tf.merge_x_m = 226.0;
  tf.lateral_reversals = 2, tf.sideslip_min_rad = -0.015, tf.sideslip_max_rad = 0.015;
  tf.ego_speed_min_mps = 8.0, tf.obstacle_speed_min_mps = 9.0;
  nc.merge_start_time_s = 1.0, nc.merge_time_s = 3.0, nc.path_length_m = 50.0;
  nc.sideslip_min_rad = -0.01, nc.sideslip_max_rad = 0.015, nc.ego_speed_min_mps = 20.0, nc.ego_speed_max_mps = 30.0;
  nc.obstacle_speed_min_mps = 16.0;
  co.merge_start_time_s = 2.0, co.merge_time_s = 2.8, co.path_length_m = 46.0;
  co.ego_speed_min_mps = 19.5, co.ego_speed_max_mps = 20.5, co.obstacle_speed_min_mps = 15.0;
  Trace tf_trace = steady_trace(10), nc_trace = steady_trace(50), co_trace = steady_trace(50);
  nc_trace.steps[30].others[0].accel_mps2 = -1.0;  // non-coop: the obstacle brakes at 3.0 s
  co_trace.steps[12].others[0].accel_mps2 = -2.0;  // coop: at 1.2 s, before the ego moves (2.0 s)
  co_trace.steps[40].ego.vy_mps = 20.0 * std::tan(0.024);  // sideslip peak 0.024 rad at 4.0 s
  co_trace.events.push_back(delivered(0.2, MessageType::kRequest, 0, 1));
  co_trace.events.push_back(delivered(0.5, MessageType::kAccept, 1, 0));
  return {{"tripfield", tf_trace, tf, {}}, {"rcpp", nc_trace, nc, {}}, {"rcpp-coop", co_trace, co, {}}};
}

Scenario one_obstacle() {
  Scenario s;
  s.vehicles.push_back(MainVehicle{});
  return s;
}

TEST(PaperClaims, PaperLikeRunsReproduceEveryClaim) {
  const std::vector<PaperClaim> claims = paper_claims(one_obstacle(), paper_like_runs());
  ASSERT_EQ(static_cast<int>(claims.size()), kPaperClaimCount);
  for (const PaperClaim& c : claims) EXPECT_TRUE(c.reproduced) << c.what << ": " << c.ours;
  EXPECT_EQ(reproduced_count(claims), kPaperClaimCount);
}

TEST(PaperClaims, CooperationWithoutAnAcceptanceOrTooLateDoesNotCount) {
  std::vector<PaperRun> runs = paper_like_runs();
  runs[2].trace.events.pop_back();  // no acceptance
  EXPECT_FALSE(paper_claims(one_obstacle(), runs).back().reproduced);
  runs = paper_like_runs();
  runs[2].metrics.merge_start_time_s = 1.0;  // the ego moved before the obstacle braked (1.2 s)
  EXPECT_FALSE(paper_claims(one_obstacle(), runs).back().reproduced);
  runs = paper_like_runs();
  runs[1].trace.steps[5].others[0].accel_mps2 = -1.0;  // without cooperation it braked earlier still
  EXPECT_FALSE(paper_claims(one_obstacle(), runs).back().reproduced);
}

TEST(PaperClaims, EachMissIsOneRow) {
  std::vector<PaperRun> runs = paper_like_runs();
  runs[0].metrics.ego_speed_min_mps = 12.0;  // TriPField's ego did not brake below 9 m/s
  runs[2].metrics.ego_speed_max_mps = 25.0;  // the coop ego's speed was not steady
  EXPECT_EQ(reproduced_count(paper_claims(one_obstacle(), runs)), kPaperClaimCount - 2);
}

TEST(PaperClaims, EventHelpersFindTheFirstMatchingEvent) {
  const std::vector<PaperRun> runs = paper_like_runs();
  const Trace& co = runs[2].trace;
  EXPECT_DOUBLE_EQ(*first_event_s(co, EventKind::kMessageDelivered, 1), 0.2);
  EXPECT_DOUBLE_EQ(*first_acceptance_s(co, 1), 0.5);
  EXPECT_FALSE(first_acceptance_s(co, 2));
  EXPECT_NEAR(*obstacle_first_braking_s(co), 1.2, 1e-12);
  EXPECT_FALSE(obstacle_first_braking_s(runs[0].trace));
  const auto [when, peak] = sideslip_peak(co);
  EXPECT_NEAR(when, 4.0, 1e-12);
  EXPECT_NEAR(peak, 0.024, 1e-9);
}

}  // namespace
}  // namespace mg
