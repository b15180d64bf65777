// Lane changes in a recording (src/recording/merge_finder.h): a ramp merge, a cut-in, a change
// into the ramp and a halt on the ramp on a synthetic road; a lanelet change along a lane is no
// merge; short stays across a lane line are noise; and the lane changes of the public recordings.
#include <gtest/gtest.h>

#include "recording/commonroad_reader.h"
#include "recording/merge_finder.h"
#include "recording_files.h"
#include "synthetic_recording.h"

namespace mg {
namespace {

std::vector<LaneChange> changes_of(const std::vector<test::SyntheticVehicle>& vs) {
  const Recording r = parse_recording(test::synthetic_recording_xml(vs), "rec.xml");
  const RoadLayout road = build_road_layout(r);
  std::vector<FrenetTrack> tracks;
  for (const RecordedVehicle& v : r.vehicles) tracks.push_back(project_track(v, road.reference, r.time_step_s, 3));
  return find_lane_changes(tracks, road, {});
}

TEST(MergeFinder, FindsRampMergesCutInsAndChangesIntoTheRamp) {
  const auto c = changes_of({test::lane_changer(1, 20, 20, -1.75, 1.75, 3.0, 80),    // ramp -> main 0
                             test::lane_changer(2, 40, 20, 1.75, 5.25, 5.0, 80),     // main 0 -> main 1
                             test::lane_changer(3, 60, 20, 1.75, -1.75, 2.0, 60)});  // main 0 -> ramp
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].vehicle_id, 3);
  EXPECT_EQ(c[0].kind, LaneChangeKind::kIntoRamp);
  EXPECT_EQ(c[1].vehicle_id, 1);
  EXPECT_EQ(c[1].kind, LaneChangeKind::kRampMerge);
  EXPECT_EQ(c[1].time_step, 30);  // the centre crosses the lane line at t = 3 s
  EXPECT_EQ(c[2].vehicle_id, 2);
  EXPECT_EQ(c[2].kind, LaneChangeKind::kCutIn);
  EXPECT_EQ(c[2].from_lane, 0);
  EXPECT_EQ(c[2].to_lane, 1);
}

TEST(MergeFinder, StayingInALaneIsNoMergeAndShortExcursionsAreNoise) {
  test::SyntheticVehicle wobbly = test::lane_changer(1, 0, 20, 1.75, 1.75, 50, 80);
  for (int i = 30; i < 33; ++i) wobbly.xyv[static_cast<std::size_t>(i)][1] = 3.6;  // 0.3 s over the line
  EXPECT_TRUE(changes_of({wobbly}).empty());
}

TEST(MergeFinder, AuditsAVehicleHaltedAtTheRampsEnd) {
  test::SyntheticVehicle halted;
  halted.id = 9;
  for (int i = 0; i < 40; ++i) halted.xyv.push_back({180.0, -1.75, 0.0, 0.0});
  const auto c = changes_of({halted});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].kind, LaneChangeKind::kRampHalt);
  EXPECT_EQ(c[0].to_lane, 0);
}

std::vector<LaneChange> recording_changes(const std::string& file) {
  const Recording r = load_recording(test::recording_path(file));
  const RoadLayout road = build_road_layout(r);
  std::vector<FrenetTrack> tracks;
  for (const RecordedVehicle& v : r.vehicles) tracks.push_back(project_track(v, road.reference, r.time_step_s, 3));
  return find_lane_changes(tracks, road, {});
}

TEST(MergeFinder, LaneChangesOfThePublicRecordings) {
  const auto a = recording_changes("USA_US101-4_1_T-1.xml");
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].vehicle_id, 389);
  EXPECT_EQ(a[0].kind, LaneChangeKind::kIntoRamp);
  EXPECT_EQ(a[0].time_step, 41);
  const auto b = recording_changes("USA_US101-3_3_T-1.xml");
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].vehicle_id, 394);
  EXPECT_EQ(b[0].kind, LaneChangeKind::kCutIn);
  EXPECT_EQ(b[0].from_lane, 2);
  EXPECT_EQ(b[0].to_lane, 3);
  const auto c = recording_changes("ZAM_Zip-1_56_T-1.xml");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].vehicle_id, 2);
  EXPECT_EQ(c[0].kind, LaneChangeKind::kIntoRamp);
  EXPECT_EQ(c[1].vehicle_id, 1);
  EXPECT_EQ(c[1].kind, LaneChangeKind::kRampMerge);
  EXPECT_EQ(c[2].vehicle_id, 2);
  EXPECT_EQ(c[2].kind, LaneChangeKind::kRampMerge);
}

}  // namespace
}  // namespace mg

namespace mg {
namespace {

TEST(LaneSequence, ShortRunsTakeTheLaneOfTheLastLongRun) {
  // Lanes drawn directly: main lane 0 at y 1.75, main lane 1 at 5.25.
  test::SyntheticVehicle v = test::lane_changer(1, 0, 20, 1.75, 1.75, 50, 40);
  for (int i = 0; i < 3; ++i) v.xyv[static_cast<std::size_t>(i)][1] = 5.25;            // a short first run: lane 1
  for (int i = 20; i < 40; i += 2) v.xyv[static_cast<std::size_t>(i)][1] = 5.25;       // flipping every step
  const Recording r = parse_recording(test::synthetic_recording_xml({v}), "rec.xml");
  const RoadLayout road = build_road_layout(r);
  const std::vector<int> lanes = lane_sequence(project_track(r.vehicles[0], road.reference, 0.1, 3), road, 5);
  EXPECT_EQ(lanes, std::vector<int>(40, 0));
}

}  // namespace
}  // namespace mg
