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

nlohmann::json rho_json(const RhoFrontier& f) {
  return {{"max_response_time_s", f.max_response_time_s ? nlohmann::json(*f.max_response_time_s) : nlohmann::json(nullptr)},
          {"holds_throughout", f.holds_throughout}};
}

nlohmann::json frontier_json(const ComplianceFrontier& f) {
  nlohmann::json curve = nlohmann::json::array();
  for (const FrontierCurvePoint& p : f.curve) curve.push_back({{"brake_scale", p.brake_scale}, {"frontier", rho_json(p.rho)}});
  return {{"profile_response_time_s", f.profile_response_time_s}, {"holds_at_profile", f.holds_at_profile},
          {"max_response_time_s", f.rho.max_response_time_s ? nlohmann::json(*f.rho.max_response_time_s) : nlohmann::json(nullptr)},
          {"holds_throughout", f.rho.holds_throughout}, {"resolution_s", kFrontierResolutionS},
          {"needed_brake_min_mps2", f.needed_brake_scale ? nlohmann::json(*f.needed_brake_scale * f.follower_brake_min_mps2) : nlohmann::json(nullptr)},
          {"follower_brake_min_mps2", f.follower_brake_min_mps2}, {"binding_rule", f.binding_rule}, {"binding_ref", f.binding_ref},
          {"curve", curve}, {"words", f.words}};
}

nlohmann::json road_json(const RoadLayout& road) {
  const RoadShape& sh = road.reference.shape();
  nlohmann::json mains = nlohmann::json::array();
  for (const Lane& l : road.main_lanes) mains.push_back(l.name());
  return {{"found_by", road.found_by}, {"main_lanes", mains}, {"ramp", road.ramp.name()},
          {"ramp_side", road.ramp_side == RampSide::kRight ? "right" : "left"}, {"ramp_end_s_m", road.ramp_end_s_m},
          {"lane_width_m", road.lane_width_m}, {"reference_length_m", sh.length_m},
          {"max_offset_from_chord_m", sh.max_offset_from_chord_m}, {"heading_change_rad", sh.heading_change_rad},
          {"max_abs_curvature_per_m", sh.max_abs_curvature_per_m}, {"highway_on_ramp", road.highway_on_ramp},
          {"on_ramp_basis", road.on_ramp_basis}};
}

std::string road_shape_text(const RoadLayout& road) {
  const RoadShape& sh = road.reference.shape();
  return "reference line " + num(sh.length_m, 1) + " m long; it deviates from a straight line by up to " + num(sh.max_offset_from_chord_m) +
         " m, turns by " + num(sh.heading_change_rad, 3) + " rad, largest curvature " + num(sh.max_abs_curvature_per_m, 4) + " 1/m";
}

std::string road_text(const RecordingAudit& a) {
  if (a.road == nullptr) return std::string(kNoLaneJoinText);
  return "ramp " + a.road->ramp.name() + " found by " + a.road->found_by + ", " +
         (a.road->highway_on_ramp ? "a highway on-ramp (" : "not a highway on-ramp (") + a.road->on_ramp_basis + "); " + road_shape_text(*a.road);
}

}  // namespace

nlohmann::json counts_json(const RecordingAudit& a) {
  return {{"found", a.merges.size()}, {"judged", a.count(AuditVerdict::kHolds) + a.count(AuditVerdict::kViolated)},
          {"holds", a.count(AuditVerdict::kHolds)}, {"violated", a.count(AuditVerdict::kViolated)},
          {"undetermined", a.count(AuditVerdict::kUndetermined)}, {"not_judged", a.count(AuditVerdict::kNotJudged)}};
}

std::string recording_verdict(const RecordingAudit& a) {
  if (a.count(AuditVerdict::kViolated) > 0) return "violated";
  if (a.merges.empty()) return "nothing to audit";
  if (a.count(AuditVerdict::kHolds) == 0) return "nothing judged";
  return "every judged merge holds";
}

