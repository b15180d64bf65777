// mergeguard audit RECORDING.xml [--report DIR] [--json] [--params FILE] [--vehicle ID]: audit a
// CommonRoad recording (2018b or 2020a; docs/audit.md): find its merges, judge each by the rules
// as check-trace judges a trace, and report. Exit 0 when every merge holds, 1 when any is
// violated, 2 for bad input (one line naming the file, the element and the problem; nothing is
// written: everything is read and validated before the report directory is touched).
#include <algorithm>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "audit/audit_profile.h"
#include "audit/audit_report.h"
#include "audit/recording_audit.h"
#include "cli/command.h"
#include "core/input_error.h"
#include "core/output_path.h"
#include "recording/commonroad_reader.h"
#include "recording/road_layout.h"
#include "report/report_markdown.h"

namespace mg::cli {
namespace {

void print_summary(const RecordingAudit& a, const std::string& report_dir) {
  std::cout << "recording: " << a.recording->benchmark_id << " (CommonRoad " << a.recording->version << ", "
            << a.recording->vehicles.size() << " vehicles)\n"
            << "road:      ramp " << a.road->ramp.name() << ", " << a.road->main_lanes.size() << (a.road->main_lanes.size() == 1 ? " main lane (" : " main lanes (")
            << a.road->found_by << ")\n"
            << "profile:   " << a.profile.name << "\n"
            << "merges:    " << a.merges.size() << "\n";
  for (const MergeAudit& m : a.merges) {
    std::cout << "  vehicle " << m.merge.change.vehicle_id << " " << to_string(m.merge.change.kind) << " at t = "
              << format_number(m.merge.change.time_step * a.recording->time_step_s, 1) << " s: "
              << (m.result.holds ? "holds" : "violated") << ", liable " << m.liable_name() << "\n";
    if (m.sensitivity) std::cout << "    sensitivity: " << m.sensitivity->summary << "\n";
  }
  std::cout << "verdict:   " << (a.holds() ? "every merge holds" : "violated") << "\n";
  if (!report_dir.empty()) std::cout << "report:    " << report_dir << "/index.{json,md,html}\n";
}

int run_audit(const std::vector<std::string>& args) {
  CLI::App app("Audit the merges of a CommonRoad recording by the rules and assign liability", "mergeguard audit");
  std::string path, params_path, report_dir;
  bool json = false;
  std::optional<int> vehicle;
  app.add_option("recording", path, "CommonRoad XML file (2018b or 2020a)")->required();
  app.add_option("--report", report_dir, "write index.{json,md,html} and one report directory per merge into DIR");
  app.add_flag("--json", json, "print the index JSON on stdout");
  app.add_option("--params", params_path, "audit profile JSON (docs/audit.md); default: the built-in profile");
  app.add_option("--vehicle", vehicle, "audit only this CommonRoad obstacle's merges");
  if (!parse_args(app, args)) return kExitOk;
  const AuditProfile profile = params_path.empty() ? default_audit_profile() : load_audit_profile(params_path);
  const Recording recording = load_recording(path);
  const RoadLayout road = build_road_layout(recording);
  if (vehicle && std::none_of(recording.vehicles.begin(), recording.vehicles.end(), [&](const RecordedVehicle& v) { return v.id == *vehicle; })) {
    throw InputError(path, "--vehicle", "no dynamic obstacle " + std::to_string(*vehicle) + " in the recording");
  }
  if (!report_dir.empty()) prepare_output_dir("--report", report_dir);
  const RecordingAudit a = audit_recording(recording, road, profile, vehicle);
  if (!report_dir.empty()) write_audit_reports(report_dir, a);
  if (json) {
    std::cout << audit_index_json(a).dump(2) << "\n";
  } else {
    print_summary(a, report_dir);
  }
  return a.holds() ? kExitOk : kExitViolation;
}

}  // namespace

Command audit_command() {
  return {"audit", "audit RECORDING.xml [--report DIR] [--json] [--params FILE] [--vehicle ID]", run_audit};
}

}  // namespace mg::cli
