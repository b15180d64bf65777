#include "audit/audit_report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "audit/audit_html.h"
#include "audit/audit_plots.h"
#include "core/atomic_file.h"
#include "core/observed_trace_json.h"
#include "report/report_json.h"
#include "report/report_markdown.h"
#include "report/svg_plot.h"

namespace mg {
namespace {

std::string num(double v, int decimals = 2) { return format_number(v, decimals); }

const RuleResult* rule(const CheckResult& r, const std::string& id) {
  for (const RuleResult& x : r.rules) {
    if (x.rule_id == id) return &x;
  }
  return nullptr;
}

// The most negative margin among the rules that failed, else the RSS margins.
std::string smallest_margins(const CheckResult& r) {
  std::string out;
  for (const char* id : {"rss_longitudinal", "rss_lateral"}) {
    const RuleResult* x = rule(r, id);
    if (x == nullptr) continue;
    // An infinite margin: no pair of vehicles came near enough to be judged.
    const std::string margin = std::isfinite(x->min_margin) ? num(x->min_margin) + " " + x->unit : "no pair near enough to judge";
    out += std::string(out.empty() ? "" : ", ") + id + " " + margin;
  }
  for (const RuleResult& x : r.rules) {
    if (!x.holds && x.rule_id != "rss_longitudinal" && x.rule_id != "rss_lateral") out += ", " + x.rule_id + " " + num(x.min_margin) + " " + x.unit;
  }
  return out;
}

std::string lane_name(const RoadLayout& road, int lane) {
  if (lane == kRampLane) return "the ramp (" + road.ramp.name() + ")";
  return "main lane " + std::to_string(lane) + " (" + road.main_lanes.at(static_cast<std::size_t>(lane)).name() + ")";
}

std::string side_lane_text(const MergeAudit& m) {
  if (m.merge.change.from_lane == kRampLane) return "the ramp, ending at X = " + num(m.merge.trace.road.side_lane_end_x_m, 1) + " m";
  return "a lane that does not end (a cut-in): its end is put beyond the recording, X = " + num(m.merge.trace.road.side_lane_end_x_m, 1) + " m";
}

nlohmann::json sensitivity_json(const SensitivitySweep& s) {
  nlohmann::json pts = nlohmann::json::array();
  for (const SensitivityPoint& p : s.points) {
    pts.push_back({{"response_time_s", p.response_time_s}, {"brake_scale", p.brake_scale}, {"holds", p.holds}, {"liable", party_name(p.liable_id)}});
  }
  return {{"flips", s.flips}, {"summary", s.summary}, {"points", pts}};
}

nlohmann::json road_json(const RoadLayout& road) {
  const RoadShape& sh = road.reference.shape();
  nlohmann::json mains = nlohmann::json::array();
  for (const Lane& l : road.main_lanes) mains.push_back(l.name());
  return {{"found_by", road.found_by}, {"main_lanes", mains}, {"ramp", road.ramp.name()},
          {"ramp_side", road.ramp_side == RampSide::kRight ? "right" : "left"}, {"ramp_end_s_m", road.ramp_end_s_m},
          {"lane_width_m", road.lane_width_m}, {"reference_length_m", sh.length_m},
          {"max_offset_from_chord_m", sh.max_offset_from_chord_m}, {"heading_change_rad", sh.heading_change_rad},
          {"max_abs_curvature_per_m", sh.max_abs_curvature_per_m}};
}

std::string road_shape_text(const RoadLayout& road) {
  const RoadShape& sh = road.reference.shape();
  return "reference line " + num(sh.length_m, 1) + " m long; it deviates from a straight line by up to " + num(sh.max_offset_from_chord_m) +
         " m, turns by " + num(sh.heading_change_rad, 3) + " rad, largest curvature " + num(sh.max_abs_curvature_per_m, 4) + " 1/m";
}

}  // namespace

std::string merge_dir_name(const RecordingAudit& a, std::size_t i) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%02zu-vehicle-%d", i + 1, a.merges[i].merge.change.vehicle_id);
  return buf;
}

