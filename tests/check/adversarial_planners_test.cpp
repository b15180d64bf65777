// Adversarial planners: each does a wrong thing the judge must see, and is judged violated with the
// right rule and the right party (the ego). Liveness: a creeper at 0.06 m/s, an early stopper 39 m
// before the side lane's end, a weaver that approaches the main lane and turns back again and
// again, a slow drifter that enters the main lane at 0.09 m/s lateral, a drifter that never
// starts a merge and ends its run still on its way, a planner that
// pretends to merge by drifting out and back, and a straddler that puts a corner of its body over
// the lane line and stays there. A RapidCheck property: a planner that never merges
// fails `progress` on every generated scenario in which a gap stayed feasible longer than the
// grace (feasibility sampled independently of the monitor's own run bookkeeping).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "fuzz/scenario_gen.h"
#include "planner/planner.h"
#include "rules/check.h"
#include "rules/liability.h"
#include "rules/merge_attempts.h"
#include "rules/merge_phases.h"
#include "rules/monitor.h"
#include "rules/feasible_gaps.h"
#include "rules/progress_monitor.h"
#include "rules/situation.h"
#include "check/checked_run.h"
#include "tests/sim/test_planners.h"

namespace mg {
namespace {

// The front stops `short_of_end_m` before the side lane's end, braking at 1.5 m/s^2.
double stopping_speed_mps(const WorldSnapshot& w, double short_of_end_m) {
  const double to_stop_m = w.setup->road.side_lane_end_x_m - short_of_end_m - (w.ego.x_m + 0.5 * w.setup->ego.size.length_m);
  return std::min(w.ego.vx_mps, std::sqrt(2.0 * 1.5 * std::max(0.0, to_stop_m)));
}

// Keeps the side lane's centre; the speed from `speed_of`.
template <class SpeedOf>
class SideLaneKeeper : public Planner {
 public:
  SideLaneKeeper(std::string name, SpeedOf speed_of) : name_(std::move(name)), speed_of_(speed_of) {}
  std::string name() const override { return name_; }
  PlanOutput plan(const WorldSnapshot& w) override {
    PlanOutput out;
    out.path = test::line_at(w.ego.x_m, w.setup->road.side_lane_y_m());
    out.target_speed_mps = speed_of_(w);
    out.accel_limit_mps2 = 3.0;
    out.mode = "keep_lane";
    return out;
  }

 private:
  std::string name_;
  SpeedOf speed_of_;
};

template <class SpeedOf>
SideLaneKeeper<SpeedOf> keeper(std::string name, SpeedOf f) { return SideLaneKeeper<SpeedOf>(std::move(name), f); }

// Follows y(x) from a function of X; the speed as the early stopper's, `short_of_end_m` before
// the end.
template <class YOf>
class PathFollower : public Planner {
 public:
  PathFollower(std::string name, YOf y_of, double speed_mps, double short_of_end_m)
      : name_(std::move(name)), y_of_(y_of), speed_(speed_mps), short_(short_of_end_m) {}
  std::string name() const override { return name_; }
  PlanOutput plan(const WorldSnapshot& w) override {
    PlanOutput out;
    out.path = sample_path(w.ego.x_m - 10.0, w.ego.x_m + 200.0, 0.5, y_of_);
    out.target_speed_mps = std::min(speed_, stopping_speed_mps(w, short_));
    out.accel_limit_mps2 = 3.0;
    out.mode = "adversary";
    return out;
  }

