// report.json validates against the structure documented in docs/rules.md (the test reads the
// table there); report.md and report.html put the verdict first; report.html has no URL.
#include "report/report_json.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "report/report_html.h"
#include "report/report_markdown.h"
#include "tests/rules/trace_builder.h"

namespace mg {
namespace {

namespace fs = std::filesystem;

struct FieldSpec {
  std::string path;  // e.g. "rules[].min_margin"
  std::string type;
};

std::vector<FieldSpec> documented_fields() {
  std::ifstream in(std::string(MG_SOURCE_DIR) + "/docs/rules.md");
  std::string line;
  bool in_section = false;
  std::vector<FieldSpec> out;
  const std::regex row(R"(^\| `([a-z_\[\]\.]+)` \| ([a-z-]+) \|)");
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) in_section = line == "## report.json";
    std::smatch m;
    if (in_section && std::regex_search(line, m, row)) out.push_back({m[1], m[2]});
  }
  return out;
}

bool has_type(const nlohmann::json& v, const std::string& type) {
  if (type == "string") return v.is_string();
  if (type == "number") return v.is_number();
  if (type == "integer") return v.is_number_integer();
  if (type == "boolean") return v.is_boolean();
  if (type == "array") return v.is_array();
  if (type == "object") return v.is_object();
  if (type == "number-or-null") return v.is_number() || v.is_null();
  ADD_FAILURE() << "undocumented type " << type;
  return false;
}

// Checks every value reached by `path` (segments split at '.', "x[]" iterates array x).
void expect_field(const nlohmann::json& doc, const FieldSpec& f) {
  std::vector<const nlohmann::json*> values{&doc};
  std::stringstream ss(f.path);
  std::string seg;
  while (std::getline(ss, seg, '.')) {
    const bool each = seg.size() > 2 && seg.substr(seg.size() - 2) == "[]";
    const std::string key = each ? seg.substr(0, seg.size() - 2) : seg;
    std::vector<const nlohmann::json*> next;
    for (const nlohmann::json* v : values) {
      ASSERT_TRUE(v->is_object() && v->contains(key)) << "missing " << f.path;
      const nlohmann::json& child = v->at(key);
      if (each) {
        ASSERT_TRUE(child.is_array()) << f.path;
        for (const auto& e : child) next.push_back(&e);
      } else {
        next.push_back(&child);
      }
    }
    values = std::move(next);
  }
  for (const nlohmann::json* v : values) EXPECT_TRUE(has_type(*v, f.type)) << f.path << " = " << v->dump();
}

// A violated check: vehicle 1 runs into vehicle 2 without braking (see liability_test).
std::pair<Scenario, CheckResult> violated_check() {
  Scenario s = test::base_scenario();
  s.name = "report_fixture";
  s.vehicles = {test::vehicle(1, -20.0, 30.0), test::vehicle(2, 10.0, 20.0)};
  Trace t = test::constant_accel_trace(s, 4.0);
  t.events.push_back(test::message_event(0.5, MessageType::kRequest, 0, 2, CoopCase::kEgoBehind, 60, 30, 22));
  return {s, check_trace(s, std::move(t))};
}

TEST(Report, JsonFollowsTheStructureDocumentedInDocsRulesMd) {
  const auto fields = documented_fields();
  ASSERT_GE(fields.size(), 30u) << "docs/rules.md report.json table not found";
  const auto [s, r] = violated_check();
  const nlohmann::json j = report_json(r);
  for (const FieldSpec& f : fields) expect_field(j, f);
  // Every top-level key of the report is documented.
  for (const auto& [key, value] : j.items()) {
    bool documented = false;
    for (const FieldSpec& f : fields) documented = documented || f.path == key;
    EXPECT_TRUE(documented) << key;
  }
  EXPECT_EQ(j.at("verdict"), "violated");
  EXPECT_EQ(j.at("liable"), "vehicle 1");
}

TEST(Report, HtmlIsSelfContainedAndStartsWithTheVerdict) {
  const auto [s, r] = violated_check();
  const std::string html = report_html(r);
  for (const char* external : {"http://", "https://", "src=", "href=", "@import", "<link", "<script"}) {
    EXPECT_EQ(html.find(external), std::string::npos) << external;
  }
  // url(...) may only name a fragment of the page itself (SVG clip paths: url(#clip0_0)).
  EXPECT_FALSE(std::regex_search(html, std::regex(R"(url\((?!#))"))) << "url( to something outside the page";
  EXPECT_NE(html.find("<svg"), std::string::npos);
  const std::string head = html.substr(0, 800);
  EXPECT_NE(head.find("Verdict: VIOLATED"), std::string::npos);
  EXPECT_NE(head.find("liable: vehicle 1"), std::string::npos);
}

TEST(Report, MarkdownStartsWithVerdictAndListsEachViolation) {
  const auto [s, r] = violated_check();
  const std::string md = report_markdown(r);
  EXPECT_LT(md.find("**Verdict: VIOLATED**"), 200u);
  for (const RuleResult& rule : r.rules) {
    if (rule.holds) continue;
    EXPECT_NE(md.find("| " + rule.rule_id + " | " + rule.paper_ref), std::string::npos) << rule.rule_id;
  }
}

TEST(Report, WriterPutsTheThreeFilesIntoTheDirectory) {
  const auto [s, r] = violated_check();
  const fs::path dir = fs::temp_directory_path() / ("mg_report_test_" + std::to_string(::getpid()));
  write_check_reports((dir / "nested").string(), r);
  for (const char* f : {"report.json", "report.md", "report.html"}) EXPECT_TRUE(fs::exists(dir / "nested" / f)) << f;
  std::ifstream in(dir / "nested" / "report.json");
  EXPECT_EQ(nlohmann::json::parse(in), report_json(r));
  fs::remove_all(dir);
}

// Reports stay readable at any size: the largest scene the format allows (64
// vehicles) over a long trace, with thousands of V2V channel events, still gives an HTML page
// under 3 MB.
TEST(Report, HtmlStaysUnderThreeMegabytesForTheLargestScene) {
  Scenario s = test::base_scenario();
  s.road.main_lanes = 4;
  for (int k = 0; k < 64; ++k) {
    MainVehicle v = test::vehicle(k + 1, -300.0 + 40.0 * (k / 4) + 9.0 * (k % 4), 20.0 + (k % 4));
    v.lane = k % 4;
    s.vehicles.push_back(v);
  }
  Trace t = test::constant_accel_trace(s, 120.0);  // 6001 steps: every series is thinned
  for (int e = 0; e < 3000; ++e)
    t.events.push_back(test::message_event(e * 0.04, MessageType::kRefuse, 1, 2, CoopCase::kEgoBehind, 0, 0, 0));
  const CheckResult r = check_trace(s, std::move(t));
  const std::string html = report_html(r);
  EXPECT_LT(html.size(), 3u * 1024u * 1024u);
  EXPECT_NE(html.find("more (report.json lists all)"), std::string::npos);
}

}  // namespace
}  // namespace mg
