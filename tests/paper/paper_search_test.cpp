#include "paper/paper_search.h"

#include <gtest/gtest.h>

#include "core/scenario.h"

namespace mg {
namespace {

Scenario base_with_obstacle() {
  Scenario s;
  MainVehicle o;
  o.behaviour.type = BehaviourType::kCooperative;
  o.v2v.capable = true;
  s.ego.v2v.capable = true;
  s.vehicles.push_back(o);
  return s;
}

TEST(PaperSearch, ACandidateSetsOnlyTheScenario) {
  PaperSearchCandidate c;
  c.gap_m = -7.5;
  c.ego_speed_mps = 21.0;
  c.obstacle_speed_mps = 19.0;
  c.obstacle_accel_max_mps2 = 3.0;
  c.obstacle_brake_min_mps2 = 2.0;
  c.obstacle_headway_s = 1.0;
  c.latency_s = 0.3;
  c.ramp_end_x_m = 270.0;
  const Scenario base = base_with_obstacle();
  const Scenario s = apply_search_candidate(base, c);
  EXPECT_DOUBLE_EQ(s.ego.x_m, 0.0);
  EXPECT_DOUBLE_EQ(s.ego.speed_mps, 21.0);
  EXPECT_DOUBLE_EQ(s.ego.v2v.latency_s, 0.3);
  EXPECT_DOUBLE_EQ(s.road.side_lane_end_x_m, 270.0);
  const MainVehicle& o = s.vehicles[0];
  EXPECT_DOUBLE_EQ(o.x_m, -7.5);
  EXPECT_DOUBLE_EQ(o.speed_mps, 19.0);
  EXPECT_DOUBLE_EQ(o.behaviour.desired_speed_mps, 19.0);
  EXPECT_DOUBLE_EQ(o.behaviour.time_headway_s, 1.0);
  EXPECT_DOUBLE_EQ(o.limits.accel_max_mps2, 3.0);
  EXPECT_DOUBLE_EQ(o.limits.brake_min_mps2, 2.0);
  EXPECT_DOUBLE_EQ(o.v2v.latency_s, 0.3);
  EXPECT_EQ(s.params, base.params) << "the planners' parameters are never searched";
}

TEST(PaperSearch, RankingPrefersConsistentThenRowsThenHeadline) {
  PaperSearchResult a, b;
  a.consistent = true, a.reproduced = 10, a.headline_miss = 3.0;
  b.consistent = false, b.reproduced = 15, b.headline_miss = 0.0;
  EXPECT_TRUE(search_result_better(a, b)) << "a run that collides or does not merge ranks last";
  b.consistent = true;
  EXPECT_TRUE(search_result_better(b, a));
  b.reproduced = 10;
  EXPECT_TRUE(search_result_better(b, a)) << "equal rows: the smaller headline miss";
  EXPECT_FALSE(search_result_better(a, a));
}

TEST(PaperSearch, EvaluationIsDeterministicAndListsItsFailedRows) {
  const Scenario base = base_with_obstacle();
  PaperSearchCandidate c;
  const PaperSearchResult r1 = evaluate_search_candidate(base, c, 1), r2 = evaluate_search_candidate(base, c, 1);
  EXPECT_EQ(r1.reproduced, r2.reproduced);
  EXPECT_EQ(r1.failed_rows, r2.failed_rows);
  EXPECT_DOUBLE_EQ(r1.headline_miss, r2.headline_miss);
  EXPECT_EQ(static_cast<int>(r1.failed_rows.size()) + r1.reproduced, kPaperClaimCount);
}

// corpus/scenarios/paper_merge.json is the chosen 13-row candidate of the search
// (docs/paper_reproduction.md, "The chosen scenario"; docs/paper_search.md) written by hand: the
// same scenario, only its name and description are the file's own.
TEST(PaperSearch, TheCommittedPaperScenarioIsTheChosenThirteenRowCandidate) {
  const Scenario file = load_scenario(MG_SOURCE_DIR "/corpus/scenarios/paper_merge.json");
  PaperSearchCandidate best;
  best.gap_m = 2.5;
  best.ego_speed_mps = 24.0;
  best.obstacle_speed_mps = 17.0;
  best.obstacle_accel_max_mps2 = 1.0;
  best.obstacle_brake_min_mps2 = 4.0;
  best.obstacle_headway_s = 1.0;
  best.obstacle_comfort_brake_mps2 = 2.0;
  best.latency_s = 0.05;
  best.ramp_end_x_m = 240.0;
  best.lead_gap_m = 60.0;
  best.lead_speed_mps = 24.0;
  Scenario built = apply_search_candidate(file, best);
  built.name = file.name;
  built.description = file.description;
  EXPECT_EQ(built, file);
  EXPECT_EQ(file.params.planner, PlannerParams{}) << "the planners run with their default parameters";
  EXPECT_EQ(file.params.rss, RssParams{});
  const PaperSearchResult r = evaluate_search_candidate(file, best, 1);
  EXPECT_GE(r.reproduced, 13);
  EXPECT_TRUE(r.consistent);
}

}  // namespace
}  // namespace mg
