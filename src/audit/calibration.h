// Calibrating the audit profile to a dataset (docs/audit.md "Calibration"): the profile under
// which a given share of the judged merges hold, found from each merge's verdicts on
// a grid of response times and braking scales (the audit's own verdict under each), within
// plausible ranges for human drivers: the response time in
// [kMinCalibratedResponseS, kMaxCalibratedResponseS], each class's b_min and b_max scaled and
// kept within its class's range (PlausibleBraking). Of the candidates, the one with the least
// braking beyond the profile's, and at it the longest response time, is proposed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "audit/audit_profile.h"
#include "audit/compliance_frontier.h"
#include "audit/merge_trace.h"
#include "audit/recording_audit.h"

namespace mg {

inline constexpr double kMinCalibratedResponseS = 0.3;
inline constexpr double kMaxCalibratedResponseS = 2.0;

struct PlausibleBraking {
  double brake_min_lo_mps2, brake_min_hi_mps2;
  double brake_max_lo_mps2, brake_max_hi_mps2;
};
// Trucks and buses brake less hard than cars, motorcycles and the rest.
PlausibleBraking plausible_braking(const std::string& vehicle_class);

// The braking scales tried, from the profile's own limits (1) up.
const std::vector<double>& calibration_brake_scales();

// The profile with this response time and every class's b_min, b_max times brake_scale, each
// kept within its class's plausible range (b_max >= b_min).
AuditProfile calibrated_profile(const AuditProfile& base, double response_time_s, double brake_scale);

// The response times tried: kMaxCalibratedResponseS down to kMinCalibratedResponseS in 0.05 s.
const std::vector<double>& calibration_response_times();

// The audit's verdict of one lane change under calibrated_profile(base, rho, scale) for every
// scale of calibration_brake_scales() and rho of calibration_response_times(), scale-major:
// exactly what the audit under that profile would say of it.
std::vector<AuditVerdict> calibration_verdicts(const RecordingView& v, const LaneChange& c, const AuditProfile& base, const AuditOptions& o);

struct CalibrationChoice {
  bool found = false;  // some profile within the ranges makes `share` of the judged merges hold
  double response_time_s = 1.0;
  double brake_scale = 1.0;
  int judged = 0;   // under the proposal
  int holding = 0;  // of those
  std::string text; // what was proposed and why, one paragraph
};
// Of the grid's profiles, the first (least braking, then longest response time) under which
// `share` of the merges judged under it hold; none: the one with the largest share.
CalibrationChoice choose_calibration(const std::vector<std::vector<AuditVerdict>>& verdicts, double share, const AuditProfile& base);

}  // namespace mg
