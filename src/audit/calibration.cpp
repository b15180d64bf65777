#include "audit/calibration.h"

#include <algorithm>
#include <cmath>

#include "core/demand.h"
#include "core/fixed_text.h"

namespace mg {

PlausibleBraking plausible_braking(const std::string& vehicle_class) {
  if (vehicle_class == "truck" || vehicle_class == "bus") return {2.0, 6.0, 4.0, 8.0};
  return {3.0, 8.0, 6.0, 10.0};
}

const std::vector<double>& calibration_brake_scales() {
  static const std::vector<double> kScales = {1.0, 1.25, 1.5, 1.75, 2.0};
  return kScales;
}

AuditProfile calibrated_profile(const AuditProfile& base, double response_time_s, double brake_scale) {
  MG_DEMAND(response_time_s >= 0.0 && brake_scale > 0.0);
  AuditProfile p = base;
  p.rss.response_time_s = response_time_s;
  for (auto& [name, limits] : p.classes) {
    const PlausibleBraking r = plausible_braking(name);
    limits.brake_min_mps2 = std::clamp(limits.brake_min_mps2 * brake_scale, std::min(r.brake_min_lo_mps2, limits.brake_min_mps2), r.brake_min_hi_mps2);
    limits.brake_max_mps2 = std::clamp(limits.brake_max_mps2 * brake_scale, std::min(r.brake_max_lo_mps2, limits.brake_max_mps2), r.brake_max_hi_mps2);
    limits.brake_max_mps2 = std::max(limits.brake_max_mps2, limits.brake_min_mps2);
  }
  return p;
}

const std::vector<double>& calibration_response_times() {
  static const std::vector<double> kTimes = [] {
    std::vector<double> t;
    for (int k = static_cast<int>(std::lround(kMaxCalibratedResponseS * 20)); k >= static_cast<int>(std::lround(kMinCalibratedResponseS * 20)); --k) t.push_back(k / 20.0);
    return t;
  }();
  return kTimes;
}

std::vector<AuditVerdict> calibration_verdicts(const RecordingView& v, const LaneChange& c, const AuditProfile& base, const AuditOptions& o) {
  AuditOptions quick = o;
  quick.frontier = false;
  std::vector<AuditVerdict> out;
  for (const double scale : calibration_brake_scales()) {
    for (const double rho : calibration_response_times()) out.push_back(audit_merge(v, c, calibrated_profile(base, rho, scale), quick).verdict);
  }
  return out;
}

CalibrationChoice choose_calibration(const std::vector<std::vector<AuditVerdict>>& verdicts, double share, const AuditProfile& base) {
  MG_DEMAND(share > 0.0 && share <= 1.0);
  CalibrationChoice c;
  c.response_time_s = base.rss.response_time_s;
  const std::size_t n_rho = calibration_response_times().size();
  double best = -1.0;
  for (std::size_t j = 0; j < calibration_brake_scales().size() && !c.found; ++j) {
    for (std::size_t k = 0; k < n_rho && !c.found; ++k) {
      int holds = 0, judged = 0;
      for (const auto& v : verdicts) {
        MG_DEMAND(v.size() == n_rho * calibration_brake_scales().size());
        const AuditVerdict x = v[j * n_rho + k];
        holds += x == AuditVerdict::kHolds ? 1 : 0;
        judged += x == AuditVerdict::kHolds || x == AuditVerdict::kViolated ? 1 : 0;
      }
      if (judged == 0) continue;
      const double got = static_cast<double>(holds) / judged;
      c.found = got >= share - 1e-12;
      if (got > best + 1e-12 || c.found) {
        best = got;
        c.brake_scale = calibration_brake_scales()[j];
        c.response_time_s = calibration_response_times()[k];
        c.judged = judged;
        c.holding = holds;
      }
    }
  }
  const std::string target = fixed_text(100.0 * share, 0) + " % of the judged merges";
  const std::string got = std::to_string(c.holding) + " of " + std::to_string(c.judged) + " judged merges hold";
  if (best < 0.0) {
    c.text = "no merge is judged under any profile of the grid: nothing to calibrate; the profile is written with its response time and braking unchanged";
  } else if (c.found) {
    c.text = "response time " + seconds_text(c.response_time_s) + " and braking limits x" + fixed_text(c.brake_scale, 2) +
             " (each class within its plausible range) make " + target + " hold: " + got;
  } else {
    c.text = "no profile within the plausible ranges (response time " + seconds_text(kMinCalibratedResponseS) + " to " + seconds_text(kMaxCalibratedResponseS) +
             ", braking up to each class's plausible maximum) makes " + target + " hold; the closest is proposed: response time " +
             seconds_text(c.response_time_s) + ", braking x" + fixed_text(c.brake_scale, 2) + ": " + got;
  }
  return c;
}

}  // namespace mg
