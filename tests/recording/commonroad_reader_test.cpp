// The CommonRoad reader (src/recording/commonroad_reader.h): both versions, the three public
// recordings, set-valued states read as their centres, and every defect of a recording refused
// with one line naming the file, the element with its id, and the problem.
#include <regex>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "recording/commonroad_reader.h"
#include "recording_files.h"
#include "synthetic_recording.h"

namespace mg {
namespace {

using test::lane_changer;
using test::synthetic_recording_xml;

std::string valid_xml(const std::string& version = "2020a") {
  return synthetic_recording_xml({lane_changer(7, 50, 20, -1.75, 1.75, 3.0, 60)}, version);
}

std::string recording_error_of(const std::string& xml) {
  try {
    parse_recording(xml, "rec.xml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CommonRoadReader, ReadsBothVersions) {
  for (const std::string version : {"2018b", "2020a"}) {
    const Recording r = parse_recording(valid_xml(version), "rec.xml");
    EXPECT_EQ(r.version, version);
    EXPECT_EQ(r.benchmark_id, "TEST_Synthetic-1");
    EXPECT_DOUBLE_EQ(r.time_step_s, 0.1);
    ASSERT_EQ(r.lanelets.size(), 3u);
    ASSERT_EQ(r.vehicles.size(), 1u);
    EXPECT_EQ(r.vehicles[0].id, 7);
    EXPECT_EQ(r.vehicles[0].states.size(), 60u);
    EXPECT_EQ(r.vehicles[0].states[59].time_step, 59);
    EXPECT_DOUBLE_EQ(*r.vehicles[0].states[0].speed_mps, 20.0);
    EXPECT_EQ(r.set_valued_states, 0);
  }
}

TEST(CommonRoadReader, ReadsThePublicRecordings) {
  const Recording a = load_recording(test::recording_path("USA_US101-4_1_T-1.xml"));
  EXPECT_EQ(a.version, "2020a");
  EXPECT_EQ(a.vehicles.size(), 22u);
  EXPECT_EQ(a.lanelets.size(), 12u);
  const Recording b = load_recording(test::recording_path("USA_US101-3_3_T-1.xml"));
  EXPECT_EQ(b.version, "2018b");
  EXPECT_EQ(b.vehicles.size(), 12u);
  EXPECT_EQ(b.vehicles[0].states.size(), 32u);  // 3.2 s at 0.1 s
  const Recording c = load_recording(test::recording_path("ZAM_Zip-1_56_T-1.xml"));
  EXPECT_EQ(c.vehicles.size(), 3u);
  EXPECT_EQ(c.lanelets.size(), 5u);
}

TEST(CommonRoadReader, ReadsSetValuedStatesAsTheirCentresAndCountsThem) {
  std::string xml = valid_xml();
  xml = std::regex_replace(xml, std::regex("<position><point><x>50.000000</x><y>-1.750000</y></point></position>"),
                           "<position><rectangle><length>2</length><width>1</width><orientation>0</orientation>"
                           "<center><x>50.5</x><y>-1.5</y></center></rectangle></position>",
                           std::regex_constants::format_first_only);
  xml = std::regex_replace(xml, std::regex("<velocity><exact>20.000000</exact></velocity>"),
                           "<velocity><intervalStart>19</intervalStart><intervalEnd>23</intervalEnd></velocity>",
                           std::regex_constants::format_first_only);
  const Recording r = parse_recording(xml, "rec.xml");
  const RecordedState& s = r.vehicles[0].states[0];
  EXPECT_TRUE(s.set_valued);
  EXPECT_DOUBLE_EQ(s.x_m, 50.5);
  EXPECT_DOUBLE_EQ(s.y_m, -1.5);
  EXPECT_DOUBLE_EQ(*s.speed_mps, 21.0);
  EXPECT_EQ(r.set_valued_states, 1);
}

struct Defect {
  const char* what;
  const char* from;  // regex, first match replaced
  const char* to;
  const char* expected;  // the whole message after "rec.xml: "
  bool every = false;    // replace every match (an element's start and end tags)
};

TEST(CommonRoadReader, RefusesEachDefectWithOneLineNamingTheElement) {
  const Defect defects[] = {
      {"unknown version", "commonRoadVersion=\"2020a\"", "commonRoadVersion=\"2023a\"",
       "commonRoad: unknown CommonRoad version \"2023a\" (this build reads 2018b and 2020a)"},
      {"dangling reference", "<adjacentLeft ref=\"2\"", "<adjacentLeft ref=\"99\"", "lanelet 1: reference to lanelet 99, which does not exist"},
      {"time gap", "<time><exact>5</exact>", "<time><exact>6</exact>", "dynamicObstacle 7/trajectory/state 4: time gap (step 6 after 4)"},
      {"time backwards", "<time><exact>5</exact>", "<time><exact>3</exact>",
       "dynamicObstacle 7/trajectory/state 4: time goes backwards (step 3 after 4)"},
      {"non-finite", "<x>50.000000</x>", "<x>nan</x>",
       "dynamicObstacle 7/initialState/position/point/x: non-finite or out-of-range number \"nan\""},
      {"absurd speed", "<velocity><exact>20.000000</exact>", "<velocity><exact>2000</exact>",
       "dynamicObstacle 7/initialState/velocity/exact: must be in [-150.000000, 150.000000], got 2000"},
      {"not a number", "<x>50.000000</x>", "<x>fifty</x>", "dynamicObstacle 7/initialState/position/point/x: not a number: \"fifty\""},
      {"missing position", "<position><point><x>50.000000</x><y>-1.750000</y></point></position>", "",
       "dynamicObstacle 7/initialState: missing <position>"},
      {"lanelet as position", "<position><point><x>50.000000</x><y>-1.750000</y></point></position>",
       "<position><lanelet ref=\"1\"/></position>",
       "dynamicObstacle 7/initialState/position: a position must be a point, rectangle, circle or polygon (a lanelet reference is not supported)"},
      {"interval time", "<time><exact>0</exact></time>", "<time><intervalStart>0</intervalStart><intervalEnd>1</intervalEnd></time>",
       "dynamicObstacle 7/initialState/time: a time must be exact (an interval of times is not supported)"},
      {"version mix", "dynamicObstacle", "obstacle", "obstacle: a <obstacle> element in a version 2020a file", true},
      {"wrong root", "<(/?)commonRoad\\b", "<$1scenario", "commonRoad: root element is <scenario>, not <commonRoad>", true},
      {"duplicate lanelet", "<lanelet id=\"3\">", "<lanelet id=\"2\">", "lanelet 2: duplicate lanelet id"},
      {"short bound", "<leftBound><point><x>0</x><y>0.000000</y></point><point><x>200.000000</x><y>0.000000</y></point></leftBound>",
       "<leftBound><point><x>0</x><y>0</y></point></leftBound>", "lanelet 1/leftBound: a bound needs at least 2 points, got 1"},
      {"zero time step", "timeStepSize=\"0.1\"", "timeStepSize=\"0\"", "commonRoad/@timeStepSize: must be in [0.001000, 10.000000], got 0"},
      {"absurd length", "<length>4.5</length>", "<length>400</length>",
       "dynamicObstacle 7/shape/rectangle/length: must be in [0.100000, 30.000000], got 400"},
  };
  for (const Defect& d : defects) {
    const std::string xml = std::regex_replace(valid_xml(), std::regex(d.from), d.to,
                                               d.every ? std::regex_constants::format_default : std::regex_constants::format_first_only);
    ASSERT_NE(xml, valid_xml()) << d.what << ": the mutation did not apply";
    EXPECT_EQ(recording_error_of(xml), std::string("rec.xml: ") + d.expected) << d.what;
  }
}

TEST(CommonRoadReader, RefusesTruncatedRecordings) {
  const std::string xml = valid_xml();
  for (const double cut : {0.1, 0.5, 0.9}) {
    const std::string e = recording_error_of(xml.substr(0, static_cast<std::size_t>(xml.size() * cut)));
    EXPECT_NE(e.find("malformed XML"), std::string::npos) << cut << ": " << e;
  }
}

}  // namespace
}  // namespace mg
