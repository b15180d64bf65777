// The observable trace of a simulated run (check/observed_run.h): what it holds, taken from the
// curated scenarios with the planners that drive them, and that the trace format carries it
// back unchanged.
#include "check/observed_run.h"

#include <cmath>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "core/observed_trace_json.h"
#include "planner/planner.h"
#include "sim/simulator.h"

namespace mg {
namespace {

struct SimulatedRun {
  Scenario scenario;
  Trace trace;
  ObservedTrace observed;
};

SimulatedRun run(const std::string& name, const std::string& planner_name) {
  SimulatedRun r;
  r.scenario = load_scenario(std::string(MG_SOURCE_DIR) + "/corpus/scenarios/" + name + ".json");
  const auto planner = make_planner(planner_name);
  r.trace = simulate(r.scenario, *planner);
  r.observed = observed_trace_of(r.scenario, r.trace);
  return r;
}

TEST(ObservedRun, EveryStepHoldsEveryDeclaredVehicleInRoadFrameVelocities) {
  const SimulatedRun r = run("fig2_s3_ahead_coop", "rcpp-coop");
  ASSERT_EQ(r.observed.vehicles.size(), r.scenario.vehicles.size() + 1);
  EXPECT_EQ(r.observed.vehicles[0].id, 0);
  EXPECT_EQ(r.observed.vehicles[0].limits, r.scenario.ego.limits);
  for (std::size_t i = 0; i < r.scenario.vehicles.size(); ++i) {
    EXPECT_EQ(r.observed.vehicles[i + 1].id, r.scenario.vehicles[i].id);
    EXPECT_EQ(r.observed.vehicles[i + 1].size, r.scenario.vehicles[i].size);
    EXPECT_EQ(r.observed.vehicles[i + 1].v2v_capable, r.scenario.vehicles[i].v2v.capable);
  }
  ASSERT_EQ(r.observed.steps.size(), r.trace.steps.size());
  bool ego_yawed = false;
  for (std::size_t k = 0; k < r.trace.steps.size(); ++k) {
    const TraceStep& sim = r.trace.steps[k];
    const ObservedStep& obs = r.observed.steps[k];
    ASSERT_EQ(obs.vehicles.size(), sim.others.size() + 1);
    EXPECT_EQ(obs.time_s, sim.time_s);
    EXPECT_EQ(obs.vehicles[0].x_m, sim.ego.x_m);
    EXPECT_EQ(obs.vehicles[0].y_m, sim.ego.y_m);
    // dY/dt of the ego, not its body-frame lateral speed: they differ while it turns.
    EXPECT_EQ(obs.vehicles[0].vy_mps, sim.ego.road_vy_mps());
    EXPECT_EQ(obs.vehicles[0].vx_mps, sim.ego.road_vx_mps());
    ego_yawed = ego_yawed || std::abs(sim.ego.yaw_rad) > 0.01;
    for (std::size_t i = 0; i < sim.others.size(); ++i) EXPECT_EQ(obs.vehicles[i + 1].x_m, sim.others[i].x_m);
  }
  EXPECT_TRUE(ego_yawed) << "the scenario should contain a merge";
}

TEST(ObservedRun, TheChannelHoldsEveryMessageEventWithItsContent) {
  const SimulatedRun r = run("responder_reneges", "rcpp-coop");
  std::size_t sent = 0, delivered = 0;
  for (const ChannelEvent& e : r.observed.channel) {
    sent += e.kind == ChannelEventKind::kSent;
    delivered += e.kind == ChannelEventKind::kDelivered;
    if (e.kind == ChannelEventKind::kDelivered) {
      EXPECT_TRUE(std::isfinite(e.message.delivered_time_s));
    }
  }
  std::size_t message_events = 0;
  for (const TraceEvent& e : r.trace.events)
    message_events += e.kind == EventKind::kMessageSent || e.kind == EventKind::kMessageDelivered ||
                      e.kind == EventKind::kMessageLost;
  EXPECT_EQ(r.observed.channel.size(), message_events);
  EXPECT_GE(sent, 2u) << "a request and its answer";
  EXPECT_GE(delivered, 2u);
}

TEST(ObservedRun, ThePlannerSelfReportIsOnlyAnAnnotation) {
  const SimulatedRun r = run("responder_reneges", "rcpp-coop");
  const nlohmann::json& a = r.observed.planner_annotations;
  EXPECT_EQ(a.at("planner"), "rcpp-coop");
  EXPECT_EQ(a.at("decisions").size(), r.trace.decisions.size());
  EXPECT_EQ(a.at("decisions").at(0).at("mode"), r.trace.decisions.at(0).mode);
  // Nothing else in the file speaks of modes or decisions. (The judge's own parameters do: the
  // rules' merge_decision_window_s is how far before an observed start they look, not a planner's.)
  nlohmann::json j = observed_trace_to_json(r.observed);
  j.erase("planner_annotations");
  ASSERT_TRUE(j.at("params").at("rules").contains("merge_decision_window_s"));
  j.at("params").at("rules").erase("merge_decision_window_s");
  const std::string text = j.dump();
  EXPECT_EQ(text.find("mode"), std::string::npos);
  EXPECT_EQ(text.find("decision"), std::string::npos);
  EXPECT_EQ(text.find("proper_response"), std::string::npos);
}

TEST(ObservedRun, TheTraceFormatCarriesItBackBitForBit) {
  for (const auto& [name, planner] : {std::pair{"responder_reneges", "rcpp-coop"}, {"leader_overbrakes", "rcpp"},
                                      {"fig2_s2_behind_noncoop", "tripfield"}}) {
    const SimulatedRun r = run(name, planner);
    const std::string text = observed_trace_to_text(r.observed);
    const ObservedTrace back = observed_trace_from_text(text, name);
    EXPECT_EQ(observed_trace_to_text(back), text) << name;
    EXPECT_EQ(back.steps, r.observed.steps) << name;
    EXPECT_EQ(back.vehicles, r.observed.vehicles) << name;
  }
}

}  // namespace
}  // namespace mg
