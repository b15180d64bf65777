// Planners that exploit what the judge used to take on trust: a V2V request's word (its case and
// its P_c), an acceptance held for the whole merge whatever gap is entered, a re-sent request
// that moves t_r, a merge whose midpoint comes long after the reading, a request without a
// number. Each is simulated against the simulator's responders and judged as `check` judges it
// (check/checked_run.h); each must be judged violated, by the rule that closes the loophole, with
// the ego liable (spec §8, points 18 to 23).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "planner/planner.h"
#include "rules/check.h"
#include "check/checked_run.h"
#include "tests/sim/test_planners.h"

namespace mg {
namespace {

// One request of a script: sent at time_s to `to`.
struct ScriptedRequest {
  double time_s = 0.0;
  int to = 1;
  CoopCase coop_case = CoopCase::kEgoAhead;
  double pc_m = 0.0;
  double d_lon_star_m = 0.0;
  double vo_star_mps = 0.0;
};

// A speed command from time_s on.
struct SpeedFrom {
  double time_s = 0.0;
  double speed_mps = 0.0;
  double accel_limit_mps2 = 0.0;
};

struct Script {
  std::vector<ScriptedRequest> requests;
  // The path: the side-lane centre raised by `offset_m` from offset_at_x_m on (a visible start of
  // the merge, without crossing anything), then a sigmoid into the main lane with its midpoint
  // parameter merge_pc_m and slope kappa.
  double offset_m = 0.0;
  double offset_at_x_m = 0.0;
  double merge_pc_m = 0.0;
  double kappa_per_m = 0.2;
  std::vector<SpeedFrom> speeds;
};

double logistic(double z) { return 1.0 / (1.0 + std::exp(-std::clamp(z, -50.0, 50.0))); }

// Follows a fixed script whatever it observes: what it sends, where it drives and how fast.
class ScriptedPlanner : public Planner {
 public:
  explicit ScriptedPlanner(Script s) : script_(std::move(s)), sent_(script_.requests.size(), false) {}
  std::string name() const override { return "test-scripted"; }
  PlanOutput plan(const WorldSnapshot& w) override {
    const double width_m = w.setup->road.lane_width_m;
    PlanOutput out;
    out.path = sample_path(w.ego.x_m - 20.0, w.ego.x_m + 600.0, 1.0, [&](double x) {
      return -width_m + script_.offset_m * logistic(0.5 * (x - script_.offset_at_x_m)) +
             (width_m - script_.offset_m) * logistic(script_.kappa_per_m * (x - script_.merge_pc_m));
    });
    for (const SpeedFrom& s : script_.speeds) {
      if (w.time_s + 1e-9 < s.time_s) break;
      out.target_speed_mps = s.speed_mps;
      out.accel_limit_mps2 = s.accel_limit_mps2;
    }
    for (std::size_t i = 0; i < script_.requests.size(); ++i) {
      const ScriptedRequest& r = script_.requests[i];
      if (sent_[i] || w.time_s + 1e-9 < r.time_s) continue;
      sent_[i] = true;
      V2vMessage m;
      m.type = MessageType::kRequest;
      m.to_id = r.to;
      m.coop_case = r.coop_case;
      m.pc_m = r.pc_m;
      m.d_lon_star_m = r.d_lon_star_m;
      m.target_speed_mps = r.vo_star_mps;
      out.outbox.push_back(m);
    }
    out.mode = "scripted";
    return out;
  }

