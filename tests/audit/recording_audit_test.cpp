// Auditing recordings (src/audit/recording_audit.h): the reviewed results of the three public
// recordings (docs/audit.md "Results on the three public recordings"), merges on a synthetic road
// judged as Definition 1 and RSS would, the sensitivity sweep flagging a verdict that flips, and
// the trace of a merge.
#include <gtest/gtest.h>

#include "audit/recording_audit.h"
#include "recording/commonroad_reader.h"
#include "recording/road_layout.h"
#include "tests/recording/recording_files.h"
#include "tests/recording/synthetic_recording.h"

namespace mg {
namespace {

// The audit points into the recording and its road: they live beside it.
struct AuditedRecording {
  explicit AuditedRecording(Recording r) : recording(std::move(r)), road(build_road_layout(recording)) {
    audit = audit_recording(recording, road, default_audit_profile());
  }
  Recording recording;
  RoadLayout road;
  RecordingAudit audit;
};

std::unique_ptr<AuditedRecording> audit_of(Recording r) { return std::make_unique<AuditedRecording>(std::move(r)); }

std::unique_ptr<AuditedRecording> audit_file(const std::string& file) { return audit_of(load_recording(test::recording_path(file))); }

// Ego on the ramp changing lanes at t = 7 s at 20 m/s (its decision recorded); a follower `gap` m
// behind and a leader 150 m ahead in the main lane.
std::unique_ptr<AuditedRecording> audit_synthetic(double gap_m) {
  return audit_of(parse_recording(test::synthetic_recording_xml({test::lane_changer(1, 20, 20, -1.75, 1.75, 7.0, 130),
                                                                  test::lane_changer(2, 20 - gap_m, 20, 1.75, 1.75, 99, 130),
                                                                  test::lane_changer(3, 170, 20, 1.75, 1.75, 99, 130)}),
                                  "rec.xml"));
}

TEST(RecordingAudit, US101_4_1_TheLeaderLeavesTheMapBeforeTheChange) {
  // 389 drifts into the auxiliary lane; 375, next ahead of it in that lane, leaves the map at
  // 1.7 s, before 389 is in the lane: whether the gap ahead was enough was not recorded.
  const auto a = audit_file("USA_US101-4_1_T-1.xml");
  EXPECT_TRUE(a->road.highway_on_ramp);  // scenarioTags highway, though every lanelet is typed urban
  ASSERT_EQ(a->audit.merges.size(), 1u);
  const MergeAudit& m = a->audit.merges[0];
  EXPECT_EQ(m.merge.change.vehicle_id, 389);
  EXPECT_EQ(m.verdict, AuditVerdict::kUndetermined);
  ASSERT_TRUE(m.censoring.has_value());
  ASSERT_FALSE(m.censoring->missing.empty());
  EXPECT_NE(m.censoring->missing[0].find("vehicle 375"), std::string::npos) << m.censoring->missing[0];
  EXPECT_TRUE(m.result.holds);  // the rules find nothing in what was recorded
  EXPECT_TRUE(a->audit.holds());
}

TEST(RecordingAudit, US101_3_3_TheCutInOf394BeganBeforeTheRecording) {
  // 394 is already moving left at t = 0: judged as if decided then, it would be violated
  // (def1_1_gap toward 395), but its decision was not recorded.
  const auto a = audit_file("USA_US101-3_3_T-1.xml");
  ASSERT_EQ(a->audit.merges.size(), 1u);
  const MergeAudit& m = a->audit.merges[0];
  EXPECT_EQ(m.merge.change.vehicle_id, 394);
  EXPECT_EQ(m.verdict, AuditVerdict::kUndetermined);
  EXPECT_NE(m.censoring->reason.find("already under way at the first judged instant"), std::string::npos) << m.censoring->reason;
  EXPECT_FALSE(m.result.holds);
  EXPECT_NE(m.result.liability_detail.find("def1_1_gap"), std::string::npos);
}

TEST(RecordingAudit, ZipperMergeVehicle2TailgatesVehicle1) {
  const auto a = audit_file("ZAM_Zip-1_56_T-1.xml");
  ASSERT_EQ(a->audit.merges.size(), 3u);
  // 2 closes in on the slow 3 from the first instant and changes lanes: who made that danger
  // was not recorded, nor 2's decision.
  EXPECT_EQ(a->audit.merges[0].merge.change.kind, LaneChangeKind::kIntoRamp);
  EXPECT_EQ(a->audit.merges[0].verdict, AuditVerdict::kUndetermined);
  // Then 2 follows 1 in 1's lane at an unsafe distance without braking: liable in both merges.
  EXPECT_EQ(a->audit.merges[1].merge.change.vehicle_id, 1);
  EXPECT_EQ(a->audit.merges[1].verdict, AuditVerdict::kViolated);
  EXPECT_EQ(a->audit.merges[1].liable_name(), "vehicle 2");
  EXPECT_EQ(a->audit.merges[2].merge.change.vehicle_id, 2);
  EXPECT_EQ(a->audit.merges[2].liable_name(), "ego (vehicle 2)");
  for (std::size_t i = 1; i < 3; ++i) {
    const MergeAudit& m = a->audit.merges[i];
    ASSERT_TRUE(m.frontier.has_value());
    EXPECT_FALSE(m.frontier->rho.max_response_time_s.has_value()) << m.frontier->words;  // violated even at rho = 0
    EXPECT_EQ(m.frontier->binding_rule, "rss_longitudinal");
    ASSERT_TRUE(m.sensitivity.has_value());
    EXPECT_FALSE(m.sensitivity->flips);
  }
}

TEST(RecordingAudit, AMergeWellClearOfTrafficHolds) {
  const auto a = audit_synthetic(120);
  ASSERT_EQ(a->audit.merges.size(), 1u);
  EXPECT_EQ(a->audit.merges[0].verdict, AuditVerdict::kHolds);
  ASSERT_TRUE(a->audit.merges[0].frontier.has_value());
  EXPECT_TRUE(a->audit.merges[0].frontier->rho.holds_throughout) << a->audit.merges[0].frontier->words;
  // The frame: the ego starts at the side lane's centre, -W, and ends in the target lane's, 0.
  const ObservedTrace& t = a->audit.merges[0].merge.trace;
  EXPECT_NEAR(t.steps.front().vehicles[0].y_m, -3.5, 1e-6);
  EXPECT_NEAR(t.steps.back().vehicles[0].y_m, 0.0, 1e-6);
  EXPECT_DOUBLE_EQ(t.road.side_lane_end_x_m, 200.0);
  EXPECT_EQ(t.road.main_lanes, 2);
}

TEST(RecordingAudit, AMergeInFrontOfACloseFollowerIsTheEgosFault) {
  const auto a = audit_synthetic(20);
  const MergeAudit& m = a->audit.merges.at(0);
  EXPECT_EQ(m.verdict, AuditVerdict::kViolated);
  EXPECT_EQ(m.liable_name(), "ego (vehicle 1)");
  ASSERT_TRUE(m.sensitivity.has_value());
  EXPECT_FALSE(m.sensitivity->flips);  // violated at every response time and braking limit swept
  EXPECT_EQ(m.sensitivity->points.size(), 12u);
}

TEST(RecordingAudit, AVerdictThatFlipsInsideThePlausibleRangeIsFlagged) {
  const auto a = audit_synthetic(70);
  const MergeAudit& m = a->audit.merges.at(0);
  EXPECT_EQ(m.verdict, AuditVerdict::kViolated);
  ASSERT_TRUE(m.sensitivity.has_value());
  EXPECT_TRUE(m.sensitivity->flips);
  EXPECT_NE(m.sensitivity->summary.find("not certain"), std::string::npos);
  // Faster response holds: the only variations that hold have the shortest response time.
  for (const SensitivityPoint& p : m.sensitivity->points) {
    if (p.holds) {
      EXPECT_DOUBLE_EQ(p.response_time_s, 0.5);
    }
  }
}

}  // namespace
}  // namespace mg

namespace mg {
namespace {

TEST(RecordingAudit, ATraceHoldsAtMost64VehiclesTheNearestOnes) {
  std::vector<test::SyntheticVehicle> vs{test::lane_changer(1, 100, 20, -1.75, 1.75, 3.0, 80)};
  for (int k = 0; k < 70; ++k) vs.push_back(test::lane_changer(10 + k, 90 + k, 20, 1.75, 1.75, 99, 80));  // a dense jam
  const auto a = audit_of(parse_recording(test::synthetic_recording_xml(vs), "rec.xml"));
  ASSERT_EQ(a->audit.merges.size(), 1u);
  const MergeTrace& m = a->audit.merges[0].merge;
  EXPECT_EQ(m.trace.vehicles.size(), kMaxVehicles);
  EXPECT_EQ(m.left_out.size(), 71u - kMaxVehicles);
  EXPECT_NE(m.left_out[0].find("beyond the 64 vehicles a trace holds"), std::string::npos) << m.left_out[0];
  EXPECT_EQ(m.recording_ids[1], 20);  // x = 100, beside the ego, is the nearest
}

}  // namespace
}  // namespace mg
