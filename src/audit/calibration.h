// Calibrating the audit profile to a dataset (docs/audit.md "Calibration"): the profile under
// which a given share of the judged merges hold, found from each merge's compliance frontier at
// a ladder of braking scales, within plausible ranges for human drivers: the response time in
// [kMinCalibratedResponseS, kMaxCalibratedResponseS], each class's b_min and b_max scaled and
// kept within its class's range (PlausibleBraking). Of the candidates, the one with the least
// braking beyond the profile's, and at it the longest response time, is proposed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "audit/audit_profile.h"
#include "audit/compliance_frontier.h"
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

// A judged merge's frontier at each of calibration_brake_scales() (the base profile's classes
// scaled as calibrated_profile does).
std::vector<RhoFrontier> calibration_frontiers(const MergeAudit& m, const AuditProfile& base);

struct CalibrationChoice {
  bool found = false;  // some profile within the ranges makes `share` of the merges hold
  double response_time_s = 1.0;
  double brake_scale = 1.0;
  int merges = 0;           // judged under the base profile
  int expected_holding = 0; // under the proposal, by the frontiers
  std::string text;         // what was proposed and why, one paragraph
};
CalibrationChoice choose_calibration(const std::vector<std::vector<RhoFrontier>>& frontiers, double share, const AuditProfile& base);

}  // namespace mg