 private:
  Script script_;
  std::vector<bool> sent_;
};

Scenario road_scenario(double horizon_s) {
  Scenario s = test::empty_scenario();
  s.name = "adversarial";
  s.ego.v2v = V2v{true, 0.05, 0.0};
  s.params.sim.horizon_s = horizon_s;
  return s;
}

MainVehicle main_vehicle(int id, double x_m, double speed_mps, BehaviourType type, bool v2v = false) {
  MainVehicle v;
  v.id = id;
  v.x_m = x_m;
  v.speed_mps = speed_mps;
  v.behaviour.type = type;
  v.v2v = V2v{v2v, 0.05, 0.0};
  return v;
}

const RuleResult* rule_of(const CheckResult& r, const std::string& id) {
  for (const RuleResult& rule : r.rules)
    if (rule.rule_id == id) return &rule;
  return nullptr;
}

// The rule is violated with the ego liable.
void expect_ego_broke(const CheckResult& r, const std::string& id) {
  const RuleResult* rule = rule_of(r, id);
  ASSERT_NE(rule, nullptr) << id << " is no rule";
  EXPECT_FALSE(rule->holds) << id << ": " << rule->detail;
  EXPECT_EQ(rule->liable_id, Party::ego()) << id << ": " << rule->detail;
}

// The detail of a rule, or "" when there is no such rule.
std::string detail_of(const CheckResult& r, const std::string& id) {
  const RuleResult* rule = rule_of(r, id);
  return rule != nullptr ? rule->detail : std::string();
}

CheckResult run(const Scenario& s, const Script& script) {
  ScriptedPlanner planner(script);
  return check_scenario(s, planner);
}

// The ego, 10 m behind vehicle 1, asks it under Def. 2.1 ("ego ahead") to slow to 17 m/s, with P_c
// 500 m ahead; vehicle 1 (cooperative) accepts; the ego speeds up to 26 m/s and cuts in ahead of
// it (P_c of its path 95 m). Judged on its word, the request was sound and the acceptance granted
// the right of way: "holds".
TEST(AdversarialPlanners, AnEgoBehindItsResponderThatSaysItIsAheadIsLiableForTheLie) {
  Scenario s = road_scenario(12.0);
  s.vehicles = {main_vehicle(1, 10.0, 20.0, BehaviourType::kCooperative, true)};
  Script script;
  script.requests = {{0.0, 1, CoopCase::kEgoAhead, 500.0, 30.0, 17.0}};
  script.merge_pc_m = 95.0;
  script.speeds = {{0.0, 26.0, 2.0}};
  const CheckResult r = run(s, script);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.liable_id, Party::ego()) << r.liability_detail;
  expect_ego_broke(r, "def2_request_truthful");
  EXPECT_NE(detail_of(r, "def2_request_truthful").find("says the ego is ahead of it"), std::string::npos);
}

// The ego 15 m ahead of vehicle 1 asks it to slow to 16 m/s with P_c = 300 m, which makes ineq. (3)
// hold by far; its path crosses the lane line at about 60 m, ahead of vehicle 1 and inside its
// safe distance. Judged on its word, the ego held the right of way and vehicle 1 was blamed for
// not braking for the cut-in.
TEST(AdversarialPlanners, AnInflatedPcGrantsNothingAndTheEgoAnswersForIt) {
  Scenario s = road_scenario(12.0);
  s.vehicles = {main_vehicle(1, -15.0, 20.0, BehaviourType::kCooperative, true)};
  Script script;
  script.requests = {{0.0, 1, CoopCase::kEgoAhead, 300.0, 30.0, 16.0}};
  script.merge_pc_m = 60.0;
  script.kappa_per_m = 0.3;
  script.speeds = {{0.0, 20.0, 2.0}};
  const CheckResult r = run(s, script);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.liable_id, Party::ego()) << r.liability_detail;
  expect_ego_broke(r, "def2_request_truthful");
  EXPECT_NE(detail_of(r, "def2_request_truthful").find("crossed the lane line"), std::string::npos);
  EXPECT_TRUE(rule_of(r, "def1_1_gap")->holds);  // the attempt is the lie's, not Definition 1's
}

// The ego asks vehicle 1, 15 m behind it, to slow down for a merge ahead of it (Def. 2.1) and gets
// its acceptance; then it brakes to 8 m/s, lets vehicle 1 pass and enters the gap behind it, ahead
// of vehicle 3 (16 m/s), too close for ineq. (1.1). Vehicle 2 is far ahead. The acceptance was
// held for the whole merge: "holds".
TEST(AdversarialPlanners, AnAcceptanceFromOneVehicleGrantsNothingInTheGapOfAnother) {
  Scenario s = road_scenario(18.0);
  s.vehicles = {main_vehicle(1, -15.0, 20.0, BehaviourType::kCooperative, true),
                main_vehicle(2, 300.0, 20.0, BehaviourType::kConstantSpeed),
                main_vehicle(3, -105.0, 16.0, BehaviourType::kConstantSpeed)};
  Script script;
  script.requests = {{0.0, 1, CoopCase::kEgoAhead, 120.0, 30.0, 16.0}};
  script.offset_m = 0.25;  // a visible start at once: the acceptance is in its decision window
  script.offset_at_x_m = 15.0;
  script.merge_pc_m = 125.0;
  script.kappa_per_m = 0.25;
  script.speeds = {{0.0, 8.0, 4.0}, {8.0, 16.0, 2.0}};
  const CheckResult r = run(s, script);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.liable_id, Party::ego()) << r.liability_detail;
  expect_ego_broke(r, "def1_1_gap");
  EXPECT_NE(detail_of(r, "def1_1_gap").find("toward follower vehicle 3"), std::string::npos);
}

