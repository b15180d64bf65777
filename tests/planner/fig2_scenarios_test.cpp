// The four situations of RCPP Fig. 2 (corpus/scenarios/fig2_*.json): the decision at the initial
// state, computed by hand. Common data: T = 0.5 s, rho_m = 4 s, cars 4.8 m long (half-lengths sum
// 4.8 m), limits a_acc = 2, b_min = 4, b_max = 8 m/s2, side lane end 350 m, speed limit 33.34 m/s.
// D_lon(v_r, v_f) = 4.8 + [0.5 v_r + 0.25 + (v_r + 1)^2/8 - v_f^2/16]_+ (RCPP eq. 1).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/scenario.h"
#include "planner/planner.h"

#include "rcpp_decision_of.h"

namespace mg {
namespace {

Scenario fig2_scenario(const std::string& name) {
  return load_scenario(std::string(MG_SOURCE_DIR) + "/corpus/scenarios/" + name + ".json");
}

PlanOutput plan_initial(const Scenario& s, const std::string& planner) {
  auto p = make_planner(planner);
  return p->plan(initial_snapshot(s));
}

void expect_choice_within_bounds(const RcppDecision& d) {
  EXPECT_GE(d.ve_star_mps, d.ve_min_mps);
  EXPECT_LE(d.ve_star_mps, d.ve_max_mps);
  EXPECT_GE(d.pc_m, d.pc_min_m);
  EXPECT_LE(d.pc_m, d.pc_max_m);
  EXPECT_GT(d.kappa_per_m, 0.0);
}

TEST(Fig2, Situation1EgoAheadMergesAheadOfTheFollower) {
  // Ego X = 100, v_e = 22; vehicle 1 X_o = 30, v_o = 20 (the follower of the gap ahead of it).
  // Ineq. (1.1): follower at rho/2 = 2 s: 30 + 40 + 2*16/8 = 74 m at 24 m/s; D_lon(24, u) = 95.175 - u^2/16.
  // Literal form (ego at v from T_dec): 100 + 2v - 95.175 + v^2/16 >= 74 <=> v^2 + 32v - 1106.8 >= 0
  // -> v >= (-32 + sqrt(32^2 + 4*1106.8))/2 = 20.916 m/s.
  // Bounded-rate form (brake at 4 to v < 22, then hold): X(2 s) = 100 + 2v + (22-v)^2/8, u = v:
  // 3v^2 - 56v - 138.8 >= 0 -> v >= 20.882. Both must hold: v_e* >= 20.916. No leader: upper = limit.
  // P_c lower bound = X(2 s) at 20.916 = 100 + 41.832 + (1.084)^2/8 = 141.979 m; upper: accelerating at
  // 2 to the limit gives 100 + 44 + 4 = 148 m.
  const PlanOutput out = plan_initial(fig2_scenario("fig2_s1_ahead_noncoop"), "rcpp");
  const RcppDecision d = decision_of(out);
  EXPECT_EQ(d.mode, DecisionMode::kDef1Merge);
  ASSERT_TRUE(d.gap);
  EXPECT_EQ(d.gap->follower_id, 1);
  EXPECT_EQ(d.gap->leader_id, -1);
  EXPECT_NEAR(d.ve_min_mps, (-32 + std::sqrt(32.0 * 32 + 4 * 1106.8)) / 2, 1e-4);
  EXPECT_DOUBLE_EQ(d.ve_max_mps, 33.34);
  const double lo = d.ve_min_mps;
  EXPECT_NEAR(d.pc_min_m, 100 + 2 * lo + (22 - lo) * (22 - lo) / 8, 1e-6);
  EXPECT_NEAR(d.pc_max_m, 148.0, 1e-6);
  expect_choice_within_bounds(d);
  EXPECT_FALSE(out.proper_response);
  EXPECT_TRUE(out.outbox.empty());
}

TEST(Fig2, Situation2EgoBehindMergesBehindTheLeader) {
  // Ego X = 30, v_e = 20; vehicle 1 X_o = 60, v_o = 22 (the leader of the gap behind it).
  // Ineq. (1.2) over [0, rho], checked at rho/2 = 2 s and rho = 4 s; D_lon(v, 22) = 0.5v + (v+1)^2/8 - 25.2.
  // Bounded-rate form, v <= 20 (brake at 4, then hold): X(t) = 30 + t v + (20 - v)^2/8.
  //   at 4 s: leader 148: v^2 - v - 372.3 <= 0 -> v <= 19.802; literal (30 + 4v): v <= 19.802 too;
  //   at 2 s: leader 104: 99.2 - 2.5v - [(v+1)^2 + (20-v)^2]/8 >= 0 <=> v^2 - 9v - 196.3 <= 0
  //   -> v <= (9 + sqrt(81 + 785.2))/2 = 19.216 (literal at 2 s: v <= 19.226). Binding: 19.216.
  // No follower: lower end 0. P_c lower bound: X(2 s) at v_e* = 0 is 30 + 40 - 8 = 62 m.
  const PlanOutput out = plan_initial(fig2_scenario("fig2_s2_behind_noncoop"), "rcpp");
  const RcppDecision d = decision_of(out);
  EXPECT_EQ(d.mode, DecisionMode::kDef1Merge);
  ASSERT_TRUE(d.gap);
  EXPECT_EQ(d.gap->follower_id, -1);
  EXPECT_EQ(d.gap->leader_id, 1);
  EXPECT_DOUBLE_EQ(d.ve_min_mps, 0.0);
  EXPECT_NEAR(d.ve_max_mps, (9 + std::sqrt(81 + 4 * 196.3)) / 2, 1e-4);
  EXPECT_NEAR(d.pc_min_m, 62.0, 1e-6);
  expect_choice_within_bounds(d);
}

TEST(Fig2, Situation3EgoAheadWithoutV2vDropsBackAndWithV2vAsksToSlowDown) {
  // Ego X = 50, v_e = 20; vehicle 1 X_o = 25, v_o = 20; rho_c = 1.5 s.
  // Def. 1, gap ahead of vehicle 1: at 2 s the follower is at 25 + 40 + 4 = 69; the ego can at most
  // reach 50 + 44 = 94 at 24 m/s, D_lon(24, 24) = 59.175 -> 94 - 59.175 = 34.8 < 69: infeasible.
  // Gap behind vehicle 1: braking puts the ego at >= 82 m at 2 s while the leader's bound is
  // 65 - D_lon(12, 20) < 82: the P_c bounds cross. So at rho_m no Def. 1 gap exists; the paper
  // halts (Def. 1.3). "rcpp" then tries the longer merges of its extension (docs/planner.md): it
  // drops back behind vehicle 1 in a merge longer than rho_m.
  const Scenario s = fig2_scenario("fig2_s3_ahead_coop");
  const RcppDecision halt_or_longer = decision_of(plan_initial(s, "rcpp"));
  EXPECT_EQ(halt_or_longer.mode, DecisionMode::kDef1Merge);
  ASSERT_TRUE(halt_or_longer.gap);
  EXPECT_EQ(halt_or_longer.gap->follower_id, -1);
  EXPECT_EQ(halt_or_longer.gap->leader_id, 1);
  EXPECT_GT(halt_or_longer.merge_duration_s, s.params.planner.merge_duration_s);
  // Def. 2.1: P_c = 50 + 20 (1.5 + 2) = 120 m. The binding condition is the start of the lateral
  // motion (docs/planner.md): 80 - D*(v) >= 25 + 0.75 (20 + v), D*(v) = 0.5v + (v+1)^2/8 - 19.95,
  // plus the planner's slack: the 1.5 m planning buffer and the request's latency 0.1 s at v_o
  // instead of v (0.1 (20 - v)) <=> v^2 + 11.2v - 450.6 <= 0 -> v_o* = 16.353 m/s >= 20 - 4*1.5
  // = 14 (brake limit). (The paper's ineq. (3) alone: v^2 + 12v - 478.6 <= 0, 16.683 m/s.)
  const PlanOutput out = plan_initial(s, "rcpp-coop");
  const RcppDecision d = decision_of(out);
  EXPECT_EQ(d.mode, DecisionMode::kDef2Request);
  EXPECT_EQ(d.coop_partner_id, 1);
  EXPECT_NEAR(d.vo_star_mps, (-11.2 + std::sqrt(11.2 * 11.2 + 4 * 450.6)) / 2, 1e-4);
  EXPECT_DOUBLE_EQ(d.pc_m, 120.0);
  const double v = d.vo_star_mps;
  EXPECT_NEAR(d.d_lon_star_m, 4.8 + 0.5 * v + 0.25 + (v + 1) * (v + 1) / 8 - 25, 1e-9);
  ASSERT_EQ(out.outbox.size(), 1u);
  const V2vMessage& m = out.outbox[0];
  EXPECT_EQ(m.type, MessageType::kRequest);
  EXPECT_EQ(m.to_id, 1);
  EXPECT_EQ(m.coop_case, CoopCase::kEgoAhead);
  EXPECT_DOUBLE_EQ(m.pc_m, 120.0);
  EXPECT_DOUBLE_EQ(m.target_speed_mps, d.vo_star_mps);
  EXPECT_DOUBLE_EQ(m.d_lon_star_m, d.d_lon_star_m);
  EXPECT_DOUBLE_EQ(out.target_speed_mps, 20.0);  // the ego keeps its speed (Def. 2.1)
}

TEST(Fig2, Situation4EgoBehindAsksToSpeedUpWithV2vAndOtherwiseDropsBack) {
  // Ego X = 50, v_e = 20; vehicle 1 X_o = 54, v_o = 20. Def. 1, gap ahead of vehicle 1: the
  // follower is at 54 + 40 + 4 = 98 > 94 (ego's best) at 2 s: infeasible before any D_lon. Gap
  // behind: within rho_m the ego would have to drop ~45 m back while a comfortable sigmoid at
  // ~20 m/s needs ~30 m on each side of P_c: no sigmoid in rho_m. So no Def. 1 gap at rho_m:
  // with V2V the ego asks vehicle 1 to speed up (Def. 2.2, as in the paper's Fig. 2); without it,
  // the longer-merge extension drops back behind vehicle 1 with rho = 1.5 rho_m. (The Def. 2.2
  // request itself is computed in definition2_test.cpp, HandComputedEgoBehindSpeed.)
  const Scenario s = fig2_scenario("fig2_s4_behind_coop");
  const RcppDecision coop = decision_of(plan_initial(s, "rcpp-coop"));
  EXPECT_EQ(coop.mode, DecisionMode::kDef2Request);
  EXPECT_EQ(coop.coop_partner_id, 1);
  EXPECT_GT(coop.vo_star_mps, 20.0);  // vehicle 1 is asked to speed up

  const RcppDecision d = decision_of(plan_initial(s, "rcpp"));
  EXPECT_EQ(d.mode, DecisionMode::kDef1Merge);
  ASSERT_TRUE(d.gap.has_value());
  EXPECT_EQ(d.gap->follower_id, -1);
  EXPECT_EQ(d.gap->leader_id, 1);
  EXPECT_DOUBLE_EQ(d.merge_duration_s, 1.5 * s.params.planner.merge_duration_s);
  EXPECT_LT(d.ve_star_mps, 20.0);  // drops back behind vehicle 1
}

}  // namespace
}  // namespace mg
