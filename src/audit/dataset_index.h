// The index of an audit of many recordings (docs/audit.md "A dataset at once"): per recording
// and overall, the merges found, judged, undetermined and not judged, the verdict shares, the
// distribution of the compliance frontiers, and the worst merges first, each linked to its
// report. It holds one summary row per merge and per recording, never a recording: the audit
// streams through the recordings one at a time.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "audit/audit_profile.h"
#include "audit/recording_audit.h"

namespace mg {

struct MergeRow {
  std::string recording;  // the benchmark id
  std::string link;       // "02-ZAM_Zip-1_56_T-1/01-vehicle-2/audit.md", relative to the index
  int vehicle = 0;
  std::string kind;
  double time_s = 0.0;
  AuditVerdict verdict = AuditVerdict::kHolds;
  std::string liable;
  std::optional<double> frontier_s;  // largest rho that holds (judged merges)
  bool holds_throughout = false;
  std::string words;                 // the frontier in words, or why undetermined / not judged
  std::optional<AuditVerdict> before;  // with --calibrate: the verdict under the profile calibrated from
};

struct RecordingRow {
  std::string path;
  std::string benchmark_id;
  std::string link;   // its own index, relative to the dataset index ("" when unreadable)
  std::string error;  // the one-line error of a recording that could not be read
  nlohmann::json counts;
  std::string verdict;
  std::string note;   // nothing to audit, the join not a highway on-ramp ...
};

struct Calibration;

struct DatasetIndex {
  AuditProfile profile;
  std::vector<RecordingRow> recordings;
  std::vector<MergeRow> merges;
  std::optional<std::string> calibration_text;  // with --calibrate: what was proposed and how verdicts changed
  std::optional<std::string> calibrated_profile_file;
  int count(AuditVerdict v) const;
  int unreadable() const;
};

// The rows of one audited recording whose reports are in `dir` (relative to the index).
void add_recording(DatasetIndex& d, const RecordingAudit& a, const std::string& path, const std::string& dir);
void add_unreadable(DatasetIndex& d, const std::string& path, const std::string& error);

// "5 found, 2 judged (1 hold, 1 violated), 3 undetermined, 0 not judged (not a highway on-ramp)".
std::string dataset_counts_text(const DatasetIndex& d);
// The merges in the order the index lists them: violated first, then by frontier (smallest
// first), then the others.
std::vector<std::size_t> worst_first(const DatasetIndex& d);

nlohmann::json dataset_index_json(const DatasetIndex& d);
std::string dataset_index_markdown(const DatasetIndex& d);
std::string dataset_index_html(const DatasetIndex& d);
// index.{json,md,html} and frontier_histogram.svg into `dir`, which exists.
void write_dataset_index(const std::string& dir, const DatasetIndex& d);

}  // namespace mg
