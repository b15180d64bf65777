// The round trip: a simulated run's observable trace written out as a CommonRoad
// recording, on a straight road and on a bend, read back and audited, gives the verdict and liable
// party that `check` gave for the simulation (the audit's profile is the scenario's own
// parameters and declared limits, its window the whole run). The rcpp scenarios of corpus/scenarios/
// with a verdict, but follower_exceeds_accel: its 12 s horizon ends one step after the
// ego's centre crosses the lane line, and the audit takes a stay in a lane shorter than 0.5 s for
// noise, so it finds no lane change to audit (docs/audit.md, "Limitations"). The rcpp-coop ones
// need the V2V channel, which a recording does not hold.
#include <gtest/gtest.h>

#include "audit/recording_audit.h"
#include "check/checked_run.h"
#include "core/scenario.h"
#include "recording/commonroad_reader.h"
#include "recording/commonroad_writer.h"
#include "recording/road_layout.h"
#include "recording/trace_recording.h"

namespace mg {
namespace {

AuditProfile profile_of(const ObservedTrace& t, const TraceRecording& tr) {
  AuditProfile p = default_audit_profile();
  p.name = "the scenario's own parameters";
  p.rss = t.params.rss;
  p.rules = t.params.rules;
  p.classes = tr.limits_by_type;
  p.classes["default"] = tr.limits_by_type.begin()->second;
  p.window_before_s = 60.0;
  p.window_after_s = 60.0;
  p.neighbour_range_m = 1000.0;
  p.default_speed_limit_mps = t.road.speed_limit_mps;
  return p;
}

// The liable party of the audit in the trace's ids.
Party trace_party(const MergeAudit& m) {
  if (!m.result.liable_id.is_vehicle()) return m.result.liable_id;
  return Party::vehicle(m.result.liable_id.vehicle_id() - kTraceObstacleIdBase);
}

struct Case {
  const char* scenario;
  double bend_radius_m;
};

class RoundTrip : public ::testing::TestWithParam<Case> {};

TEST_P(RoundTrip, TheAuditOfTheRecordedRunAgreesWithCheck) {
  const Scenario s = load_scenario(std::string(MG_SOURCE_DIR) + "/corpus/scenarios/" + GetParam().scenario + ".json");
  const CheckResult checked = check_scenario(s, "rcpp");
  const TraceRecording tr = trace_to_recording(checked.trace, GetParam().bend_radius_m);
  const Recording r = parse_recording(recording_to_xml(tr.recording), "round trip");
  const RoadLayout road = build_road_layout(r);
  const RecordingAudit a = audit_recording(r, road, profile_of(checked.trace, tr), AuditOptions{kTraceObstacleIdBase, false, false});
  ASSERT_EQ(a.merges.size(), 1u) << "the ego's merge (or halt) is found, and only it";
  const MergeAudit& m = a.merges[0];
  // The side lane ends as far ahead of the ego as it did in the simulation.
  EXPECT_NEAR(m.merge.trace.road.side_lane_end_x_m - m.merge.trace.steps[0].vehicles[0].x_m,
              checked.trace.road.side_lane_end_x_m - checked.trace.steps[0].vehicles[0].x_m, 0.1);
  // A simulated run records everything from its first instant: nothing is censored.
  EXPECT_EQ(m.verdict, checked.holds ? AuditVerdict::kHolds : AuditVerdict::kViolated) << (m.censoring ? m.censoring->reason : "");
  EXPECT_EQ(m.result.holds, checked.holds) << m.result.liability_detail << " | check: " << checked.liability_detail;
  EXPECT_EQ(trace_party(m), checked.liable_id) << m.result.liability_detail << " | check: " << checked.liability_detail;
}

INSTANTIATE_TEST_SUITE_P(Scenarios, RoundTrip,
                         ::testing::Values(Case{"paper_merge", 0}, Case{"paper_merge", 400}, Case{"fig2_s1_ahead_noncoop", 0},
                                           Case{"fig2_s1_ahead_noncoop", 400}, Case{"fig2_s2_behind_noncoop", 0},
                                           Case{"fig2_s2_behind_noncoop", 400}, Case{"leader_overbrakes", 0},
                                           Case{"leader_overbrakes", 400}, Case{"no_feasible_gap_halt", 0},
                                           Case{"no_feasible_gap_halt", 400}),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           return std::string(i.param.scenario) + (i.param.bend_radius_m > 0 ? "_bend" : "_straight");
                         });

}  // namespace
}  // namespace mg
