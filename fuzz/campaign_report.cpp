#include "fuzz/campaign_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "core/atomic_file.h"
#include "fuzz/corpus_case.h"
#include "fuzz/rule_coverage.h"
#include "fuzz/scenario_spec.h"
#include "report/report_table.h"
#include "report/svg_plot.h"

namespace mg::fuzz {
namespace {

using nlohmann::json;

std::string fixed(double x, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << x;
  return out.str();
}

std::string bin_label(std::size_t b) {
  const auto& e = kMarginBinEdges;
  if (b == 0) return "< " + fixed(e.front(), 1);
  if (b == e.size()) return ">= " + fixed(e.back(), 1);
  return "[" + fixed(e[b - 1], 1) + ", " + fixed(e[b], 1) + ")";
}

std::string relative_to(const std::string& path, const std::string& dir) {
  std::error_code ec;
  const auto rel = std::filesystem::relative(std::filesystem::absolute(path), std::filesystem::absolute(dir), ec);
  return ec ? path : rel.string();
}

ReportTable count_table(const std::string& what, const std::map<std::string, std::uint64_t>& counts) {
  ReportTable t{{what, "failures"}, {}};
  for (const auto& [k, n] : counts) t.rows.push_back({k, std::to_string(n)});
  return t;
}

ReportTable signature_table(const CampaignResult& r, const std::string& dir, const std::map<std::string, std::string>& reports) {
  ReportTable t{{"signature", "scenarios", "first run", "case", "vehicles", "shrink steps", "liability report"}, {}};
  for (const auto& [sig, rec] : r.signatures) {
    std::string case_cell = rec.known_before ? "already in corpus" : "not written";
    if (!rec.case_path.empty()) case_cell = "[" + std::filesystem::path(rec.case_path).filename().string() + "](" + relative_to(rec.case_path, dir) + ")";
    const auto report = reports.find(rec.case_path);
    const std::string report_cell = report == reports.end() ? "-" : "[report](" + report->second + ")";
    t.rows.push_back({sig.key(), std::to_string(rec.count),
                      std::to_string(rec.first_run) + (rec.first_run_guided ? " (guided)" : ""), case_cell,
                      rec.case_path.empty() ? "-" : std::to_string(rec.case_vehicles),
                      rec.case_path.empty() ? "-" : std::to_string(rec.shrink_steps) + (rec.shrink_minimal ? "" : " (budget)"),
                      report_cell});
  }
  return t;
}

// Statistics are over the scenarios that exercised the rule; a rule that never applied says so
// instead of showing a sentinel.
ReportTable margin_table(const CampaignOptions& o, const CampaignResult& r) {
  ReportTable t{{"rule", "unit", "scenarios", "exercised", "violated", "min", "mean"}, {}};
  for (std::size_t b = 0; b < kMarginBinEdges.size() + 1; ++b) t.header.push_back(bin_label(b));
  for (const RuleCoverage& c : rule_coverage(o.planner, r)) {
    const auto it = r.margins.find(c.rule);
    if (it == r.margins.end()) continue;
    const MarginStats& m = it->second;
    std::vector<std::string> row{c.rule, m.unit, std::to_string(m.scenarios), std::to_string(m.exercised),
                                 std::to_string(m.violated)};
    if (m.exercised == 0) {
      const std::string why = c.applicable ? "not exercised" : "not applicable";
      row.insert(row.end(), {why, why});
    } else {
      row.insert(row.end(), {fixed(m.min, 3), fixed(*m.mean(), 3)});
    }
    for (auto n : m.bins) row.push_back(std::to_string(n));
    t.rows.push_back(row);
  }
  return t;
}

// One rule's margin histogram as a small inline SVG bar chart (bins below zero, the violations,
// in red); heights on a square-root scale so that a handful of near misses stays visible beside
// thousands of comfortable margins.
std::string histogram_svg(const std::string& rule, const MarginStats& m) {
  constexpr int kBarW = 34, kGap = 4, kH = 70, kTop = 14, kLabelH = 26;
  const int bins = static_cast<int>(m.bins.size());
  const int width = bins * (kBarW + kGap);
  std::uint64_t peak = 1;
  for (auto n : m.bins) peak = std::max(peak, n);
  // Bins 0 .. zero_bin-1 lie below a margin of 0 (kMarginBinEdges has an edge at 0).
  const int zero_bin = static_cast<int>(std::find(kMarginBinEdges.begin(), kMarginBinEdges.end(), 0.0) - kMarginBinEdges.begin()) + 1;
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << kTop + kH + kLabelH
      << "\" role=\"img\" aria-label=\"margin histogram of " << html_escape(rule) << "\">";
  for (int b = 0; b < bins; ++b) {
    const auto n = m.bins[static_cast<std::size_t>(b)];
    const int h = n == 0 ? 0 : std::max(1, static_cast<int>(std::lround(kH * std::sqrt(static_cast<double>(n) / static_cast<double>(peak)))));
    const int x = b * (kBarW + kGap);
    const bool violated = b < zero_bin;
    out << "<rect x=\"" << x << "\" y=\"" << kTop + kH - h << "\" width=\"" << kBarW << "\" height=\"" << h << "\" fill=\""
        << (violated ? "#d9480f" : "#1f77b4") << "\"><title>" << html_escape(bin_label(static_cast<std::size_t>(b))) << ": " << n
        << "</title></rect>";
    out << "<text x=\"" << x + kBarW / 2 << "\" y=\"" << kTop + kH - h - 2 << "\" font-size=\"9\" text-anchor=\"middle\">" << n << "</text>";
    out << "<text x=\"" << x + kBarW / 2 << "\" y=\"" << kTop + kH + 11 << "\" font-size=\"8\" text-anchor=\"middle\">"
        << html_escape(bin_label(static_cast<std::size_t>(b))) << "</text>";
  }
  out << "<text x=\"0\" y=\"" << kTop + kH + 23 << "\" font-size=\"9\">" << html_escape(m.unit) << "</text></svg>";
  return out.str();
}

// The margin histograms of the exercised rules, for the HTML report.
std::string histogram_section(const CampaignOptions& o, const CampaignResult& r) {
  std::string out = "<h2>Margin histograms (exercised scenarios; red: violations)</h2>\n<div class=\"hists\">\n";
  bool any = false;
  for (const RuleCoverage& c : rule_coverage(o.planner, r)) {
    const auto it = r.margins.find(c.rule);
    if (it == r.margins.end() || it->second.exercised == 0) continue;
    any = true;
    out += "<figure><figcaption>" + html_escape(c.rule) + " (" + std::to_string(it->second.exercised) + " of " +
           std::to_string(it->second.scenarios) + ")</figcaption>" + histogram_svg(c.rule, it->second) + "</figure>\n";
  }
  return any ? out + "</div>\n" : "";
}

// Failing scenarios and distinct signatures against elapsed time (the campaign's progress
// samples): whether findings were still coming when the campaign stopped.
std::string findings_over_time(const CampaignResult& r) {
  if (r.timeline.size() < 2) return "";
  svg::Plot plot = svg::frame("", "elapsed [s]", "count", 560, 260);
  plot.legend = svg::LegendCorner::kTopLeft;
  svg::Series failing{"failing scenarios", {}, {}, "#d9480f", "", 1.6};
  svg::Series signatures{"signatures", {}, {}, "#1f77b4", "6 3", 1.6};
  for (const CampaignProgress& p : r.timeline) {
    failing.x.push_back(p.elapsed_s);
    failing.y.push_back(static_cast<double>(p.failing_scenarios));
    signatures.x.push_back(p.elapsed_s);
    signatures.y.push_back(static_cast<double>(p.signatures));
  }
  plot.series = {failing, signatures};
  plot.y_range = svg::Range{0.0, std::max(1.0, std::max(failing.y.back(), signatures.y.back()) * 1.1)};
  return "<h2>Findings over time</h2>\n" + svg::render(plot) + "\n";
}

// The rule and RSS parameters the campaign's generated scenarios are judged with: the defaults,
// except those the generator draws per scenario (rho_m, rho_c and T, given as their ranges).
// Corpus cases are judged with the parameters they carry.
json judged_with_json() {
  const auto per_scenario = [](const RealRange& r) { return json{{"per_scenario", {r.lo, r.hi}}}; };
  json rules = rule_params_to_json(RuleParams{});
  rules["merge_duration_s"] = per_scenario(range::kMergeDuration);
  rules["comm_threshold_s"] = per_scenario(range::kCommThreshold);
  json rss = rss_params_to_json(RssParams{});
  rss["response_time_s"] = per_scenario(range::kResponseTime);
  return {{"rules", rules}, {"rss", rss}};
}

ReportTable judged_with_table() {
  ReportTable t{{"parameter", "value"}, {}};
  const json judged = judged_with_json();
  for (const auto& [group, values] : judged.items())
    for (const auto& [name, value] : values.items()) t.rows.push_back({group + "." + name, value.dump()});
  return t;
}

struct Section {
  std::string title;
  ReportTable table;
};

std::string headline(const CampaignOptions& o, const CampaignResult& r) {
  std::ostringstream out;
  out << r.scenarios << " scenarios with planner " << o.planner << " in " << fixed(r.seconds, 1) << " s ("
      << fixed(r.scenarios_per_second(), 1) << " scenarios/s, " << o.jobs << " jobs, seed " << o.seed << ", shard "
      << o.shard_index << "/" << o.shard_count << (r.interrupted ? ", interrupted" : "") << "): "
      << r.failing_scenarios << " failing scenarios, " << r.signatures.size() << " signatures, " << r.new_cases.size()
      << " new corpus cases";
  std::size_t minimal = 0;
  for (const auto& [sig, rec] : r.signatures) minimal += !rec.case_path.empty() && rec.shrink_minimal ? 1 : 0;
  if (!r.new_cases.empty())
    out << " (" << minimal << " of them local minima" << (minimal < r.new_cases.size() ? "; the rest were cut by the shrink budget" : "") << ")";
  out << ".";
  if (o.search == SearchMode::kGuided) {
    std::size_t found = 0;
    for (const auto& [sig, rec] : r.signatures) found += rec.first_run_guided ? 1 : 0;
    const double share = r.scenarios > 0 ? 100.0 * static_cast<double>(r.guided_runs) / static_cast<double>(r.scenarios) : 0.0;
    out << " Guided search: " << r.guided_runs << " runs (" << fixed(share, 1) << " %) perturbed low-margin scenarios; "
        << r.guided_failing_scenarios << " of them failed, and " << found << " of the " << r.signatures.size()
        << " signatures were first seen in a guided run.";
  }
  if (!r.planner_process.is_null()) out << " " << planner_process_text(r) << ".";
  if (r.first_failure_run)
    out << " First failing run: " << *r.first_failure_run << " (first failure after " << fixed(r.first_failure_s.value_or(0.0), 2) << " s).";
  return out.str();
}

}  // namespace

std::string planner_process_text(const CampaignResult& r) {
  if (!r.planner_process.is_object()) return "";
  const nlohmann::json hello = r.planner_process.value("hello", nlohmann::json::object());
  std::ostringstream out;
  out << "Planner process: " << hello.value("name", std::string("(unnamed)")) << " version "
      << hello.value("version", std::string("(none)")) << " (from its hello); its stderr logs:";
  for (const nlohmann::json& log : r.planner_process.value("logs", nlohmann::json::array()))
    if (log.is_string()) out << " " << log.get<std::string>();
  return out.str();
}

// The warning a reader must see first: rules that could apply but no scenario exercised, so the
// campaign says nothing about them; and the rules that cannot apply to this planner.
std::vector<std::string> coverage_warnings(const CampaignOptions& o, const CampaignResult& r) {
  std::vector<std::string> out;
  if (r.scenarios == 0) return out;
  const auto never = rules_never_exercised(o.planner, r);
  if (!never.empty()) {
    std::string line = "Warning: " + std::to_string(never.size()) + " rule(s) that can apply to " + o.planner +
                       " were exercised in none of the " + std::to_string(r.scenarios) +
                       " scenarios, so this campaign says nothing about them:";
    for (const auto& rule : never) line += " " + rule;
    out.push_back(line + ".");
  }
  std::map<std::string, std::vector<std::string>> by_reason;
  for (const auto& [rule, why] : rules_not_applicable(o.planner)) by_reason[why].push_back(rule);
  for (const auto& [why, rules] : by_reason) {
    std::string line = "Not applicable to " + o.planner + ":";
    for (const auto& rule : rules) line += " " + rule;
    out.push_back(line + " (" + why + ").");
  }
  return out;
}

json campaign_summary_json(const CampaignOptions& o, const CampaignResult& r) {
  json signatures = json::array();
  for (const auto& [sig, rec] : r.signatures) {
    signatures.push_back({{"signature", sig.key()},
                          {"planner", sig.planner},
                          {"property", sig.property},
                          {"rule", sig.rule},
                          {"party", sig.party},
                          {"scenarios", rec.count},
                          {"first_run", rec.first_run},
                          {"first_run_guided", rec.first_run_guided},
                          {"known_before", rec.known_before},
                          {"case", rec.case_path.empty() ? json(nullptr) : json(rec.case_path)},
                          {"case_vehicles", rec.case_vehicles},
                          {"shrink_steps", rec.shrink_steps},
                          {"shrink_attempts", rec.shrink_attempts},
                          {"shrink_minimal", rec.shrink_minimal}});
  }
  json margins = json::object();
  for (const RuleCoverage& c : rule_coverage(o.planner, r)) {
    const auto it = r.margins.find(c.rule);
    if (it == r.margins.end()) continue;
    const MarginStats& m = it->second;
    json bins = json::array();
    for (std::size_t b = 0; b < m.bins.size(); ++b) bins.push_back({{"range", bin_label(b)}, {"count", m.bins[b]}});
    const bool stats = m.exercised > 0;
    margins[c.rule] = {{"unit", m.unit},
                       {"scenarios", m.scenarios},
                       {"exercised", m.exercised},
                       {"applicable", c.applicable},
                       {"violated", m.violated},
                       {"min", stats ? json(m.min) : json(nullptr)},
                       {"mean", stats ? json(*m.mean()) : json(nullptr)},
                       {"sum_micro", m.sum_micro},
                       {"bins", bins}};
    if (!c.applicable) margins[c.rule]["not_applicable_why"] = c.not_applicable_why;
  }
  json not_applicable = json::object();
  for (const auto& [rule, why] : rules_not_applicable(o.planner)) not_applicable[rule] = why;
  json summary = {{"planner", o.planner},
          {"seed", o.seed},
          {"runs", o.runs ? json(*o.runs) : json(nullptr)},
          {"time_budget_s", o.time_s ? json(*o.time_s) : json(nullptr)},
          {"jobs", o.jobs},
          {"shard", std::to_string(o.shard_index) + "/" + std::to_string(o.shard_count)},
          {"corpus", o.corpus_dir},
          {"families", o.gen.targeted_families ? "mixed" : "uniform"},
          {"search", to_string(o.search)},
          {"stop_on_failure", o.stop_on_failure},
          {"stop_on_new_failure", o.stop_on_new_failure},
          {"interrupted", r.interrupted},
          {"signal", r.interrupted && !r.stop_signal.empty() ? json(r.stop_signal) : json(nullptr)},
          {"scenarios", r.scenarios},
          {"seconds", r.seconds},
          {"scenarios_per_second", r.scenarios_per_second()},
          {"violations", r.failing_scenarios},
          {"guided_runs", r.guided_runs},
          {"guided_violations", r.guided_failing_scenarios},
          {"first_failure_run", r.first_failure_run ? json(*r.first_failure_run) : json(nullptr)},
          {"first_failure_s", r.first_failure_s ? json(*r.first_failure_s) : json(nullptr)},
          {"first_new_failure_run", r.first_new_failure_run ? json(*r.first_new_failure_run) : json(nullptr)},
          {"first_new_failure_s", r.first_new_failure_s ? json(*r.first_new_failure_s) : json(nullptr)},
          {"property_failures", r.property_failures},
          {"signatures", r.signatures.size()},
          {"new_cases", r.new_cases},
          {"new_cases_local_minima", std::count_if(r.signatures.begin(), r.signatures.end(), [](const auto& kv) {
             return !kv.second.case_path.empty() && kv.second.shrink_minimal;
           })},
          {"failures_by_property", r.by_property},
          {"failures_by_rule", r.by_rule},
          {"failures_by_party", r.by_party},
          {"signature_list", signatures},
          {"margins", margins},
          {"rules_never_exercised", r.scenarios > 0 ? rules_never_exercised(o.planner, r) : std::vector<std::string>{}},
          {"rules_not_applicable", not_applicable},
          {"judged_with", judged_with_json()},
          {"date", utc_now_iso8601()}};
  if (!r.planner_process.is_null()) summary["planner_process"] = r.planner_process;
  return summary;
}

void write_campaign_report(const std::string& dir, const CampaignOptions& o, const CampaignResult& r,
                           const std::map<std::string, std::string>& reports) {
  const std::vector<Section> sections = {
      {"Failure signatures and corpus cases", signature_table(r, dir, reports)},
      {"Failures by property", count_table("property", r.by_property)},
      {"Failures by rule", count_table("rule", r.by_rule)},
      {"Failures by liable party", count_table("party", r.by_party)},
      {"Rule coverage and robustness margins (statistics over the scenarios that exercised the rule; bins in "
       "the rule's unit)",
       margin_table(o, r)},
      {"Judged with (generated scenarios; corpus cases carry their own parameters)", judged_with_table()},
  };
  std::string md = "# mergeguard fuzzing campaign\n\n" + headline(o, r) + "\n";
  const std::vector<std::string> warnings = coverage_warnings(o, r);
  for (const std::string& w : warnings) md += "\n> " + w + "\n";
  std::string page = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>mergeguard fuzzing campaign</title>"
                     "<style>body{font-family:sans-serif}table{border-collapse:collapse}td,th{border:1px solid #999;"
                     "padding:2px 6px;text-align:left}.warning{background:#fde2c8;border-left:6px solid #d9480f;padding:6px 10px}"
                     ".note{color:#555}.hists{display:flex;flex-wrap:wrap;gap:8px}figure{margin:4px;border:1px solid #ddd;"
                     "padding:4px}figcaption{font-size:12px}</style></head><body>\n<h1>mergeguard fuzzing campaign</h1>\n<p>" +
                     html_escape(headline(o, r)) + "</p>\n";
  const std::string over_time = findings_over_time(r);
  for (const std::string& w : warnings)
    page += std::string(w.rfind("Warning", 0) == 0 ? "<p class=\"warning\">" : "<p class=\"note\">") + html_escape(w) + "</p>\n";
  for (const Section& s : sections) {
    md += "\n## " + s.title + "\n\n" + (s.table.rows.empty() ? "None.\n" : table_markdown(s.table));
    page += "<h2>" + html_escape(s.title) + "</h2>\n" + (s.table.rows.empty() ? "<p>None.</p>\n" : table_html(s.table));
  }
  page += over_time + histogram_section(o, r);
  page += "</body></html>\n";
  const std::filesystem::path base(dir);
  write_files_atomic({{(base / "report.json").string(), campaign_summary_json(o, r).dump(2) + "\n"},
                      {(base / "report.md").string(), md},
                      {(base / "report.html").string(), page}});
}

}  // namespace mg::fuzz
