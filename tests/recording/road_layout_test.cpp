// The road of a recording (src/recording/road_layout.h): the ramp and the main lanes found by
// topology in the three public recordings and a synthetic one, by laneletType where present, and
// a recording without a ramp refused.
#include <regex>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "recording/commonroad_reader.h"
#include "recording/road_layout.h"
#include "recording_files.h"
#include "synthetic_recording.h"

namespace mg {
namespace {

RoadLayout road_of(const std::string& file) { return build_road_layout(load_recording(test::recording_path(file))); }

TEST(RoadLayout, FindsTheRampsOfThePublicRecordings) {
  const RoadLayout a = road_of("USA_US101-4_1_T-1.xml");
  EXPECT_EQ(a.ramp.name(), "lanelets 15-16");
  EXPECT_EQ(a.ramp_side, RampSide::kRight);
  ASSERT_EQ(a.main_lanes.size(), 5u);
  EXPECT_EQ(a.main_lanes[0].name(), "lanelets 12-13");
  EXPECT_EQ(a.main_lanes[4].name(), "lanelets 2-4");
  EXPECT_NEAR(a.ramp_end_s_m, 121.9, 0.5);
  const RoadLayout b = road_of("USA_US101-3_3_T-1.xml");
  EXPECT_EQ(b.ramp.name(), "lanelets 23-22");
  EXPECT_EQ(b.main_lanes.size(), 5u);
  const RoadLayout c = road_of("ZAM_Zip-1_56_T-1.xml");
  EXPECT_EQ(c.ramp.name(), "lanelets 25-28");  // bends into 24; 26-27-24 runs straight on
  EXPECT_EQ(c.ramp_side, RampSide::kLeft);
  ASSERT_EQ(c.main_lanes.size(), 1u);
  EXPECT_EQ(c.main_lanes[0].name(), "lanelets 26-27-24");
  EXPECT_NEAR(c.ramp_end_s_m, 180.4, 0.5);
}

TEST(RoadLayout, LanesOfTheSyntheticRoadAreWhereTheyWereDrawn) {
  const RoadLayout r = build_road_layout(parse_recording(test::synthetic_recording_xml({test::lane_changer(1, 0, 10, 1.75, 1.75, 50, 10)}), "rec.xml"));
  EXPECT_NEAR(r.lane_width_m, 3.5, 1e-9);
  EXPECT_NEAR(r.main_lanes[1].centre_d_at(100), 3.5, 1e-6);
  EXPECT_NEAR(r.ramp.centre_d_at(100), -3.5, 1e-6);
  EXPECT_NEAR(r.ramp_end_s_m, 200, 1e-6);
  EXPECT_EQ(r.found_by, "topology: the rightmost lane, which ends with a main lane on its left");
}

TEST(RoadLayout, PrefersLaneletTypes) {
  std::string xml = test::synthetic_recording_xml({test::lane_changer(1, 0, 10, 1.75, 1.75, 50, 10)});
  // Typed, the ramp may even continue as far as the main lanes.
  xml = std::regex_replace(xml, std::regex("<adjacentLeft ref=\"2\" drivingDir=\"same\"/>"),
                           "<adjacentLeft ref=\"2\" drivingDir=\"same\"/><laneletType>accessRamp</laneletType>");
  const RoadLayout r = build_road_layout(parse_recording(xml, "rec.xml"));
  EXPECT_EQ(r.found_by, "laneletType accessRamp");
  EXPECT_EQ(r.ramp.name(), "lanelet 1");
}

TEST(RoadLayout, RefusesARoadWithoutARamp) {
  std::string xml = test::synthetic_recording_xml({test::lane_changer(1, 0, 10, 1.75, 1.75, 50, 10)});
  // Three lanes side by side that nothing says are adjacent: no lane has a main lane beside it.
  xml = std::regex_replace(xml, std::regex("<adjacent(Left|Right) ref=\"[0-9]\" drivingDir=\"same\"/>"), "");
  try {
    build_road_layout(parse_recording(xml, "rec.xml"));
    ADD_FAILURE() << "a road without a ramp was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("rec.xml: lanelets: no ramp found", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace mg

namespace mg {
namespace {

TEST(RoadLayout, RefusesALaneLongerThanARecordingCovers) {
  std::string xml = test::synthetic_recording_xml({test::lane_changer(1, 0, 10, 1.75, 1.75, 50, 10)});
  xml = std::regex_replace(xml, std::regex("<x>400.000000</x>"), "<x>30000</x>");
  try {
    build_road_layout(parse_recording(xml, "rec.xml"));
    ADD_FAILURE() << "a 30 km lane was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("longer than a recording covers (at most 20 km)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mg
