#include "audit/calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "audit/censoring.h"
#include "core/demand.h"

namespace mg {
namespace {

std::string fixed(double v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// A frontier as one number for ranking: holding throughout counts as the range's end, failing
// even at 0 as below any response time.
double frontier_value(const RhoFrontier& f) {
  if (f.holds_throughout) return kMaxFrontierResponseTimeS;
  return f.max_response_time_s.value_or(-1.0);
}

// How many merges hold at rho by their frontiers.
int holding_at(const std::vector<std::vector<RhoFrontier>>& frontiers, std::size_t scale, double rho_s) {
  return static_cast<int>(std::count_if(frontiers.begin(), frontiers.end(), [&](const std::vector<RhoFrontier>& f) { return frontier_value(f[scale]) >= rho_s; }));
}

}  // namespace

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

std::vector<RhoFrontier> calibration_frontiers(const MergeAudit& m, const AuditProfile& base) {
  std::vector<RhoFrontier> out;
  for (const double scale : calibration_brake_scales()) {
    const JudgeAt judge = [&](double rho_s, double) {
      const CheckResult r = check_observed(with_profile(m.merge, calibrated_profile(base, rho_s, scale)));
      VariedJudgement j;
      j.holds = r.holds;
      return j;
    };
    const double hint = base.rss.response_time_s;
    out.push_back(rho_frontier(judge, scale, hint, judge(hint, scale).holds));
  }
  return out;
}

CalibrationChoice choose_calibration(const std::vector<std::vector<RhoFrontier>>& frontiers, double share, const AuditProfile& base) {
  MG_DEMAND(share > 0.0 && share <= 1.0);
  CalibrationChoice c;
  c.merges = static_cast<int>(frontiers.size());
  const int needed = static_cast<int>(std::ceil(share * c.merges - 1e-9));
  double best_rho = -1.0;
  std::size_t best_scale = 0;
  for (std::size_t j = 0; j < calibration_brake_scales().size() && c.merges > 0; ++j) {
    std::vector<double> v;
    for (const auto& f : frontiers) v.push_back(frontier_value(f[j]));
    std::sort(v.rbegin(), v.rend());
    const double rho = v[static_cast<std::size_t>(std::max(needed, 1) - 1)];
    if (rho > best_rho) best_rho = rho, best_scale = j;
    if (rho >= kMinCalibratedResponseS) {
      c.found = true;
      best_rho = rho, best_scale = j;
      break;
    }
  }
  c.brake_scale = calibration_brake_scales()[best_scale];
  // Floored to 0.01 s so that every merge whose frontier is at or above it still holds.
  c.response_time_s = c.merges == 0 ? base.rss.response_time_s
                                    : std::clamp(std::floor(best_rho * 100.0 + 1e-9) / 100.0, kMinCalibratedResponseS, kMaxCalibratedResponseS);
  c.expected_holding = c.merges == 0 ? 0 : holding_at(frontiers, best_scale, c.response_time_s);
  const std::string target = fixed(100.0 * share, 0) + " % of the " + std::to_string(c.merges) + " judged merges";
  if (c.merges == 0) {
    c.text = "no merge was judged under the profile: nothing to calibrate; the profile is written unchanged";
  } else if (c.found) {
    c.text = "response time " + seconds_text(c.response_time_s) + " and braking limits x" + fixed(c.brake_scale, 2) +
             " (within each class's plausible range) make " + target + " hold (" + std::to_string(c.expected_holding) + " by their frontiers)";
  } else {
    c.text = "no profile within the plausible ranges (response time " + seconds_text(kMinCalibratedResponseS) + " to " +
             seconds_text(kMaxCalibratedResponseS) + ", braking up to each class's plausible maximum) makes " + target +
             " hold; the closest is proposed: response time " + seconds_text(c.response_time_s) + ", braking x" + fixed(c.brake_scale, 2) +
             " (" + std::to_string(c.expected_holding) + " hold by their frontiers)";
  }
  return c;
}

}  // namespace mg
