// The audit's reports (src/audit/audit_report.h, audit_html.h, audit_plots.h): the index lists
// every merge with its verdict, liable party, margins and sensitivity; each merge's page names the
// recording, the profile and who is who, and embeds both plots; the HTML is self-contained.
#include <gtest/gtest.h>

#include "audit/audit_html.h"
#include "audit/audit_plots.h"
#include "audit/audit_report.h"
#include "recording/commonroad_reader.h"
#include "recording/road_layout.h"
#include "tests/recording/recording_files.h"

namespace mg {
namespace {

struct Zipper {
  Zipper() : recording(load_recording(test::recording_path("ZAM_Zip-1_56_T-1.xml"))), road(build_road_layout(recording)) {
    audit = audit_recording(recording, road, default_audit_profile());
  }
  Recording recording;
  RoadLayout road;
  RecordingAudit audit;
};

TEST(AuditReport, TheIndexListsEveryMerge) {
  const Zipper z;
  const nlohmann::json j = audit_index_json(z.audit);
  EXPECT_EQ(j["format"], "mergeguard-audit-index");
  ASSERT_EQ(j["merges"].size(), 3u);
  EXPECT_EQ(j["merges"][1]["report_dir"], "02-vehicle-1");
  EXPECT_EQ(j["merges"][1]["liable"], "vehicle 2");
  EXPECT_FALSE(j["merges"][1]["sensitivity"]["flips"].get<bool>());
  EXPECT_EQ(j["merges"][1]["sensitivity"]["points"].size(), 12u);
  EXPECT_EQ(j["road"]["ramp_side"], "left");
  const std::string md = audit_index_markdown(z.audit);
  EXPECT_NE(md.find("| 2 | 1 | ramp merge | 5.7 | violated | vehicle 2 | violated at rho = 1 s; violated even at rho = 0 s (binding: rss_longitudinal"),
            std::string::npos) << md;
  EXPECT_NE(md.find("| 1 | 2 | into the ramp | 2.1 | undetermined | - | undetermined: the merge was already under way"), std::string::npos) << md;
  EXPECT_NE(md.find("merges: 3 found, 2 judged (0 hold, 2 violated), 1 undetermined, 0 not judged"), std::string::npos) << md;
  EXPECT_EQ(j["counts"]["undetermined"], 1);
  EXPECT_EQ(j["merges"][0]["verdict"], "undetermined");
  EXPECT_FALSE(j["merges"][0]["undetermined"]["reason"].get<std::string>().empty());
  EXPECT_TRUE(j["merges"][1]["frontier"]["max_response_time_s"].is_null());
  EXPECT_EQ(j["merges"][1]["frontier"]["binding_rule"], "rss_longitudinal");
  EXPECT_NE(md.find("[03-vehicle-2](03-vehicle-2/audit.md)"), std::string::npos);
}

TEST(AuditReport, AMergesPageSaysWhatItRestsOn) {
  const Zipper z;
  const std::string md = merge_audit_markdown(z.audit, 1);
  EXPECT_NE(md.find("**Verdict: violated**, liable: **vehicle 2**"), std::string::npos) << md;
  EXPECT_NE(md.find("Profile: mergeguard default recorded-traffic profile (v1) (response time 1.00 s"), std::string::npos);
  EXPECT_NE(md.find("from the ramp (lanelets 25-28) into main lane 0 (lanelets 26-27-24)"), std::string::npos);
  EXPECT_NE(md.find("Side lane: the ramp, ending at X = 180.4 m"), std::string::npos);
  EXPECT_NE(md.find("it deviates from a straight line by up to 1.13 m"), std::string::npos);
  EXPECT_NE(md.find("Ego = CommonRoad obstacle 1"), std::string::npos);
  EXPECT_NE(md.find("Sensitivity: 0 of 12 profile variations hold"), std::string::npos);
  EXPECT_NE(md.find("Compliance frontier: violated at rho = 1 s; violated even at rho = 0 s"), std::string::npos) << md;
  EXPECT_NE(md.find("![compliance frontier](frontier.svg)"), std::string::npos);
}

TEST(AuditReport, HtmlIsSelfContainedWithBothPlots) {
  const Zipper z;
  const std::string html = merge_audit_html(z.audit, 1);
  EXPECT_EQ(html.find("http"), html.find("http://www.w3.org/2000/svg"));  // only SVG namespaces
  EXPECT_NE(html.find("The road in its own shape"), std::string::npos);
  EXPECT_NE(html.find("Curvilinear frame"), std::string::npos);
  EXPECT_EQ(html.find("report.md"), std::string::npos);  // the HTML links the HTML and JSON reports
  EXPECT_NE(html.find("<a href=\"report.html\">"), std::string::npos);
  const std::string index = audit_index_html(z.audit);
  EXPECT_NE(index.find("<a href=\"02-vehicle-1/audit.html\">"), std::string::npos);
}

TEST(AuditReport, TheRoadPlotShowsTheRampAndEveryParticipant) {
  const Zipper z;
  const std::string svg = road_shape_svg(z.audit, z.audit.merges[1]);
  EXPECT_NE(svg.find(">ramp<"), std::string::npos);
  EXPECT_NE(svg.find(">ego 1<"), std::string::npos);
  EXPECT_NE(svg.find(">2<"), std::string::npos);
  EXPECT_NE(svg.find(">3<"), std::string::npos);
  const std::string frenet = curvilinear_svg(z.audit.merges[1]);
  EXPECT_NE(frenet.find("side lane ends"), std::string::npos);
}

}  // namespace
}  // namespace mg
