// The audit's reports (docs/audit.md "Reports"): for each merge, in
// DIR/<NN>-vehicle-<id>/, the rules' liability report (report.{json,md,html}, written by the same
// code as `check-trace --report`) and the audit's own page (audit.{json,md,html}: the recording,
// the profile, who is who, the frame, how far the road deviates from straight, the verdict with
// its smallest margins and sensitivity, and the plots in the road's own shape and in the
// curvilinear frame), and the merge's observable trace (trace.json, docs/trace_format.md: what
// `check-trace` judges to the same verdict); and DIR/index.{json,md,html} listing every merge.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "audit/recording_audit.h"

namespace mg {

// "03-vehicle-389": the directory of merge i (0-based) under the report directory.
std::string merge_dir_name(const RecordingAudit& a, std::size_t i);

nlohmann::json audit_index_json(const RecordingAudit& a);
// {"found", "judged", "holds", "violated", "undetermined", "not_judged"} and the same in words.
nlohmann::json counts_json(const RecordingAudit& a);
std::string counts_text(const RecordingAudit& a);
// "violated", "every judged merge holds", "nothing judged", "nothing to audit".
std::string recording_verdict(const RecordingAudit& a);
nlohmann::json merge_audit_json(const RecordingAudit& a, std::size_t i);
std::string audit_index_markdown(const RecordingAudit& a);
std::string merge_audit_markdown(const RecordingAudit& a, std::size_t i);
// The index's frontier column: the frontier in words, or why undetermined or not judged.
std::string merge_row_frontier(const MergeAudit& m);

// Writes every file (each atomically) into `dir`, which exists.
void write_audit_reports(const std::string& dir, const RecordingAudit& a);

}  // namespace mg
