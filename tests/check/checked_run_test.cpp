// The lying planner: the checker judges what was observed, never what the planner says
// about itself. For generated scenarios (fuzz/scenario_gen.h) and the built-in planners, the run's
// observable trace judged intact, with its planner_annotations removed, with falsified
// annotations (other modes, gaps, P_c values, invented merge claims) and with random JSON in their
// place gives the same verdict, the same violated rules and the same liable parties
// (src/check/checked_run.h simulates and judges; rules/check.h judges).
//
// Each run simulates once (2-5 ms) and judges four times; the number of runs is RapidCheck's
// (RC_PARAMS="max_success=N", default 100).
#include "check/checked_run.h"

#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "fuzz/scenario_gen.h"
#include "planner/rcpp_planner.h"
#include "rules/check.h"
#include "tests/sim/test_planners.h"

namespace mg {
namespace {

using nlohmann::json;

const std::vector<std::string> kModes = {"keep_lane", "def1_merge", "def2_request", "def2_merge", "def1_halt",
                                         "proper_response", "merged", "potential_field", "yield", ""};

// What the property compares: every field the judgement consists of. The planner's name is not
// among them: it is read from the annotations to be shown, and a lie may rename the planner.
std::string judgement(const CheckResult& r) {
  std::ostringstream out;
  out.precision(17);
  out << "holds " << r.holds << ", liable " << r.liable_id.code() << ", collision " << r.collision << " liable "
      << r.collision_liable_id.code() << "\n";
  for (const RuleResult& rule : r.rules) {
    out << rule.rule_id << ": holds " << rule.holds << ", liable " << rule.liable_id.code() << ", first violation "
        << (rule.first_violation_time_s ? std::to_string(*rule.first_violation_time_s) : "none") << " ("
        << (rule.first_violation_time_s ? *rule.first_violation_time_s : -1.0) << "), margin " << rule.min_margin
        << "\n";
  }
  out << "right of way:";
  for (const auto& [t, holder] : r.right_of_way) out << " " << t << "->" << holder.code();
  out << "\nmerge phases:";
  for (const double t : r.merge_phase_times_s) out << " " << t;
  out << "\n";
  return out.str();
}

// The planner's account, falsified: every decision gets another mode, another gap, other v_e*,
// P_c and D*_lon values and another reason, and merges are claimed at random moments.
json falsified(const json& annotations, const ObservedTrace& t, std::uint32_t seed) {
  std::mt19937 rng(seed);
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  const auto number = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const auto some_id = [&]() -> json {
    const int k = pick(static_cast<int>(t.vehicles.size()) + 2);
    if (k == 0) return nullptr;
    if (k == 1) return 99;  // undeclared
    return t.vehicles[static_cast<std::size_t>(k - 2)].id;
  };
  json lie = annotations.is_object() ? annotations : json::object();
  json decisions = lie.contains("decisions") && lie["decisions"].is_array() ? lie["decisions"] : json::array();
  for (json& d : decisions) {
    if (!d.is_object()) continue;
    d["mode"] = kModes[static_cast<std::size_t>(pick(static_cast<int>(kModes.size())))];
    d["gap"] = pick(4) == 0 ? json(nullptr) : json{{"follower_id", some_id()}, {"leader_id", some_id()}};
    for (const char* key : {"ve_min_mps", "ve_max_mps", "ve_star_mps", "vo_star_mps"}) d[key] = number(-5.0, 60.0);
    for (const char* key : {"pc_min_m", "pc_max_m", "pc_m", "d_lon_star_m"}) d[key] = number(-1000.0, 1000.0);
    d["coop_partner_id"] = some_id();
    d["reason"] = "the ego held the right of way (it says)";
  }
  const double end = t.steps.back().time_s;
  for (int k = pick(5); k > 0; --k)
    decisions.push_back({{"time_s", number(0.0, end)}, {"mode", pick(2) ? "def1_merge" : "def2_merge"},
                         {"gap", {{"follower_id", some_id()}, {"leader_id", some_id()}}}, {"pc_m", number(0.0, 500.0)},
                         {"reason", "gap feasible, right of way granted"}});
  lie["decisions"] = std::move(decisions);
  lie["planner"] = pick(2) ? "rcpp" : "an honest planner";
  lie["right_of_way"] = "ego";
  lie["liable"] = "vehicle 1";
  return lie;
}

// Any JSON value, up to `depth` levels of nesting, with the annotation keys among its keys.
json random_json(int depth) {
  const int kind = *rc::gen::inRange(0, depth > 0 ? 7 : 5);
  switch (kind) {
    case 0: return nullptr;
    case 1: return *rc::gen::arbitrary<bool>();
    case 2: return *rc::gen::arbitrary<int>();
    case 3: return *rc::gen::inRange(-1000000, 1000000) / 7.0;
    case 4: return *rc::gen::container<std::string>(rc::gen::inRange('a', 'z'));
    case 5: {
      json a = json::array();
      for (int n = *rc::gen::inRange(0, 4); n > 0; --n) a.push_back(random_json(depth - 1));
      return a;
    }
    default: {
      json o = json::object();
      for (int n = *rc::gen::inRange(0, 4); n > 0; --n) {
        const std::string key = *rc::gen::element<std::string>("planner", "decisions", "mode", "gap", "pc_m", "time_s",
                                                               "reason", "right_of_way", "liable", "other");
        o[key] = random_json(depth - 1);
      }
      return o;
    }
  }
}

RC_GTEST_PROP(CheckedRun, TheVerdictIgnoresWhatThePlannerSaysAboutItself, ()) {
  fuzz::GenConfig config;
  config.max_vehicles = 4;
  const Scenario scenario = *fuzz::gen_scenario(config);
  const std::string planner = *rc::gen::element<std::string>("rcpp", "rcpp-coop", "tripfield");
  const CheckResult honest = check_scenario(scenario, planner, PlannerAccount::kDecisions);
  const ObservedTrace& trace = honest.trace;
  RC_ASSERT(!trace.planner_annotations.is_null());
  RC_TAG(planner, honest.holds ? "holds" : "violated");
  const std::string expected = judgement(honest);

  const auto judged_with = [&trace](json annotations) {
    ObservedTrace t = trace;
    t.planner_annotations = std::move(annotations);
    return judgement(check_observed(std::move(t)));
  };
  RC_ASSERT(judged_with(nullptr) == expected);
  RC_ASSERT(judged_with(falsified(trace.planner_annotations, trace, *rc::gen::arbitrary<std::uint32_t>())) == expected);
  RC_ASSERT(judged_with(random_json(3)) == expected);
}

// The annotations really are the planner's (the property above would hold trivially otherwise),
// and a falsified account really differs from them.
// The default ego and one vehicle 60 m ahead of it.
Scenario one_vehicle_ahead() {
  Scenario s;
  MainVehicle v;
  v.id = 1;
  v.x_m = 60.0;
  s.vehicles.push_back(v);
  return s;
}

TEST(CheckedRun, TheAnnotationsHoldThePlannersDecisions) {
  const Scenario s = one_vehicle_ahead();
  const CheckResult r = check_scenario(s, "rcpp", PlannerAccount::kDecisions);
  const json& a = r.trace.planner_annotations;
  ASSERT_TRUE(a.is_object());
  EXPECT_EQ(a.at("planner"), "rcpp");
  ASSERT_FALSE(a.at("decisions").empty());
  EXPECT_NE(falsified(a, r.trace, 7), a);
}

// check_scenario takes a planner object as well as a registry name: a planner under test needs no
// registration, and one object is judged exactly as the registry's planner of the same kind.
TEST(CheckedRun, APlannerObjectOutsideTheRegistryIsJudgedLikeARegisteredOne) {
  const Scenario s = one_vehicle_ahead();
  RcppPlanner rcpp(false);
  const CheckResult by_object = check_scenario(s, rcpp);
  const CheckResult by_name = check_scenario(s, "rcpp");
  EXPECT_EQ(by_object.trace_digest, by_name.trace_digest);
  EXPECT_EQ(by_object.holds, by_name.holds);
  EXPECT_EQ(by_object.liable_id, by_name.liable_id);

  // A planner nobody registered: keeps the side lane and halts, and is judged all the same.
  test::LaneKeepPlanner unregistered(s.ego.y_m, 0.0, 4.0);
  ASSERT_EQ(make_planner(unregistered.name()), nullptr);
  const CheckResult judged = check_scenario(s, unregistered);
  EXPECT_EQ(judged.planner, unregistered.name());
  EXPECT_FALSE(judged.rules.empty());
}

}  // namespace
}  // namespace mg