std::string counts_text(const RecordingAudit& a) {
  const auto n = [&](AuditVerdict v) { return std::to_string(a.count(v)); };
  return std::to_string(a.merges.size()) + " found, " + std::to_string(a.count(AuditVerdict::kHolds) + a.count(AuditVerdict::kViolated)) +
         " judged (" + n(AuditVerdict::kHolds) + " hold, " + n(AuditVerdict::kViolated) + " violated), " + n(AuditVerdict::kUndetermined) +
         " undetermined, " + n(AuditVerdict::kNotJudged) + " not judged (not a highway on-ramp)";
}

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
                      {"verdict", to_string(m.verdict)}, {"liable", m.liable_name()},
                      {"why", m.verdict == AuditVerdict::kViolated ? m.result.liability_detail : std::string()},
                      {"smallest_margins", m.judged() ? smallest_margins(m.result) : std::string()},
                      {"report_dir", merge_dir_name(a, i)}, {"entering_vehicles", m.merge.entering_ids},
                      {"window_start", m.merge.window_start.why}};
  if (m.censoring) {
    j["undetermined"] = {{"reason", m.censoring->reason}, {"missing", m.censoring->missing}, {"judged_on_record", m.censoring->judged_on_record}};
  }
  if (m.verdict == AuditVerdict::kNotJudged) j["not_judged"] = m.not_judged_reason;
  if (m.frontier) j["frontier"] = frontier_json(*m.frontier);
  if (m.sensitivity) j["sensitivity"] = sensitivity_json(*m.sensitivity);
  return j;
}

nlohmann::json audit_index_json(const RecordingAudit& a) {
  nlohmann::json merges = nlohmann::json::array();
  for (std::size_t i = 0; i < a.merges.size(); ++i) merges.push_back(merge_audit_json(a, i));
  return {{"format", "mergeguard-audit-index"}, {"version", 1}, {"recording", a.source},
          {"benchmark_id", a.recording->benchmark_id}, {"commonroad_version", a.recording->version},
          {"time_step_s", a.recording->time_step_s}, {"vehicles", a.recording->vehicles.size()},
          {"set_valued_states", a.recording->set_valued_states}, {"road", a.road ? road_json(*a.road) : nlohmann::json()},
          {"profile", audit_profile_to_json(a.profile)}, {"verdict", recording_verdict(a)}, {"counts", counts_json(a)},
          {"nothing_to_audit", a.nothing_to_audit()}, {"merges", merges}};
}

namespace {

// The verdict in one line, with what decides it: the liable party, why undetermined or not judged.
std::string verdict_line(const MergeAudit& m) {
  switch (m.verdict) {
    case AuditVerdict::kHolds: return "**Verdict: holds**, liable: **none**";
    case AuditVerdict::kViolated: return "**Verdict: violated**, liable: **" + m.liable_name() + "**";
    case AuditVerdict::kUndetermined: return "**Verdict: undetermined**: " + m.censoring->reason;
    case AuditVerdict::kNotJudged: return "**Not judged**: " + m.not_judged_reason;
  }
  return "";
}

}  // namespace