nlohmann::json merge_audit_json(const RecordingAudit& a, std::size_t i) {
  const MergeAudit& m = a.merges[i];
  nlohmann::json who = nlohmann::json::array();
  for (std::size_t k = 0; k < m.merge.recording_ids.size(); ++k) {
    who.push_back({{"trace_id", m.merge.trace.vehicles[k].id}, {"commonroad_id", m.merge.recording_ids[k]}});
  }
  nlohmann::json j = {{"recording", a.source}, {"profile", a.profile.name}, {"kind", to_string(m.merge.change.kind)},
                      {"vehicle", m.merge.change.vehicle_id}, {"from_lane", lane_name(*a.road, m.merge.change.from_lane)},
                      {"to_lane", lane_name(*a.road, m.merge.change.to_lane)}, {"time_s", m.merge.change.time_step * a.recording->time_step_s},
                      {"window_s", {m.merge.first_step * a.recording->time_step_s, m.merge.last_step * a.recording->time_step_s}},
                      {"side_lane", side_lane_text(m)}, {"vehicles", who}, {"left_out", m.merge.left_out}, {"notes", m.merge.notes},
                      {"verdict", m.result.holds ? "holds" : "violated"}, {"liable", m.liable_name()},
                      {"why", m.result.liability_detail}, {"smallest_margins", smallest_margins(m.result)},
                      {"report_dir", merge_dir_name(a, i)}};
  if (m.sensitivity) j["sensitivity"] = sensitivity_json(*m.sensitivity);
  return j;
}

nlohmann::json audit_index_json(const RecordingAudit& a) {
  nlohmann::json merges = nlohmann::json::array();
  for (std::size_t i = 0; i < a.merges.size(); ++i) merges.push_back(merge_audit_json(a, i));
  return {{"format", "mergeguard-audit-index"}, {"version", 1}, {"recording", a.source},
          {"benchmark_id", a.recording->benchmark_id}, {"commonroad_version", a.recording->version},
          {"time_step_s", a.recording->time_step_s}, {"vehicles", a.recording->vehicles.size()},
          {"set_valued_states", a.recording->set_valued_states}, {"road", road_json(*a.road)},
          {"profile", audit_profile_to_json(a.profile)}, {"verdict", a.holds() ? "holds" : "violated"}, {"merges", merges}};
}

std::string merge_audit_markdown(const RecordingAudit& a, std::size_t i) {
  const MergeAudit& m = a.merges[i];
  const nlohmann::json j = merge_audit_json(a, i);
  std::string md = "# Audit: " + m.merge.trace.name + "\n\n";
  md += "**Verdict: " + std::string(m.result.holds ? "holds" : "violated") + "**, liable: **" + m.liable_name() + "**\n\n";
  if (!m.result.liability_detail.empty()) md += "Why: " + m.result.liability_detail + "\n\n";
  md += "- Recording: `" + a.source + "` (" + a.recording->benchmark_id + ", CommonRoad " + a.recording->version + ")\n";
  md += "- Profile: " + a.profile.name + " (response time " + num(a.profile.rss.response_time_s) + " s; limits by vehicle class, docs/audit.md)\n";
  md += "- Merge: " + to_string(m.merge.change.kind) + ", vehicle " + std::to_string(m.merge.change.vehicle_id) + " from " +
        j["from_lane"].get<std::string>() + " into " + j["to_lane"].get<std::string>() + ", in the new lane from t = " +
        num(j["time_s"].get<double>(), 1) + " s\n";
  md += "- Window judged: t = " + num(j["window_s"][0].get<double>(), 1) + " to " + num(j["window_s"][1].get<double>(), 1) + " s\n";
  md += "- Side lane: " + side_lane_text(m) + "\n";
  md += "- Road: " + road_shape_text(*a.road) + "\n";
  md += "- Smallest margins: " + smallest_margins(m.result) + "\n";
  md += "- Ego = CommonRoad obstacle " + std::to_string(m.merge.recording_ids[0]) + "; the other vehicles keep their CommonRoad ids";
  for (std::size_t k = 1; k < m.merge.recording_ids.size(); ++k) {
    if (m.merge.trace.vehicles[k].id != m.merge.recording_ids[k]) md += " (trace id " + std::to_string(m.merge.trace.vehicles[k].id) + " = obstacle " + std::to_string(m.merge.recording_ids[k]) + ")";
  }
  md += "\n";
  for (const std::string& s : m.merge.left_out) md += "- Left out: " + s + "\n";
  for (const std::string& s : m.merge.notes) md += "- Note: " + s + "\n";
  if (m.sensitivity) md += "- Sensitivity: " + m.sensitivity->summary + "\n";
  md += "\n![road](road.svg)\n\n![curvilinear frame](frenet.svg)\n\nFull liability report (every rule): [report.md](report.md), [report.html](report.html), [report.json](report.json); "
        "the judged trace: [trace.json](trace.json) (`mergeguard check-trace trace.json` gives the same verdict)\n";
  return md;
}

