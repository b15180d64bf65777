// The merge phases the rules observe (rules/merge_phases.h): on the curated scenarios with the
// planners that drive them, read from the run and from its observable trace they are the same,
// and with the default thresholds they fall on the simulator's merge events.
#include "rules/merge_phases.h"

#include <optional>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "planner/planner.h"
#include "sim/observed_run.h"
#include "sim/simulator.h"

namespace mg {
namespace {

std::optional<double> first_event_s(const Trace& t, EventKind k) {
  for (const TraceEvent& e : t.events)
    if (e.kind == k && e.vehicle_id == 0) return e.time_s;
  return std::nullopt;
}

TEST(MergePhases, ObservedFromTheRunOrItsTraceTheyFallOnTheSimulatorsMergeEvents) {
  int merged = 0;
  for (const auto& [name, planner] : {std::pair{"responder_reneges", "rcpp-coop"}, {"leader_overbrakes", "rcpp"},
                                      {"fig2_s3_ahead_coop", "rcpp-coop"}, {"fig2_s2_behind_noncoop", "tripfield"}}) {
    const Scenario s = load_scenario(std::string(MG_SOURCE_DIR) + "/corpus/scenarios/" + name + ".json");
    const Trace t = simulate(s, *make_planner(planner));
    const MergePhases from_run = observe_merge_phases(s, t);
    const MergePhases from_trace = observe_merge_phases(observed_trace_of(s, t));
    ASSERT_EQ(from_run.events.size(), from_trace.events.size()) << name;
    for (std::size_t i = 0; i < from_run.events.size(); ++i) {
      EXPECT_EQ(from_run.events[i].kind, from_trace.events[i].kind) << name;
      EXPECT_EQ(from_run.events[i].step, from_trace.events[i].step) << name;
    }
    const auto time_of = [&](MergePhaseKind k) -> std::optional<double> {
      const auto e = from_run.first(k);
      return e ? std::optional(e->time_s) : std::nullopt;
    };
    EXPECT_EQ(time_of(MergePhaseKind::kStart), first_event_s(t, EventKind::kMergeStart)) << name;
    EXPECT_EQ(time_of(MergePhaseKind::kMidpoint), first_event_s(t, EventKind::kMergeMidpoint)) << name;
    EXPECT_EQ(time_of(MergePhaseKind::kComplete), first_event_s(t, EventKind::kMergeComplete)) << name;
    merged += time_of(MergePhaseKind::kComplete).has_value();
  }
  EXPECT_GE(merged, 3) << "most of these scenarios end with a completed merge";
}

TEST(MergePhases, AnEgoThatStartsInTheMainLaneNeverMerges) {
  Scenario s = load_scenario(std::string(MG_SOURCE_DIR) + "/corpus/scenarios/fig2_s1_ahead_noncoop.json");
  s.ego.y_m = 0.0;
  s.params.sim.horizon_s = 3.0;
  const Trace t = simulate(s, *make_planner("rcpp"));
  EXPECT_TRUE(observe_merge_phases(s, t).events.empty());
}

}  // namespace
}  // namespace mg