std::string merge_audit_markdown(const RecordingAudit& a, std::size_t i) {
  const MergeAudit& m = a.merges[i];
  const nlohmann::json j = merge_audit_json(a, i);
  std::string md = "# Audit: " + m.merge.trace.name + "\n\n" + verdict_line(m) + "\n\n";
  if (m.verdict == AuditVerdict::kViolated && !m.result.liability_detail.empty()) md += "Why: " + m.result.liability_detail + "\n\n";
  if (m.frontier) md += "Compliance frontier: " + m.frontier->words + "\n\n";
  md += "- Recording: `" + a.source + "` (" + a.recording->benchmark_id + ", CommonRoad " + a.recording->version + ")\n";
  md += "- Profile: " + a.profile.name + " (response time " + num(a.profile.rss.response_time_s) + " s; limits by vehicle class, docs/audit.md)\n";
  md += "- Merge: " + to_string(m.merge.change.kind) + ", vehicle " + std::to_string(m.merge.change.vehicle_id) + " from " +
        j["from_lane"].get<std::string>() + " into " + j["to_lane"].get<std::string>() + ", in the new lane from t = " +
        num(j["time_s"].get<double>(), 1) + " s\n";
  md += "- Window judged: t = " + num(j["window_s"][0].get<double>(), 1) + " to " + num(j["window_s"][1].get<double>(), 1) + " s (its start: " +
        m.merge.window_start.why + ")\n";
  md += "- Side lane: " + side_lane_text(m) + "\n";
  md += "- Road: " + road_shape_text(*a.road) + "; the join: " + (a.road->highway_on_ramp ? "a highway on-ramp (" : "not a highway on-ramp (") +
        a.road->on_ramp_basis + ")\n";
  if (m.judged()) md += "- Smallest margins: " + smallest_margins(m.result) + "\n";
  if (m.censoring) {
    for (const std::string& s : m.censoring->missing) md += "- Not recorded: " + s + "\n";
    for (const std::string& s : m.censoring->judged_on_record) md += "- Judged on what was recorded: " + s + "\n";
  }
  md += "- Ego = CommonRoad obstacle " + std::to_string(m.merge.recording_ids[0]) + "; the other vehicles keep their CommonRoad ids";
  for (std::size_t k = 1; k < m.merge.recording_ids.size(); ++k) {
    if (m.merge.trace.vehicles[k].id != m.merge.recording_ids[k]) md += " (trace id " + std::to_string(m.merge.trace.vehicles[k].id) + " = obstacle " + std::to_string(m.merge.recording_ids[k]) + ")";
  }
  md += "\n";
  for (const std::string& s : m.merge.left_out) md += "- Left out: " + s + "\n";
  for (const std::string& s : m.merge.notes) md += "- Note: " + s + "\n";
  if (m.sensitivity) md += "- Sensitivity: " + m.sensitivity->summary + "\n";
  md += "\n![road](road.svg)\n\n![curvilinear frame](frenet.svg)\n\n";
  if (m.frontier) md += "![compliance frontier](frontier.svg)\n\n";
  md += m.verdict == AuditVerdict::kNotJudged ? std::string("The judged trace would be: [trace.json](trace.json)\n")
                                              : "Full liability report (every rule): [report.md](report.md), [report.html](report.html), [report.json](report.json); "
                                                "the judged trace: [trace.json](trace.json) (`mergeguard check-trace trace.json` gives the rules' verdict)\n";
  return md;
}

std::string merge_row_frontier(const MergeAudit& m) {
  if (m.frontier) return m.frontier->words;
  if (m.censoring) return "undetermined: " + m.censoring->reason;
  if (m.verdict == AuditVerdict::kNotJudged) return m.not_judged_reason;
  return "-";
}

std::string audit_index_markdown(const RecordingAudit& a) {
  std::string md = "# Audit of " + a.recording->benchmark_id + "\n\n";
  md += "Recording `" + a.source + "` (CommonRoad " + a.recording->version + ", " + std::to_string(a.recording->vehicles.size()) +
        " vehicles). Profile: " + a.profile.name + ". Road: " + road_text(a) + ".\n\n";
  if (!a.nothing_to_audit().empty()) md += a.nothing_to_audit() + ".\n\n";
  md += "Overall: **" + recording_verdict(a) + "**; merges: " + counts_text(a) + ".\n\n";
  if (a.merges.empty()) return md;
  md += "| # | vehicle | kind | t [s] | verdict | liable | compliance frontier | sensitivity | report |\n|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < a.merges.size(); ++i) {
    const MergeAudit& m = a.merges[i];
    md += "| " + std::to_string(i + 1) + " | " + std::to_string(m.merge.change.vehicle_id) + " | " + to_string(m.merge.change.kind) + " | " +
          num(m.merge.change.time_step * a.recording->time_step_s, 1) + " | " + to_string(m.verdict) + " | " + m.liable_name() + " | " +
          merge_row_frontier(m) + " | " + (m.sensitivity ? m.sensitivity->summary : std::string("-")) + " | [" + merge_dir_name(a, i) + "](" +
          merge_dir_name(a, i) + "/audit.md) |\n";
  }
  return md;
}

void write_audit_reports(const std::string& dir, const RecordingAudit& a) {
  for (std::size_t i = 0; i < a.merges.size(); ++i) {
    const std::string sub = dir + "/" + merge_dir_name(a, i);
    std::filesystem::create_directories(sub);
    if (a.merges[i].verdict != AuditVerdict::kNotJudged) write_check_reports(sub, a.merges[i].result);
    if (a.merges[i].frontier) write_files_atomic({{sub + "/frontier.svg", frontier_svg(a.merges[i])}});
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