std::string audit_index_markdown(const RecordingAudit& a) {
  std::string md = "# Audit of " + a.recording->benchmark_id + "\n\n";
  md += "Recording `" + a.source + "` (CommonRoad " + a.recording->version + ", " + std::to_string(a.recording->vehicles.size()) +
        " vehicles). Profile: " + a.profile.name + ". Road: ramp " + a.road->ramp.name() + " found by " + a.road->found_by + "; " +
        road_shape_text(*a.road) + ".\n\n";
  md += "Overall: **" + std::string(a.holds() ? "every merge holds" : "violated") + "**, " + std::to_string(a.merges.size()) + (a.merges.size() == 1 ? " merge" : " merges") + " found.\n\n";
  md += "| # | vehicle | kind | t [s] | verdict | liable | smallest margins | sensitivity | report |\n|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < a.merges.size(); ++i) {
    const MergeAudit& m = a.merges[i];
    md += "| " + std::to_string(i + 1) + " | " + std::to_string(m.merge.change.vehicle_id) + " | " + to_string(m.merge.change.kind) + " | " +
          num(m.merge.change.time_step * a.recording->time_step_s, 1) + " | " + (m.result.holds ? "holds" : "violated") + " | " + m.liable_name() +
          " | " + smallest_margins(m.result) + " | " + (m.sensitivity ? m.sensitivity->summary : std::string("-")) + " | [" +
          merge_dir_name(a, i) + "](" + merge_dir_name(a, i) + "/audit.md) |\n";
  }
  return md;
}

void write_audit_reports(const std::string& dir, const RecordingAudit& a) {
  for (std::size_t i = 0; i < a.merges.size(); ++i) {
    const std::string sub = dir + "/" + merge_dir_name(a, i);
    std::filesystem::create_directories(sub);
    write_check_reports(sub, a.merges[i].result);
    write_files_atomic({{sub + "/audit.json", merge_audit_json(a, i).dump(2) + "\n"},
                        {sub + "/audit.md", merge_audit_markdown(a, i)},
                        {sub + "/audit.html", merge_audit_html(a, i)},
                        {sub + "/road.svg", road_shape_svg(a, a.merges[i])},
                        {sub + "/frenet.svg", curvilinear_svg(a.merges[i])},
                        {sub + "/trace.json", observed_trace_to_json(a.merges[i].merge.trace).dump() + "\n"}});
  }
  write_files_atomic({{dir + "/index.json", audit_index_json(a).dump(2) + "\n"},
                      {dir + "/index.md", audit_index_markdown(a)},
                      {dir + "/index.html", audit_index_html(a)}});
}

}  // namespace mg
