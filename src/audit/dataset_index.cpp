#include "audit/dataset_index.h"

#include <algorithm>
#include <numeric>
#include <regex>

#include "audit/audit_html.h"
#include "audit/audit_plots.h"
#include "audit/audit_report.h"
#include "core/atomic_file.h"
#include "report/report_markdown.h"

namespace mg {
namespace {

// The index's numbers: two decimals unless a column asks for other.
std::string index_number(double v, int decimals = 2) { return format_number(v, decimals); }

std::string share(int n, int of) { return of == 0 ? std::string("-") : index_number(100.0 * n / of, 1) + " %"; }

std::string frontier_cell(const MergeRow& m) {
  if (m.holds_throughout) return ">= 5";
  if (m.frontier_s) return index_number(*m.frontier_s, 2);
  return m.verdict == AuditVerdict::kHolds || m.verdict == AuditVerdict::kViolated ? "none (not even at 0)" : "-";
}

nlohmann::json merge_row_json(const MergeRow& m) {
  nlohmann::json j = {{"recording", m.recording}, {"link", m.link}, {"vehicle", m.vehicle}, {"kind", m.kind}, {"time_s", m.time_s},
                      {"verdict", to_string(m.verdict)}, {"liable", m.liable},
                      {"frontier_max_response_time_s", m.frontier_s ? nlohmann::json(*m.frontier_s) : nlohmann::json(nullptr)},
                      {"frontier_holds_throughout", m.holds_throughout}, {"words", m.words}};
  if (m.before) j["verdict_before_calibration"] = to_string(*m.before);
  return j;
}

std::string histogram(const DatasetIndex& d) {
  std::vector<std::optional<double>> values;
  std::vector<bool> throughout;
  for (const MergeRow& m : d.merges) {
    if (m.verdict != AuditVerdict::kHolds && m.verdict != AuditVerdict::kViolated) continue;
    values.push_back(m.frontier_s);
    throughout.push_back(m.holds_throughout);
  }
  return frontier_histogram_svg(values, throughout);
}

// Quartiles of the frontier values of the judged merges ("holds throughout" counts as 5 s).
std::string frontier_distribution(const DatasetIndex& d) {
  std::vector<double> v;
  int none = 0;
  for (const MergeRow& m : d.merges) {
    if (m.verdict != AuditVerdict::kHolds && m.verdict != AuditVerdict::kViolated) continue;
    if (m.frontier_s) v.push_back(*m.frontier_s);
    else ++none;
  }
  if (v.empty() && none == 0) return "no judged merge";
  std::sort(v.begin(), v.end());
  const auto q = [&](double f) { return v.empty() ? 0.0 : v[static_cast<std::size_t>(f * (v.size() - 1) + 0.5)]; };
  std::string s = std::to_string(v.size() + none) + " judged merges; ";
  if (!v.empty()) s += "largest rho that holds: min " + index_number(v.front()) + " s, median " + index_number(q(0.5)) + " s, max " + index_number(v.back()) + " s";
  if (none > 0) s += std::string(v.empty() ? "" : "; ") + std::to_string(none) + " violated even at rho = 0";
  return s;
}

}  // namespace

int DatasetIndex::count(AuditVerdict v) const {
  return static_cast<int>(std::count_if(merges.begin(), merges.end(), [v](const MergeRow& m) { return m.verdict == v; }));
}

int DatasetIndex::unreadable() const {
  return static_cast<int>(std::count_if(recordings.begin(), recordings.end(), [](const RecordingRow& r) { return !r.error.empty(); }));
}

void add_recording(DatasetIndex& d, const RecordingAudit& a, const std::string& path, const std::string& dir) {
  const std::string prefix = dir.empty() ? "" : dir + "/";
  RecordingRow r{path, a.recording->benchmark_id, prefix + "index.md", "", counts_json(a), recording_verdict(a), a.nothing_to_audit()};
  if (a.road != nullptr && !a.road->highway_on_ramp) r.note += std::string(r.note.empty() ? "" : "; ") + "the join is not a highway on-ramp: " + a.road->on_ramp_basis;
  d.recordings.push_back(r);
  const double dt = a.recording->time_step_s;
  for (std::size_t i = 0; i < a.merges.size(); ++i) {
    const MergeAudit& m = a.merges[i];
    MergeRow row{a.recording->benchmark_id, prefix + merge_dir_name(a, i) + "/audit.md", m.merge.change.vehicle_id, to_string(m.merge.change.kind),
                 m.merge.change.time_step * dt, m.verdict, m.liable_name(), std::nullopt, false, merge_row_frontier(m), std::nullopt};
    if (m.frontier) {
      row.frontier_s = m.frontier->rho.max_response_time_s;
      row.holds_throughout = m.frontier->rho.holds_throughout;
    }
    d.merges.push_back(row);
  }
}

void add_unreadable(DatasetIndex& d, const std::string& path, const std::string& error) {
  d.recordings.push_back({path, "", "", error, nlohmann::json::object(), "unreadable", ""});
}

std::string dataset_counts_text(const DatasetIndex& d) {
  const int judged = d.count(AuditVerdict::kHolds) + d.count(AuditVerdict::kViolated);
  return std::to_string(d.merges.size()) + " found, " + std::to_string(judged) + " judged (" + std::to_string(d.count(AuditVerdict::kHolds)) +
         " hold, " + std::to_string(d.count(AuditVerdict::kViolated)) + " violated), " + std::to_string(d.count(AuditVerdict::kUndetermined)) +
         " undetermined, " + std::to_string(d.count(AuditVerdict::kNotJudged)) + " not judged (not a highway on-ramp)";
}

std::vector<std::size_t> worst_first(const DatasetIndex& d) {
  std::vector<std::size_t> order(d.merges.size());
  std::iota(order.begin(), order.end(), 0);
  const auto rank = [&](const MergeRow& m) {
    const int group = m.verdict == AuditVerdict::kViolated ? 0 : m.verdict == AuditVerdict::kHolds ? 1 : m.verdict == AuditVerdict::kUndetermined ? 2 : 3;
    const double f = m.holds_throughout ? 1e9 : m.frontier_s.value_or(-1.0);
    return std::make_pair(group, f);
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(d.merges[a]) < rank(d.merges[b]); });
  return order;
}

