// Auditing a recording: every merge found becomes an observable trace
// (merge_trace.h), judged by check_observed exactly as `check-trace` judges a trace; for each
// violated merge, the verdict's sensitivity to the profile's response time and braking limits.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "audit/audit_profile.h"
#include "audit/merge_trace.h"
#include "recording/commonroad_recording.h"
#include "recording/road_layout.h"
#include "rules/check.h"

namespace mg {

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
  CheckResult result;
  std::optional<SensitivitySweep> sensitivity;  // for violated merges
  std::string liable_name() const;              // "none", "ego (vehicle 389)", "vehicle 375" ...
};

struct RecordingAudit {
  std::string source;
  const Recording* recording = nullptr;
  const RoadLayout* road = nullptr;
  AuditProfile profile;
  std::vector<LaneChange> changes;  // every one found, audited or not
  std::vector<MergeAudit> merges;
  bool holds() const;
};

// `only_vehicle`: audit only that CommonRoad obstacle's merges (--vehicle).
RecordingAudit audit_recording(const Recording& r, const RoadLayout& road, const AuditProfile& p,
                               std::optional<int> only_vehicle = std::nullopt);

// Judges the trace again with every (response time, brake scale) of the profile's ranges.
SensitivitySweep sweep_sensitivity(const ObservedTrace& trace, const SensitivityRanges& ranges);

}  // namespace mg