 private:
  std::string name_;
  YOf y_of_;
  double speed_, short_;
};

template <class YOf>
PathFollower<YOf> follower(std::string name, YOf f, double speed_mps, double short_of_end_m) {
  return PathFollower<YOf>(std::move(name), f, speed_mps, short_of_end_m);
}

const RuleResult& rule(const CheckResult& r, const std::string& id) {
  for (const RuleResult& x : r.rules)
    if (x.rule_id == id) return x;
  throw std::runtime_error("no rule " + id);
}

// The curated scenario every liveness adversary is run on: the default ego (side lane centre,
// 20 m/s, side lane ending at 300 m) and two vehicles passing in the main lane.
Scenario passing_traffic() {
  Scenario s;
  s.name = "passing_traffic";
  s.vehicles = {test::vehicle(1, 40.0, 22.0, BehaviourType::kConstantSpeed),
                test::vehicle(2, -60.0, 22.0, BehaviourType::kConstantSpeed)};
  return s;
}

double measure(const RuleResult& r, const std::string& name) {
  for (const auto& [n, v] : r.measures)
    if (n == name) return v;
  return std::nan("");
}

TEST(AdversarialPlanners, ACreeperAt6CmPerSecondLetsTheRightOfWayPass) {
  auto p = keeper("creeper", [](const WorldSnapshot&) { return 0.06; });
  const CheckResult r = check_scenario(passing_traffic(), p);
  const RuleResult& progress = rule(r, "progress");
  ASSERT_FALSE(progress.holds) << progress.detail;
  EXPECT_EQ(progress.liable_id, Party::ego());
  EXPECT_GE(measure(progress, "feasible_gaps_let_pass"), 1.0) << progress.detail;
  EXPECT_GT(measure(progress, "offered_unused_s"), 3.0) << progress.detail;
  EXPECT_NE(progress.detail.find("let the right of way pass"), std::string::npos) << progress.detail;
}

TEST(AdversarialPlanners, AnEarlyStopper39MBeforeTheEndLetsTheRightOfWayPass) {
  auto p = keeper("early-stopper", [](const WorldSnapshot& w) { return stopping_speed_mps(w, 39.0); });
  const CheckResult r = check_scenario(passing_traffic(), p);
  const RuleResult& progress = rule(r, "progress");
  ASSERT_FALSE(progress.holds) << progress.detail;
  EXPECT_EQ(progress.liable_id, Party::ego());
  EXPECT_TRUE(rule(r, "side_lane_end").holds);  // it did stop in time: only liveness is at fault
  // It did stop there.
  const ObservedState& last = r.trace.steps.back().vehicles[0];
  EXPECT_LT(last.vx_mps, 0.05);
  EXPECT_NEAR(r.trace.road.side_lane_end_x_m - (last.x_m + 2.4), 39.0, 1.5);
}

TEST(AdversarialPlanners, AWeaverTowardTheMainLaneOscillates) {
  // Between 0.2 and 0.7 m off the side lane's centre, 60 m a period: never back at the centre,
  // its body never over the lane line (-3.5 + 0.7 + 0.95 < -1.75).
  const double side_y = -3.5;
  auto p = follower("weaver", [side_y](double x) { return side_y + 0.45 + 0.25 * std::sin(2.0 * M_PI * x / 60.0); },
                    20.0, 39.0);
  const CheckResult r = check_scenario(passing_traffic(), p);
  const RuleResult& smooth = rule(r, "smoothness_oscillation");
  ASSERT_FALSE(smooth.holds) << smooth.detail;
  EXPECT_EQ(smooth.liable_id, Party::ego());
  // Its outward swings are attempts that never entered the main lane: waiting, for progress.
  EXPECT_FALSE(rule(r, "progress").holds);
}

TEST(AdversarialPlanners, ADrifterThatNeverStartsAMergeIsCreditedOnlyTheEndOfItsApproach) {
  // At 5 m/s, y rising 2 mm per metre (1 cm/s lateral) from the side lane's centre: it moves
  // toward the main lane for the whole run and never starts a merge; the trace ends with it still
  // on its way. Only the last rho_b of that approach pauses the clock (the start it may lead into
  // would lie beyond the trace); the gaps it let pass before fail it.
  Scenario s = passing_traffic();
  s.ego.speed_mps = 5.0;
  const double side_y = -3.5;
  auto p = follower("drifter", [side_y](double x) { return side_y + 0.002 * std::max(0.0, x); }, 5.0, 10.0);
  const CheckResult r = check_scenario(s, p);
  const ObservedState& last = r.trace.steps.back().vehicles[0];
  ASSERT_GT(last.vy_mps, 0.0);                   // still approaching when the trace ends
  ASSERT_LT(last.y_m, -0.5 * r.trace.road.lane_width_m);  // never in the main lane
  const RuleResult& progress = rule(r, "progress");
  ASSERT_FALSE(progress.holds) << progress.detail;
  EXPECT_EQ(progress.liable_id, Party::ego());
  EXPECT_LT(*progress.first_violation_time_s, r.trace.steps.back().time_s - r.rule_params.merge_duration_s);
}

TEST(AdversarialPlanners, ASlowDrifterIsMergingAndJudgedByDefinition1) {
  // At 5 m/s, y rising 0.018 m per metre: 0.09 m/s lateral, below the 0.1 m/s that makes a start
  // of lateral motion alone. A platoon at 5 m/s, 12 m apart, drives alongside: when the drifter's
  // body crosses the lane line (t ~ 9 s) no gap of it admits a Definition 1 merge.
  Scenario s;
  s.name = "slow_drift";
  s.ego.speed_mps = 5.0;
  s.road.side_lane_end_x_m = 400.0;
  for (int i = 0; i < 8; ++i) s.vehicles.push_back(test::vehicle(i + 1, 54.0 - 12.0 * i, 5.0, BehaviourType::kConstantSpeed));
  auto p = follower("slow-drifter", [](double x) { return std::min(0.0, -3.5 + 0.018 * std::max(0.0, x)); }, 5.0, 0.0);
  const CheckResult r = check_scenario(s, p);
  const MergePhases phases = observe_merge_phases(r.trace, r.rule_params);
  ASSERT_GE(phases.count(MergePhaseKind::kStart), 1);
  const RuleResult& follower_gap = rule(r, "def1_1_gap");
  const RuleResult& leader_gap = rule(r, "def1_2_gap");
  ASSERT_FALSE(follower_gap.holds && leader_gap.holds) << follower_gap.detail << "\n" << leader_gap.detail;
  EXPECT_EQ((follower_gap.holds ? leader_gap : follower_gap).liable_id, Party::ego());
  EXPECT_EQ(r.liable_id, Party::ego());
}

TEST(AdversarialPlanners, PretendingToMergeByDriftingOutAndBackIsWaiting) {
  // Out to 0.6 m off the centre and back to it every 40 m (2 s at 20 m/s) on an empty road, never
  // over the lane line: each outward swing is an observed start and each return an abort, neither
  // a merge, while every gap is open.
  Scenario s;
  s.name = "empty_road";
  auto p = follower("pretender",
                    [](double x) { return -3.5 + 0.3 * (1.0 - std::cos(2.0 * M_PI * x / 40.0)); }, 20.0, 39.0);
  const CheckResult r = check_scenario(s, p);
  ASSERT_GE(observe_merge_phases(r.trace, r.rule_params).count(MergePhaseKind::kAbort), 2);
  const RuleResult& progress = rule(r, "progress");
  ASSERT_FALSE(progress.holds) << progress.detail;
  EXPECT_EQ(progress.liable_id, Party::ego());
  EXPECT_LT(*progress.first_violation_time_s, 6.2);  // while still at 20 m/s (it brakes from 6.25 s)
}

TEST(AdversarialPlanners, AStraddlerWithItsBodyOverTheLaneLineLetsTheRightOfWayPass) {
  // On an empty road, out of the side lane until the body is 0.3 m over the lane line (centre at
  // Y = -2.4), then straight on there, never reaching the midpoint, stopping 39 m before the side
  // lane's end. An attempt whose body entered the main lane is a merge, but not for ever: 1.5 rho_b
  // after its start (6 s at rho_b = 4 s) the longest merge the rule offers would have reached its
  // midpoint, and from then the straddler waits while every gap is open. It broke no rule before.
  auto p = follower("straddler", [](double x) { return std::min(-2.4, -3.5 + 0.02 * std::max(0.0, x)); }, 20.0, 39.0);
  Scenario s;
  s.name = "empty_road";
  const CheckResult r = check_scenario(s, p);
  ASSERT_GE(observe_merge_phases(r.trace, r.rule_params).count(MergePhaseKind::kStart), 1);
  const RuleResult& progress = rule(r, "progress");
  ASSERT_FALSE(progress.holds) << progress.detail;
  EXPECT_EQ(progress.liable_id, Party::ego());
  EXPECT_NEAR(*progress.first_violation_time_s, r.trace.steps.front().time_s + 0.48 + 6.0 + 3.0, 0.5);
}

TEST(AdversarialPlanners, AnNanMarginFailsTheRuleInsteadOfPassing) {
  MarginAccumulator acc("progress", 3);
  acc.record(0, 0.0, 1.0, Party::ego(), 1.0, 0.0);
  acc.record(1, 0.02, std::nan(""), Party::ego(), 1.0, 0.0);
  const MonitorOutput out = acc.finish();
  EXPECT_FALSE(out.result.holds);
  EXPECT_EQ(out.result.liable_id, Party::ego());
  EXPECT_NEAR(*out.result.first_violation_time_s, 0.02, 1e-12);
  EXPECT_NE(out.result.detail.find("missing or not finite"), std::string::npos);
}

// The never-merging planner of the property: keeps the side lane's centre and halts 10 m before
// its end (a planner that obeys Def. 1.3 and never merges).
auto never_merging() {
  return keeper("never-merges", [](const WorldSnapshot& w) { return stopping_speed_mps(w, 10.0); });
}

// Whether some run of 0.1 s samples, each with a feasible gap while the ego waits in the side
// lane out of any RSS danger, holds more than the grace plus one sample of time in which the ego
// did not prepare a merge (a deliberate speed change toward a feasible gap's v_e*, at 0.5 m/s^2 or
// more, pauses the count without ending the run).
bool feasible_longer_than_grace(const CheckResult& r) {
  const ObservedTrace& t = r.trace;
  const RuleParams& p = r.rule_params;
  const Situation sit = observe_situation(t, p);
  const MonitorContext ctx{t, sit.row, p, sit.phases, sit.attempts, sit.exchanges};
  double owed_s = -1.0;
  for (std::size_t i = 0; i < t.steps.size(); i += 5) {
    const ObservedState& ego = t.steps[i].vehicles[0];
    const double line_y = -0.5 * t.road.lane_width_m;
    const std::vector<FeasibleMerge> gaps =
        ego.y_m < line_y && ego_left_edge_y_m(t, ego) <= line_y ? def1_gaps_feasible(t, p, i) : std::vector<FeasibleMerge>{};
    if (gaps.empty() || ego_rear_in_rss_danger(ctx, i)) {
      owed_s = -1.0;
      continue;
    }
    bool preparing = false;
    for (const FeasibleMerge& g : gaps)
      preparing = preparing || (ego.vx_mps > g.ve_max_mps && ego.accel_mps2 <= -0.5) ||
                  (ego.vx_mps < g.ve_star_mps && ego.accel_mps2 >= 0.5);
    owed_s = owed_s < 0.0 ? 0.0 : owed_s + (preparing ? 0.0 : 0.1);
    if (owed_s > p.progress_grace_s + 0.2) return true;
  }
  return false;
}

RC_GTEST_PROP(AdversarialPlanners, ANeverMergingPlannerFailsProgressWheneverAGapStayedFeasible, ()) {
  fuzz::GenConfig config;
  config.max_vehicles = 4;
  const Scenario scenario = *fuzz::gen_scenario(config);
  auto planner = never_merging();
  const CheckResult r = check_scenario(scenario, planner);
  const bool owed = feasible_longer_than_grace(r);
  RC_CLASSIFY(owed, "a gap stayed feasible longer than the grace");
  const RuleResult& progress = rule(r, "progress");
  if (owed) {
    RC_ASSERT(!progress.holds);
    RC_ASSERT(progress.liable_id == Party::ego());
  }
  if (!progress.holds) RC_ASSERT(progress.liable_id == Party::ego());
}

}  // namespace
}  // namespace mg
