// Auditing a recording (docs/audit.md): every merge found becomes an observable trace
// (merge_trace.h), judged by check_observed exactly as `check-trace` judges a trace. A merge
// whose decision, or the gap it was decided for, was not observed, or whose blame falls on a
// danger already under way at the first judged instant, is undetermined (censoring.h); a join
// that is not a highway on-ramp is not judged. For every judged merge: the compliance frontier
// (compliance_frontier.h) and the verdict's sensitivity to the profile's response time and
// braking limits.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "audit/audit_profile.h"
#include "audit/compliance_frontier.h"
#include "audit/merge_trace.h"
#include "recording/commonroad_recording.h"
#include "recording/road_layout.h"
#include "rules/check.h"

namespace mg {

enum class AuditVerdict { kHolds, kViolated, kUndetermined, kNotJudged };
std::string to_string(AuditVerdict v);  // "holds", "violated", "undetermined", "not judged"

// Why a merge is undetermined, and what the recording did judge of it.
struct Censoring {
  std::string reason;                         // one line
  std::vector<std::string> missing;           // what was not recorded
  std::vector<std::string> judged_on_record;  // the rules that need no more than was recorded
};

// One point of the sensitivity sweep.
struct SensitivityPoint {
  double response_time_s = 0.0;
  double brake_scale = 1.0;
  bool holds = true;
  Party liable_id = Party::nobody();
};

struct SensitivitySweep {
  std::vector<SensitivityPoint> points;
  bool flips = false;  // the verdict is not the same at every point: not certain
  std::string summary; // one line for the index
};

struct MergeAudit {
  MergeTrace merge;
  AuditVerdict verdict = AuditVerdict::kHolds;
  CheckResult result;                           // the rules' judgement (also of an undetermined merge)
  std::optional<Censoring> censoring;           // kUndetermined
  std::string not_judged_reason;                // kNotJudged
  std::optional<ComplianceFrontier> frontier;   // judged merges
  std::optional<SensitivitySweep> sensitivity;  // judged merges
  bool judged() const { return verdict == AuditVerdict::kHolds || verdict == AuditVerdict::kViolated; }
  std::string liable_name() const;              // "none", "ego (vehicle 389)", "vehicle 375" ...
  std::string recording_name(int trace_id) const;  // "vehicle 375" for a trace vehicle id
};

struct AuditOptions {
  std::optional<int> only_vehicle;  // --vehicle
  bool all_lane_joins = false;      // --all-lane-joins: judge joins that are not highway on-ramps
  bool frontier = true;             // compute each judged merge's frontier and sweep
};

// What the reports say of a road on which find_road_layout found no ramp.
inline constexpr std::string_view kNoLaneJoinText = "no lane joins or runs beside another";

struct RecordingAudit {
  std::string source;
  const Recording* recording = nullptr;
  const RoadLayout* road = nullptr;  // nullptr: no lane joins or runs beside another
  AuditProfile profile;
  std::vector<LaneChange> changes;  // every one found, audited or not
  std::vector<MergeAudit> merges;
  int count(AuditVerdict v) const;
  bool holds() const { return count(AuditVerdict::kViolated) == 0; }
  // "nothing to audit": no moving vehicle, no lane joining or beside another, or no lane change
  // found.
  std::string nothing_to_audit() const;
};

RecordingAudit audit_recording(const Recording& r, const RoadLayout& road, const AuditProfile& p, const AuditOptions& o = {});
// The audit of a recording whose road has no lane joining or beside another (find_road_layout
// found none): nothing to audit.
RecordingAudit audit_recording_without_lane_join(const Recording& r, const AuditProfile& p);
// One lane change of a recording's view, as audit_recording audits it.
MergeAudit audit_merge(const RecordingView& v, const LaneChange& c, const AuditProfile& p, const AuditOptions& o);

// Judges the trace again with every (response time, brake scale) of the profile's ranges.
SensitivitySweep sweep_sensitivity(const ObservedTrace& trace, const SensitivityRanges& ranges);

// The trace with another response time and braking limits (b_min and b_max times brake_scale,
// capped at kMaxBrakeMps2): how the frontier, the sweep and the calibration re-judge a merge.
ObservedTrace with_profile_variation(const ObservedTrace& t, double response_time_s, double brake_scale);

}  // namespace mg