nlohmann::json dataset_index_json(const DatasetIndex& d) {
  nlohmann::json recs = nlohmann::json::array(), merges = nlohmann::json::array();
  for (const RecordingRow& r : d.recordings) {
    nlohmann::json j = {{"path", r.path}, {"benchmark_id", r.benchmark_id}, {"link", r.link}, {"verdict", r.verdict}, {"counts", r.counts}, {"note", r.note}};
    if (!r.error.empty()) j["error"] = r.error;
    recs.push_back(j);
  }
  for (const std::size_t i : worst_first(d)) merges.push_back(merge_row_json(d.merges[i]));
  const int judged = d.count(AuditVerdict::kHolds) + d.count(AuditVerdict::kViolated);
  nlohmann::json j = {{"format", "mergeguard-audit-dataset-index"}, {"version", 1}, {"profile", audit_profile_to_json(d.profile)},
                      {"recordings", recs}, {"unreadable", d.unreadable()},
                      {"counts", {{"found", d.merges.size()}, {"judged", judged}, {"holds", d.count(AuditVerdict::kHolds)},
                                  {"violated", d.count(AuditVerdict::kViolated)}, {"undetermined", d.count(AuditVerdict::kUndetermined)},
                                  {"not_judged", d.count(AuditVerdict::kNotJudged)}}},
                      {"frontier_distribution", frontier_distribution(d)}, {"merges_worst_first", merges}};
  if (d.calibration_text) j["calibration"] = *d.calibration_text;
  if (d.calibrated_profile_file) j["calibrated_profile_file"] = *d.calibrated_profile_file;
  return j;
}

std::string dataset_index_markdown(const DatasetIndex& d) {
  const int judged = d.count(AuditVerdict::kHolds) + d.count(AuditVerdict::kViolated);
  std::string md = "# Audit of " + std::to_string(d.recordings.size()) + " recordings\n\n";
  md += "Profile: " + d.profile.name + " (response time " + index_number(d.profile.rss.response_time_s) + " s; docs/audit.md).\n\n";
  if (d.calibration_text) md += "Calibration: " + *d.calibration_text + "\n\n";
  md += "Overall: merges " + dataset_counts_text(d) + ". Of the judged merges " + share(d.count(AuditVerdict::kHolds), judged) + " hold and " +
        share(d.count(AuditVerdict::kViolated), judged) + " are violated.";
  if (d.unreadable() > 0) md += " **" + std::to_string(d.unreadable()) + " recording(s) could not be read** (listed below).";
  md += "\n\nCompliance frontiers: " + frontier_distribution(d) + ".\n\n![frontier histogram](frontier_histogram.svg)\n\n";
  md += "## Recordings\n\n| recording | verdict | found | judged | holds | violated | undetermined | not judged | note |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const RecordingRow& r : d.recordings) {
    if (!r.error.empty()) {
      md += "| `" + r.path + "` | **unreadable** | - | - | - | - | - | - | " + r.error + " |\n";
      continue;
    }
    const auto c = [&](const char* k) { return std::to_string(r.counts.at(k).get<int>()); };
    md += "| [" + r.benchmark_id + "](" + r.link + ") | " + r.verdict + " | " + c("found") + " | " + c("judged") + " | " + c("holds") + " | " +
          c("violated") + " | " + c("undetermined") + " | " + c("not_judged") + " | " + r.note + " |\n";
  }
  md += "\n## Merges, worst first\n\n| # | recording | vehicle | kind | t [s] | verdict | ";
  md += d.calibration_text ? "before calibration | " : "";
  md += "liable | largest rho that holds [s] | in words | report |\n|---|---|---|---|---|---|" + std::string(d.calibration_text ? "---|" : "") + "---|---|---|---|\n";
  int k = 0;
  for (const std::size_t i : worst_first(d)) {
    const MergeRow& m = d.merges[i];
    md += "| " + std::to_string(++k) + " | " + m.recording + " | " + std::to_string(m.vehicle) + " | " + m.kind + " | " + index_number(m.time_s, 1) + " | " +
          to_string(m.verdict) + " | " + (d.calibration_text ? (m.before ? to_string(*m.before) : std::string("-")) + " | " : std::string()) +
          m.liable + " | " + frontier_cell(m) + " | " + m.words + " | [audit](" + m.link + ") |\n";
  }
  return md;
}

std::string dataset_index_html(const DatasetIndex& d) {
  std::string md = std::regex_replace(dataset_index_markdown(d), std::regex(R"((\]\([^)\s]*)\.md\))"), "$1.html)");
  return audit_page_html("Audit of " + std::to_string(d.recordings.size()) + " recordings", md, {{"frontier_histogram.svg", histogram(d)}});
}

void write_dataset_index(const std::string& dir, const DatasetIndex& d) {
  write_files_atomic({{dir + "/index.json", dataset_index_json(d).dump(2) + "\n"},
                      {dir + "/index.md", dataset_index_markdown(d)},
                      {dir + "/index.html", dataset_index_html(d)},
                      {dir + "/frontier_histogram.svg", histogram(d)}});
}

}  // namespace mg
