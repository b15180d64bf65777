// The measures the RCPP paper compares planners by (its §IV and spec §11), computed from a
// trace: merge time, path length of the manoeuvre, trajectory oscillation, sideslip, speeds.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "core/scenario.h"
#include "sim/trace.h"

namespace mg {

inline constexpr double kLateralReversalDeadbandMps = 0.1;  // |v_Y| below this has no sign

struct PaperMetrics {
  bool merged = false;                      // a kMergeComplete event happened
  bool collision = false;                   // ego box overlapped a main-lane box at some step
  std::optional<double> merge_start_time_s; // first kMergeStart
  std::optional<double> merge_time_s;       // first kMergeStart -> first kMergeComplete
  std::optional<double> path_length_m;      // ego CG arc length over the same interval
  std::optional<double> merge_x_m;          // ego X when its centre crossed the lane boundary
  int lateral_reversals = 0;                // sign changes of the road-frame lateral speed
  double sideslip_min_rad = 0.0, sideslip_max_rad = 0.0;
  double yaw_min_rad = 0.0, yaw_max_rad = 0.0;
  double ego_speed_min_mps = 0.0, ego_speed_max_mps = 0.0;
  double obstacle_speed_min_mps = 0.0;      // over all main-lane vehicles (NaN without any)
};

// Sign changes of v with a dead band: values with |v| < deadband carry no sign, so a single
// S-shaped lane change (v_Y >= 0 throughout) counts 0 and each weave counts 1 or 2.
int count_sign_changes(const std::vector<double>& v, double deadband);

// Whether two oriented rectangles (centre, yaw, length, width) overlap (separating axes).
bool boxes_overlap(double x1, double y1, double yaw1, double l1, double w1, double x2, double y2, double yaw2,
                   double l2, double w2);

PaperMetrics compute_paper_metrics(const Scenario& s, const Trace& t);

// The keys of metrics.json: merged, collision, merge_time_s, path_length_m, lateral_reversals,
// sideslip_min_rad, sideslip_max_rad, ego_speed_min_mps, ego_speed_max_mps,
// obstacle_speed_min_mps (+ merge_start_time_s, merge_x_m, yaw_min_rad, yaw_max_rad);
// absent values are null.
nlohmann::json paper_metrics_to_json(const PaperMetrics& m);

// 100 (baseline - value) / baseline: how much smaller value is than baseline, in percent.
std::optional<double> reduction_pct(const std::optional<double>& baseline, const std::optional<double>& value);

// A report's optional number in JSON: the number, or null.
inline nlohmann::json or_null(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace mg
