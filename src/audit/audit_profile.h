// The profile a recording is audited with (docs/audit.md "Profile"): recordings carry
// no declared limits or response times, so these come from here, one set of limits per vehicle
// class, with the RSS and rule parameters, the smoothing and merge-window settings, and the
// ranges of the sensitivity sweep. One struct, loaded strictly from JSON (`--params FILE`, each
// key optional: absent keys keep the documented defaults of default_audit_profile()).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/params.h"
#include "core/scenario.h"

namespace mg {

struct SensitivityRanges {
  std::vector<double> response_times_s = {0.5, 1.0, 1.5, 2.0};  // each in [0, 5]
  std::vector<double> brake_scales = {0.75, 1.0, 1.25};         // scales b_min and b_max, each in [0.25, 4]
  bool operator==(const SensitivityRanges&) const = default;
};

struct AuditProfile {
  std::string name = "mergeguard default recorded-traffic profile (v1)";
  RssParams rss{1.0, 0.1};                 // human response time 1 s, [0, 5]
  RuleParams rules;                        // the rules' defaults, but merge_complete_yaw_rad 0.05
  std::map<std::string, Limits> classes;   // by CommonRoad obstacle type; "default" for the rest
  int smoothing_half_window_steps = 3;     // local_slope window +-3 steps, [1, 50]
  double window_before_s = 6.0;            // the audited window around the lane change, [1, 60]
  double window_after_s = 6.0;             // [1, 60]
  double neighbour_range_m = 80.0;         // others within this along the road take part, [10, 1000]
  double min_lane_time_s = 0.5;            // shorter stays in a lane are noise, [0, 5]
  double halted_speed_mps = 0.5;           // Definition 1.3: halted on the ramp below this, [0, 5]
  double halt_near_end_m = 50.0;           // ... within this of the ramp's end, [0, 1000]
  double default_speed_limit_mps = 33.34;  // when the lanelets give none, (0, 100]
  SensitivityRanges sensitivity;
  bool operator==(const AuditProfile&) const = default;

  // The class's limits, or the "default" class's.
  const Limits& limits_for(const std::string& type) const;
};

AuditProfile default_audit_profile();
// Every key optional; unknown keys, wrong types and out-of-range values are InputErrors.
AuditProfile audit_profile_from_json(const nlohmann::json& j, const std::string& source);
AuditProfile load_audit_profile(const std::string& path);
nlohmann::json audit_profile_to_json(const AuditProfile& p);

}  // namespace mg
