#include "paper/paper_metrics.h"

#include <cmath>

#include <gtest/gtest.h>

#include "sim/simulator.h"
#include "tests/sim/test_planners.h"

namespace mg {
namespace {

TEST(PaperMetrics, ASingleSCountsNoReversalAndEachWeaveCounts) {
  EXPECT_EQ(count_sign_changes({0.0, 0.3, 0.8, 0.3, 0.05, -0.05, 0.0}, 0.1), 0);
  EXPECT_EQ(count_sign_changes({0.0, 0.5, -0.5, 0.5, 0.0}, 0.1), 2);
  EXPECT_EQ(count_sign_changes({0.5, 0.05, -0.05, 0.5}, 0.1), 0) << "the dead band hides jitter";
}

TEST(PaperMetrics, BoxesOverlapOnlyWhenTouching) {
  EXPECT_TRUE(boxes_overlap(0, 0, 0, 4.8, 1.9, 4.0, 0.0, 0.0, 4.8, 1.9));
  EXPECT_FALSE(boxes_overlap(0, 0, 0, 4.8, 1.9, 5.0, 0.0, 0.0, 4.8, 1.9));
  EXPECT_FALSE(boxes_overlap(0, 0, 0, 4.8, 1.9, 0.0, 2.0, 0.0, 4.8, 1.9));
  // Rotated by 90 degrees a 4.8 m car reaches 2.4 m sideways.
  EXPECT_TRUE(boxes_overlap(0, 0, M_PI / 2, 4.8, 1.9, 0.0, 3.2, 0.0, 4.8, 1.9));
}

TEST(PaperMetrics, ReductionIsRelativeToTheBaseline) {
  EXPECT_DOUBLE_EQ(*reduction_pct(10.0, 2.5), 75.0);
  EXPECT_DOUBLE_EQ(*reduction_pct(10.0, 12.0), -20.0);
  EXPECT_FALSE(reduction_pct(std::nullopt, 2.0));
  EXPECT_FALSE(reduction_pct(10.0, std::nullopt));
}

TEST(PaperMetrics, SigmoidMergeMeasuresTimeLengthAndNoReversal) {
  Scenario s = test::empty_scenario();
  s.vehicles.push_back(test::vehicle(1, 100.0, 20.0, BehaviourType::kIdm));
  test::SigmoidPlanner planner(60.0, 0.2, 3.5, -3.5, 20.0);
  const Trace t = simulate(s, planner);
  const PaperMetrics m = compute_paper_metrics(s, t);
  ASSERT_TRUE(m.merged);
  EXPECT_FALSE(m.collision);
  ASSERT_TRUE(m.merge_time_s && m.path_length_m && m.merge_x_m);
  // At 20 m/s the path length over the manoeuvre is speed x time, plus a little for the S.
  EXPECT_NEAR(*m.path_length_m, 20.0 * *m.merge_time_s, 0.02 * *m.path_length_m);
  EXPECT_GT(*m.path_length_m, 20.0 * *m.merge_time_s);
  EXPECT_NEAR(*m.merge_x_m, 60.0, 3.0);
  EXPECT_EQ(m.lateral_reversals, 0);
  EXPECT_LT(m.sideslip_min_rad, 0.0 + 1e-12);
  EXPECT_GT(m.sideslip_max_rad, 0.0);
  EXPECT_DOUBLE_EQ(m.obstacle_speed_min_mps, 20.0);
}

TEST(PaperMetrics, CollisionIsDetected) {
  Scenario s = test::empty_scenario();
  s.vehicles.push_back(test::vehicle(1, 30.0, 10.0, BehaviourType::kConstantSpeed));  // slow, ahead
  s.vehicles[0].behaviour.desired_speed_mps = 10.0;
  test::SigmoidPlanner planner(20.0, 0.3, 3.5, -3.5, 20.0);  // cuts in and drives into it
  const Trace t = simulate(s, planner);
  EXPECT_TRUE(compute_paper_metrics(s, t).collision);
}

TEST(PaperMetrics, JsonHasTheIssueKeysAndNullsForAbsentValues) {
  PaperMetrics m;
  const nlohmann::json j = paper_metrics_to_json(m);
  for (const char* key : {"merged", "collision", "merge_time_s", "path_length_m", "lateral_reversals", "sideslip_min_rad",
                          "sideslip_max_rad", "ego_speed_min_mps", "ego_speed_max_mps", "obstacle_speed_min_mps"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["merge_time_s"].is_null());
}

}  // namespace
}  // namespace mg
