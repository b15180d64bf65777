// What the audit can and cannot tell (docs/audit.md "Censoring", "What counts as an on-ramp",
// "Compliance frontier", "Main-lane duties toward entering vehicles"), on synthetic recordings
// whose answers the tests know: a merge under way when the recording starts, a gap vehicle seen
// for part of the decision, a danger already under way at the first instant, an urban junction,
// a merge that holds only below a response time computed here from RCPP eq. (1), a lane change
// toward a vehicle entering from the ramp, and a recording with nothing to audit.
#include <gtest/gtest.h>

#include <memory>

#include "audit/calibration.h"
#include "audit/recording_audit.h"
#include "core/rss.h"
#include "recording/commonroad_reader.h"
#include "recording/road_layout.h"
#include "tests/recording/synthetic_recording.h"

namespace mg {
namespace {

struct Audited {
  Audited(Recording r, const AuditOptions& o) : recording(std::move(r)), road(build_road_layout(recording)) {
    audit = audit_recording(recording, road, default_audit_profile(), o);
  }
  Recording recording;
  RoadLayout road;
  RecordingAudit audit;
};

std::unique_ptr<Audited> audit_xml(const std::string& xml, const AuditOptions& o = {}) {
  return std::make_unique<Audited>(parse_recording(xml, "rec.xml"), o);
}

const MergeAudit& merge_of(const Audited& a, int vehicle) {
  for (const MergeAudit& m : a.audit.merges) {
    if (m.merge.change.vehicle_id == vehicle) return m;
  }
  throw std::runtime_error("no merge of vehicle " + std::to_string(vehicle));
}

using test::lane_changer;

TEST(AuditCensoring, AMergeUnderWayAtTheFirstInstantIsUndetermined) {
  // The ego is already moving off the ramp's centre at t = 0, 20 m ahead of a main-lane vehicle:
  // judged as if decided at t = 0 it would be violated, but its decision was not recorded.
  const auto a = audit_xml(test::synthetic_recording_xml({lane_changer(1, 50, 20, -1.75, 1.75, 0.5, 100), lane_changer(2, 30, 20, 1.75, 1.75, 99, 100)}));
  const MergeAudit& m = merge_of(*a, 1);
  EXPECT_EQ(m.verdict, AuditVerdict::kUndetermined);
  ASSERT_TRUE(m.censoring.has_value());
  EXPECT_NE(m.censoring->reason.find("already under way at the first judged instant"), std::string::npos) << m.censoring->reason;
  EXPECT_FALSE(m.censoring->missing.empty());
  EXPECT_FALSE(m.censoring->judged_on_record.empty());  // on_road, sideslip, ... judged all the same
  EXPECT_FALSE(m.frontier.has_value());
  EXPECT_EQ(m.liable_name(), "-");
  EXPECT_EQ(a->audit.count(AuditVerdict::kUndetermined), 1);
  EXPECT_TRUE(a->audit.holds());  // undetermined alone is no violation
}

TEST(AuditCensoring, AnUnseenDecisionDoesNotMatterToAMergeThatHoldsWithoutIt) {
  // The same start with nobody near: no right of way is needed, so the verdict stands.
  const auto a = audit_xml(test::synthetic_recording_xml({lane_changer(1, 50, 20, -1.75, 1.75, 0.5, 100), lane_changer(2, 300, 20, 5.25, 5.25, 99, 100)}));
  EXPECT_EQ(merge_of(*a, 1).verdict, AuditVerdict::kHolds);
}

TEST(AuditCensoring, AGapVehicleSeenForPartOfTheDecisionLeavesAHoldingMergeUndetermined) {
  // The ego merges at 6 s with a clear gap; the vehicle just ahead of it in the main lane is
  // recorded only from 5 s (it entered the map then): whether it left room is not known.
  const auto a = audit_xml(test::synthetic_recording_xml({lane_changer(1, 50, 20, -1.75, 1.75, 6.0, 120),
                                                          test::recorded_from(lane_changer(2, 125, 20, 1.75, 1.75, 99, 120), 50)}));
  const MergeAudit& m = merge_of(*a, 1);
  EXPECT_EQ(m.verdict, AuditVerdict::kUndetermined) << m.result.liability_detail << " | " << m.merge.left_out.size();
  ASSERT_TRUE(m.censoring.has_value());
  EXPECT_NE(m.censoring->reason.find("was not observed over the decision window"), std::string::npos) << m.censoring->reason;
  ASSERT_EQ(m.censoring->missing.size(), 1u);
  EXPECT_NE(m.censoring->missing[0].find("vehicle 2, next to the ego in the lane entered, recorded only from 5.0 s"), std::string::npos)
      << m.censoring->missing[0];
}

TEST(AuditCensoring, ADangerUnderWayAtTheFirstInstantIsNotBlamedOnTheVehicleBehind) {
  // Vehicle 3 follows vehicle 2 in the main lane 15 m behind at the same speed from the first
  // instant (RSS-unsafe at 1 s response): whether 2 cut in or 3 closed in was not recorded, so
  // 3 is not blamed for not braking; the ego's merge, far ahead, is undetermined by it.
  const auto a = audit_xml(test::synthetic_recording_xml({lane_changer(1, 140, 20, -1.75, 1.75, 6.0, 120), lane_changer(2, 100, 20, 1.75, 1.75, 99, 120),
                                                          lane_changer(3, 85, 20, 1.75, 1.75, 99, 120)}));
  const MergeAudit& m = merge_of(*a, 1);
  EXPECT_EQ(m.verdict, AuditVerdict::kUndetermined);
  ASSERT_TRUE(m.censoring.has_value());
  EXPECT_NE(m.censoring->reason.find("the danger between vehicle 3 and vehicle 2 for which vehicle 3 is blamed"), std::string::npos)
      << m.censoring->reason;
  EXPECT_NE(m.censoring->reason.find("lasted to the window's end"), std::string::npos) << m.censoring->reason;
  // Judged as check-trace judges the trace, vehicle 3 would be liable: the rules are unchanged.
  EXPECT_FALSE(m.result.holds);
}

TEST(AuditOnRamp, ATurnAtAnUrbanJunctionIsNotJudgedAsARampMerge) {
  const std::string xml = test::urban_junction_xml({test::junction_turner(1, 8.0, 80)});
  const auto a = audit_xml(xml);
  EXPECT_FALSE(a->road.highway_on_ramp);
  EXPECT_NE(a->road.on_ramp_basis.find("not the geometry or speed limit of a ramp"), std::string::npos) << a->road.on_ramp_basis;
  // The turn is found as a join from lanelet 20 (projected on the eastbound lane, the straight
  // approach reads as lane changes back and forth): none of it is judged.
  ASSERT_FALSE(a->audit.merges.empty());
  EXPECT_EQ(a->audit.merges[0].merge.change.kind, LaneChangeKind::kRampMerge);
  for (const MergeAudit& m : a->audit.merges) {
    EXPECT_EQ(m.verdict, AuditVerdict::kNotJudged);
    EXPECT_NE(m.not_judged_reason.find("not a highway on-ramp"), std::string::npos);
  }
  // Asked for, every lane join is judged.
  const auto all = audit_xml(xml, AuditOptions{std::nullopt, true, false});
  EXPECT_TRUE(all->audit.merges.at(0).judged());
}

TEST(AuditOnRamp, TheMapSaysWhatARampIs) {
  // The synthetic road has no types nor tags: its ramp runs beside the main lane for 200 m.
  const auto plain = audit_xml(test::synthetic_recording_xml({lane_changer(1, 50, 20, -1.75, 1.75, 4.0, 60)}));
  EXPECT_TRUE(plain->road.highway_on_ramp);
  EXPECT_NE(plain->road.on_ramp_basis.find("geometry and speed limit of a ramp"), std::string::npos) << plain->road.on_ramp_basis;
  // A scenario tag says highway even where every lanelet is typed urban (the NGSIM recordings).
  std::string junction = test::urban_junction_xml({test::junction_turner(1, 8.0, 80)});
  junction.replace(junction.find("<urban/><intersection/>"), 23, "<highway/>");
  EXPECT_TRUE(audit_xml(junction)->road.highway_on_ramp);
}

// The centre-to-centre distance RCPP eq. (1) asks of two cars at 20 m/s (the profile's car class).
double car_following_distance_m(double rho_s) {
  return rss_longitudinal_m({20.0, 20.0, 4.5, 4.5, rho_s, 3.5, 4.0, 8.0});
}

TEST(AuditFrontier, AMergeBehindALeaderHoldsExactlyBelowTheResponseTimeOfItsGap) {
  // The ego merges from the ramp 60 m (centre to centre) behind a main-lane vehicle, both at
  // 20 m/s throughout: it holds while 60 m >= D_lon(rho), i.e. up to the rho found here.
  double lo = 0.0, hi = 5.0;
  while (hi - lo > 1e-6) (car_following_distance_m(0.5 * (lo + hi)) <= 60.0 ? lo : hi) = 0.5 * (lo + hi);
  const double known_s = lo;
  ASSERT_GT(known_s, 0.5);
  ASSERT_LT(known_s, 1.0);
  const auto a = audit_xml(test::synthetic_recording_xml({lane_changer(1, 20, 20, -1.75, 1.75, 7.0, 140), lane_changer(2, 80, 20, 1.75, 1.75, 99, 140)}));
  const MergeAudit& m = merge_of(*a, 1);
  ASSERT_EQ(m.verdict, AuditVerdict::kViolated) << (m.censoring ? m.censoring->reason : "");
  ASSERT_TRUE(m.frontier.has_value());
  ASSERT_TRUE(m.frontier->rho.max_response_time_s.has_value());
  EXPECT_NEAR(*m.frontier->rho.max_response_time_s, known_s, 2 * kFrontierResolutionS) << m.frontier->words;
  EXPECT_EQ(m.frontier->binding_rule, "rss_longitudinal");
  EXPECT_NE(m.frontier->words.find("violated at rho = 1 s; holds for rho <= 0.76 s (binding: rss_longitudinal"), std::string::npos) << m.frontier->words;
  EXPECT_NE(m.frontier->words.find("at rho = 1 s a follower would need b_min >= 5.5 m/s2 (profile: 4.0)"), std::string::npos) << m.frontier->words;
  // Below the frontier the trace holds, above it not: the same judgement as the verdict.
  EXPECT_TRUE(check_observed(with_profile_variation(m.merge.trace, known_s - 0.02, 1.0)).holds);
  EXPECT_FALSE(check_observed(with_profile_variation(m.merge.trace, known_s + 0.02, 1.0)).holds);
  ASSERT_TRUE(m.sensitivity.has_value());
  EXPECT_TRUE(m.sensitivity->flips);  // holds at 0.5 s, violated from 1 s
}

TEST(AuditEnteringVehicles, ALaneChangeIntoTheLaneARampVehicleEntersIsJudgedTowardIt) {
  // Vehicle 5 is on the ramp and enters the right main lane at 10 s; the ego changes from the
  // left main lane into the right one at 7 s, 15 m behind it (CommonRoad R_I5's situation).
  const std::vector<test::SyntheticVehicle> scene{lane_changer(1, 35, 10, 5.25, 1.75, 7.0, 140), lane_changer(5, 50, 10, -1.75, 1.75, 10.0, 140)};
  const auto a = audit_xml(test::synthetic_recording_xml(scene));
  const MergeAudit& m = merge_of(*a, 1);
  EXPECT_EQ(m.merge.change.kind, LaneChangeKind::kCutIn);
  EXPECT_EQ(m.merge.entering_ids, std::vector<int>{5});
  EXPECT_EQ(m.verdict, AuditVerdict::kViolated) << (m.censoring ? m.censoring->reason : "");
  EXPECT_EQ(m.liable_name(), "ego (vehicle 1)");
  // Without the entering vehicle the same lane change holds.
  const auto alone = audit_xml(test::synthetic_recording_xml({scene[0]}));
  EXPECT_EQ(merge_of(*alone, 1).verdict, AuditVerdict::kHolds);
}

TEST(AuditNothing, ARecordingWithoutMovingVehiclesHasNothingToAudit) {
  const auto a = audit_xml(test::synthetic_recording_xml({}));
  EXPECT_TRUE(a->audit.merges.empty());
  EXPECT_NE(a->audit.nothing_to_audit().find("no moving vehicle"), std::string::npos);
  EXPECT_TRUE(a->audit.holds());
}

TEST(AuditCalibration, TheProposalIsTheFirstProfileOfTheGridThatReachesTheShare) {
  using V = AuditVerdict;
  const std::size_t n = calibration_brake_scales().size() * calibration_response_times().size();
  // Merge A holds everywhere; merge B holds only with braking x1.5 or more and rho <= 1 s.
  std::vector<V> a(n, V::kHolds), b(n, V::kViolated);
  const std::size_t rhos = calibration_response_times().size();
  for (std::size_t j = 2; j < calibration_brake_scales().size(); ++j) {
    for (std::size_t k = 0; k < rhos; ++k) {
      if (calibration_response_times()[k] <= 1.0 + 1e-9) b[j * rhos + k] = V::kHolds;
    }
  }
  const CalibrationChoice half = choose_calibration({a, b}, 0.5, default_audit_profile());
  EXPECT_TRUE(half.found);
  EXPECT_DOUBLE_EQ(half.brake_scale, 1.0);
  EXPECT_DOUBLE_EQ(half.response_time_s, 2.0);
  const CalibrationChoice all = choose_calibration({a, b}, 1.0, default_audit_profile());
  EXPECT_TRUE(all.found);
  EXPECT_DOUBLE_EQ(all.brake_scale, 1.5);
  EXPECT_DOUBLE_EQ(all.response_time_s, 1.0);
  EXPECT_EQ(all.holding, 2);
  // The proposed profile keeps each class within its plausible braking range.
  const AuditProfile p = calibrated_profile(default_audit_profile(), 1.0, 2.0);
  EXPECT_DOUBLE_EQ(p.classes.at("car").brake_min_mps2, 8.0);
  EXPECT_DOUBLE_EQ(p.classes.at("car").brake_max_mps2, 10.0);
  EXPECT_DOUBLE_EQ(p.classes.at("truck").brake_min_mps2, 6.0);
  EXPECT_DOUBLE_EQ(p.classes.at("truck").brake_max_mps2, 8.0);
}

}  // namespace
}  // namespace mg