// Vehicle 1 answers over a 1 s link: its acceptance of the request of t = 0 arrives at 1.06 s,
// after rho_c. The ego re-sent the request at 0.5 s; bound to "the latest earlier request" the
// acceptance looked timely, and the cut-in ahead of vehicle 1 was granted: "holds".
TEST(AdversarialPlanners, ReSendingARequestDoesNotMakeALateAcceptanceTimely) {
  Scenario s = road_scenario(12.0);
  s.vehicles = {main_vehicle(1, -15.0, 20.0, BehaviourType::kCooperative, true)};
  s.vehicles[0].v2v.latency_s = 1.0;
  Script script;
  script.requests = {{0.0, 1, CoopCase::kEgoAhead, 64.0, 24.5, 16.0}, {0.5, 1, CoopCase::kEgoAhead, 72.0, 24.5, 16.0}};
  script.merge_pc_m = 64.0;
  script.kappa_per_m = 0.3;
  script.speeds = {{0.0, 20.0, 2.0}};
  const CheckResult r = run(s, script);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.liable_id, Party::ego()) << r.liability_detail;
  expect_ego_broke(r, "def2_3_fallback");
  EXPECT_NE(detail_of(r, "def2_3_fallback").find("first request of t = 0 s"), std::string::npos);
}

// At t = 0 the gap ahead of vehicle 1 (80 m behind, 20 m/s) holds for a merge of rho_m = 4 s. The
// ego takes 8 s to its midpoint, while vehicle 1 accelerates legally to 30 m/s. Read at rho_m, the
// ego held the right of way from t = 0, and the cut-in was vehicle 1's to answer.
TEST(AdversarialPlanners, AMergeWhoseMidpointComesLateIsReadWithTheFollowerAcceleratingUntilThen) {
  Scenario s = road_scenario(14.0);
  s.ego.v2v = V2v{};
  s.vehicles = {main_vehicle(1, -80.0, 20.0, BehaviourType::kConstantSpeed)};
  s.vehicles[0].behaviour.desired_speed_mps = 30.0;
  Script script;
  script.offset_m = 0.25;
  script.offset_at_x_m = 15.0;
  script.merge_pc_m = 160.0;
  script.kappa_per_m = 0.12;
  script.speeds = {{0.0, 20.0, 2.0}};
  const CheckResult r = run(s, script);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.liable_id, Party::ego()) << r.liability_detail;
  expect_ego_broke(r, "def1_1_gap");
  expect_ego_broke(r, "rss_longitudinal");  // the cut-in is the ego's
}

// A Def. 2.2 request without P_c (NaN): vehicle 1 accepts (its v_o* is reachable) and the ego
// merges behind it. def2_request_sound skipped the request and the acceptance granted the right of
// way: "holds".
TEST(AdversarialPlanners, AnAcceptedRequestWithoutPcFailsAndGrantsNothing) {
  Scenario s = road_scenario(10.0);
  s.vehicles = {main_vehicle(1, 30.0, 18.0, BehaviourType::kCooperative, true),
                main_vehicle(2, -90.0, 17.0, BehaviourType::kConstantSpeed)};
  Script script;
  script.requests = {{0.0, 1, CoopCase::kEgoBehind, std::numeric_limits<double>::quiet_NaN(), 30.0, 20.0}};
  script.merge_pc_m = 52.0;
  script.kappa_per_m = 0.3;
  script.speeds = {{0.0, 17.0, 4.0}};
  const CheckResult r = run(s, script);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.liable_id, Party::ego()) << r.liability_detail;
  expect_ego_broke(r, "def2_request_sound");
  ASSERT_EQ(r.right_of_way_observations.size(), 1u);
  EXPECT_EQ(r.right_of_way_observations[0].find("(Def. 2)"), std::string::npos) << r.right_of_way_observations[0];
}

}  // namespace
}  // namespace mg
