// mergeguard audit INPUT... [--report DIR] [--json] [--params FILE] [--vehicle ID]
// [--all-lane-joins] [--calibrate SHARE]: audit CommonRoad recordings (2018b or 2020a;
// docs/audit.md): find their merges, judge each by the rules as check-trace judges a trace, give
// each judged merge its compliance frontier, and report. One recording: exit 0 when no judged
// merge is violated (undetermined merges alone are no violation), 1 when one is, 2 for bad input
// (one line naming the file, the element and the problem; nothing is written). Several
// recordings or a directory: one index over all of them, a recording that cannot be read listed
// with its error and skipped; the exit code adds 4 when some input was skipped.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "audit/audit_profile.h"
#include "audit/audit_report.h"
#include "audit/calibration.h"
#include "audit/dataset_index.h"
#include "audit/recording_audit.h"
#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_path.h"
#include "recording/commonroad_reader.h"
#include "recording/road_layout.h"
#include "report/report_markdown.h"

namespace mg::cli {
namespace {

namespace fs = std::filesystem;

inline constexpr int kExitSomeInputSkipped = 4;  // added to 0 or 1: some recording could not be read

struct AuditArgs {
  std::vector<std::string> inputs;
  std::string params_path, report_dir;
  bool json = false;
  std::optional<int> vehicle;
  bool all_lane_joins = false;
  std::optional<double> calibrate;
};

std::string road_line(const RecordingAudit& a) {
  if (a.road == nullptr) return std::string(kNoLaneJoinText);
  const RoadLayout& r = *a.road;
  return "ramp " + r.ramp.name() + ", " + std::to_string(r.main_lanes.size()) + (r.main_lanes.size() == 1 ? " main lane (" : " main lanes (") + r.found_by +
         "); " + (r.highway_on_ramp ? "a highway on-ramp (" : "not a highway on-ramp (") + r.on_ramp_basis + ")";
}

void print_summary(const RecordingAudit& a, const std::string& report_dir) {
  std::cout << "recording: " << a.recording->benchmark_id << " (CommonRoad " << a.recording->version << ", "
            << a.recording->vehicles.size() << " vehicles)\n"
            << "road:      " << road_line(a) << "\n"
            << "profile:   " << a.profile.name << "\n";
  if (!a.nothing_to_audit().empty()) std::cout << "note:      " << a.nothing_to_audit() << "\n";
  std::cout << "merges:    " << counts_text(a) << "\n";
  for (const MergeAudit& m : a.merges) {
    std::cout << "  vehicle " << m.merge.change.vehicle_id << " " << to_string(m.merge.change.kind) << " at t = "
              << format_number(m.merge.change.time_step * a.recording->time_step_s, 1) << " s: " << to_string(m.verdict);
    if (m.verdict == AuditVerdict::kHolds || m.verdict == AuditVerdict::kViolated) std::cout << ", liable " << m.liable_name();
    std::cout << "\n    " << merge_row_frontier(m) << "\n";
    if (m.sensitivity) std::cout << "    sensitivity: " << m.sensitivity->summary << "\n";
  }
  std::cout << "verdict:   " << recording_verdict(a) << "\n";
  if (!report_dir.empty()) std::cout << "report:    " << report_dir << "/index.{json,md,html}\n";
}

// The recordings named: files as given, directories as their *.xml files in name order.
std::vector<std::string> expand_inputs(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  for (const std::string& in : inputs) {
    std::error_code ec;
    if (!fs::is_directory(in, ec)) {
      files.push_back(in);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& e : fs::directory_iterator(in, ec)) {
      if (e.path().extension() == ".xml") found.push_back(e.path().string());
    }
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

AuditOptions options_of(const AuditArgs& a) { return {a.vehicle, a.all_lane_joins, true}; }

// A road without a lane join has nothing to audit (docs/audit.md "Nothing to audit").
RecordingAudit audit_of(const Recording& r, const std::optional<RoadLayout>& road, const AuditProfile& p, const AuditOptions& o) {
  return road ? audit_recording(r, *road, p, o) : audit_recording_without_lane_join(r, p);
}

int run_single(const AuditArgs& args, const AuditProfile& profile) {
  const std::string& path = args.inputs.front();
  const Recording recording = load_recording(path);
  const std::optional<RoadLayout> road = find_road_layout(recording);
  if (args.vehicle && std::none_of(recording.vehicles.begin(), recording.vehicles.end(), [&](const RecordedVehicle& v) { return v.id == *args.vehicle; })) {
    throw InputError(path, "--vehicle", "no dynamic obstacle " + std::to_string(*args.vehicle) + " in the recording");
  }
  if (!args.report_dir.empty()) prepare_output_dir("--report", args.report_dir);
  const RecordingAudit a = audit_of(recording, road, profile, options_of(args));
  if (!args.report_dir.empty()) write_audit_reports(args.report_dir, a);
  if (args.json) {
    std::cout << audit_index_json(a).dump(2) << "\n";
  } else {
    print_summary(a, args.report_dir);
  }
  return a.holds() ? kExitOk : kExitViolation;
}

// "02-ZAM_Zip-1_56_T-1": the directory of the i-th recording (0-based) of a dataset.
std::string recording_dir_name(std::size_t i, const std::string& path) {
  const std::string stem = fs::path(path).stem().string();
  std::string safe;
  for (const char ch : stem.substr(0, 80)) safe += std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_' || ch == '.' ? ch : '_';
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02zu-", i + 1);
  return buf + safe;
}

// Audits every recording in turn (one in memory at a time), writing its reports when `dir` is
// set; `each` sees every audit before its recording is dropped.
template <typename Each>
DatasetIndex audit_all(const std::vector<std::string>& files, const AuditProfile& profile, const AuditOptions& o, const std::string& dir, Each each) {
  DatasetIndex d;
  d.profile = profile;
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::cerr << "[" << i + 1 << "/" << files.size() << "] " << files[i] << ": ";
    try {
      const Recording recording = load_recording(files[i]);
      const std::optional<RoadLayout> road = find_road_layout(recording);
      const RecordingAudit a = audit_of(recording, road, profile, o);
      const std::string sub = recording_dir_name(i, files[i]);
      if (!dir.empty()) {
        fs::create_directories(dir + "/" + sub);
        write_audit_reports(dir + "/" + sub, a);
      }
      add_recording(d, a, files[i], sub);
      each(a);
      std::cerr << counts_text(a) << "\n";
    } catch (const InputError& e) {
      std::cerr << "unreadable, skipped\nmergeguard audit: " << e.what() << "\n";
      add_unreadable(d, files[i], e.what());
    }
  }
  return d;
}

// --calibrate: every lane change's verdict on the calibration grid (one recording in memory at
// a time), the proposal from them, then the audit under the proposal, with each merge's verdict
// under the profile calibrated from.
DatasetIndex calibrate(const std::vector<std::string>& files, const AuditProfile& base, const AuditArgs& args) {
  std::vector<std::vector<AuditVerdict>> verdicts;
  std::cerr << "calibration, pass 1 of 2: each merge's verdict on the grid of profiles\n";
  AuditOptions first = options_of(args);
  first.frontier = false;
  const DatasetIndex before = audit_all(files, base, first, "", [&](const RecordingAudit& a) {
    if (a.road == nullptr) return;
    const RecordingView view = view_recording(*a.recording, *a.road, base);
    for (const MergeAudit& m : a.merges) verdicts.push_back(calibration_verdicts(view, m.merge.change, base, first));
  });
  const CalibrationChoice c = choose_calibration(verdicts, *args.calibrate, base);
  AuditProfile proposed = calibrated_profile(base, c.response_time_s, c.brake_scale);
  proposed.name = "calibrated from " + base.name + " to " + format_number(100.0 * *args.calibrate, 0) + " % holding";
  const std::string profile_file = args.report_dir + "/calibrated_profile.json";
  write_files_atomic({{profile_file, audit_profile_to_json(proposed).dump(2) + "\n"}});
  std::cerr << "calibration: " << c.text << "\ncalibration, pass 2 of 2: the audit under the proposed profile (" << profile_file << ")\n";
  DatasetIndex d = audit_all(files, proposed, options_of(args), args.report_dir, [](const RecordingAudit&) {});
  for (std::size_t i = 0; i < d.merges.size() && i < before.merges.size(); ++i) d.merges[i].before = before.merges[i].verdict;
  const int judged = d.count(AuditVerdict::kHolds) + d.count(AuditVerdict::kViolated);
  d.calibration_text = c.text + ". The audit under it: " + std::to_string(d.count(AuditVerdict::kHolds)) + " of " + std::to_string(judged) +
                       " judged merges hold; " + std::to_string(d.count(AuditVerdict::kViolated)) +
                       " still violated (listed first below, each with its verdict under " + base.name + "). Written as a --params file: calibrated_profile.json";
  d.calibrated_profile_file = "calibrated_profile.json";
  return d;
}

int run_dataset(const AuditArgs& args, const AuditProfile& profile) {
  const std::vector<std::string> files = expand_inputs(args.inputs);
  if (files.empty()) throw UsageError("no recording (*.xml) in the inputs given");
  if (!args.report_dir.empty()) prepare_output_dir("--report", args.report_dir);
  const DatasetIndex d = args.calibrate ? calibrate(files, profile, args) : audit_all(files, profile, options_of(args), args.report_dir, [](const RecordingAudit&) {});
  if (!args.report_dir.empty()) write_dataset_index(args.report_dir, d);
  if (args.json) {
    std::cout << dataset_index_json(d).dump(2) << "\n";
  } else {
    std::cout << "recordings: " << d.recordings.size() << " (" << d.unreadable() << " unreadable)\n"
              << "profile:    " << d.profile.name << "\n"
              << "merges:     " << dataset_counts_text(d) << "\n";
    if (d.calibration_text) std::cout << "calibration: " << *d.calibration_text << "\n";
    for (const std::size_t i : worst_first(d)) {
      const MergeRow& m = d.merges[i];
      std::cout << "  " << m.recording << " vehicle " << m.vehicle << " " << m.kind << " at t = " << format_number(m.time_s, 1) << " s: " << to_string(m.verdict)
                << (m.verdict == AuditVerdict::kViolated ? ", liable " + m.liable : std::string()) << "\n    " << m.words << "\n";
    }
    std::cout << "verdict:    " << (d.count(AuditVerdict::kViolated) > 0 ? "violated" : "no judged merge violated") << "\n";
    if (!args.report_dir.empty()) std::cout << "report:     " << args.report_dir << "/index.{json,md,html}\n";
  }
  return (d.count(AuditVerdict::kViolated) > 0 ? kExitViolation : kExitOk) + (d.unreadable() > 0 ? kExitSomeInputSkipped : 0);
}

int run_audit(const std::vector<std::string>& raw) {
  CLI::App app("Audit the merges of CommonRoad recordings by the rules and assign liability", "mergeguard audit");
  AuditArgs args;
  app.add_option("recordings", args.inputs, "CommonRoad XML files (2018b or 2020a) or directories of them")->required();
  app.add_option("--report", args.report_dir, "write index.{json,md,html} and one report directory per merge (per recording for several) into DIR");
  app.add_flag("--json", args.json, "print the index JSON on stdout");
  app.add_option("--params", args.params_path, "audit profile JSON (docs/audit.md); default: the built-in profile");
  app.add_option("--vehicle", args.vehicle, "audit only this CommonRoad obstacle's merges");
  app.add_flag("--all-lane-joins", args.all_lane_joins, "judge every lane join as a ramp merge, also where the map is not a highway on-ramp");
  app.add_option("--calibrate", args.calibrate, "propose the profile under which this share of the judged merges holds (writes DIR/calibrated_profile.json)")
      ->check(CLI::Range(0.01, 1.0));
  if (!parse_args(app, raw)) return kExitOk;
  if (args.calibrate && args.report_dir.empty()) throw UsageError("--calibrate needs --report DIR (the proposed profile is written there)");
  const AuditProfile profile = args.params_path.empty() ? default_audit_profile() : load_audit_profile(args.params_path);
  std::error_code ec;
  const bool dataset = args.inputs.size() > 1 || fs::is_directory(args.inputs.front(), ec) || args.calibrate;
  return dataset ? run_dataset(args, profile) : run_single(args, profile);
}

}  // namespace

Command audit_command() {
  return {"audit", "audit RECORDING.xml|DIR... [--report DIR] [--json] [--params FILE] [--vehicle ID] [--all-lane-joins] [--calibrate SHARE]", run_audit};
}

}  // namespace mg::cli
