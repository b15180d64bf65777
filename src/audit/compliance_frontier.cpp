#include "audit/compliance_frontier.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/demand.h"
#include "core/fixed_text.h"

namespace mg {
namespace {

// The smallest brake scale, in steps of the follower's b_min by kBrakeStepMps2 from the
// profile's up to the cap, at which judge(rho, scale) holds; nullopt when none does. A scan, not
// a bisection: a larger b_min shortens the safe distance but also demands a harder proper
// response (RSS Def. 5), so holding need not be monotone in it.
std::optional<double> brake_frontier(const JudgeAt& judge, double rho_s, double follower_brake_min_mps2, double cap) {
  const int steps = static_cast<int>(std::floor((cap - 1.0) * follower_brake_min_mps2 / kBrakeStepMps2 + 1e-9));
  for (int k = 1; k <= steps; ++k) {
    const double scale = 1.0 + k * kBrakeStepMps2 / follower_brake_min_mps2;
    if (judge(rho_s, scale).holds) return scale;
  }
  return std::nullopt;
}

std::string frontier_words(const ComplianceFrontier& f) {
  const std::string rho = "rho = " + seconds_text(f.profile_response_time_s);
  std::string w = f.holds_at_profile ? "holds at " + rho : "violated at " + rho;
  if (f.rho.holds_throughout) {
    w += "; holds for every rho up to " + seconds_text(kMaxFrontierResponseTimeS);
  } else if (f.rho.max_response_time_s) {
    w += "; holds for rho <= " + seconds_text(*f.rho.max_response_time_s);
  } else {
    w += "; violated even at rho = 0 s";
  }
  if (!f.binding_rule.empty()) w += " (binding: " + f.binding_rule + ", " + f.binding_ref + ")";
  if (!f.holds_at_profile) {
    w += f.needed_brake_scale ? "; at " + rho + " a follower would need b_min >= " + fixed_text(*f.needed_brake_scale * f.follower_brake_min_mps2, 1) +
                                    " m/s2 (profile: " + fixed_text(f.follower_brake_min_mps2, 1) + ")"
                              : "; at " + rho + " no braking up to " + fixed_text(kMaxBrakeMps2, 0) + " m/s2 suffices";
  }
  return w;
}

}  // namespace

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", s);
  std::string t = buf;
  while (t.back() == '0') t.pop_back();
  if (t.back() == '.') t.pop_back();
  return t + " s";
}

RhoFrontier rho_frontier(const JudgeAt& judge, double brake_scale, double hint_s, bool holds_at_hint) {
  MG_DEMAND(hint_s >= 0.0 && hint_s <= kMaxFrontierResponseTimeS);
  RhoFrontier f;
  double lo = 0.0, hi = kMaxFrontierResponseTimeS;
  (holds_at_hint ? lo : hi) = hint_s;
  if (holds_at_hint && judge(kMaxFrontierResponseTimeS, brake_scale).holds) {
    f.holds_throughout = true;
    f.max_response_time_s = kMaxFrontierResponseTimeS;
    return f;
  }
  if (!holds_at_hint && (hint_s == 0.0 || !judge(0.0, brake_scale).holds)) {
    f.first_failing_s = 0.0;
    return f;
  }
  while (hi - lo > kFrontierResolutionS) {
    const double mid = 0.5 * (lo + hi);
    (judge(mid, brake_scale).holds ? lo : hi) = mid;
  }
  f.max_response_time_s = lo;
  f.first_failing_s = hi;
  return f;
}

ComplianceFrontier compliance_frontier(const JudgeAt& judge, double profile_response_time_s, double follower_brake_min_mps2,
                                       const std::vector<double>& curve_brake_scales) {
  ComplianceFrontier f;
  f.profile_response_time_s = profile_response_time_s;
  f.follower_brake_min_mps2 = follower_brake_min_mps2;
  const VariedJudgement at_profile = judge(profile_response_time_s, 1.0);
  f.holds_at_profile = at_profile.holds;
  f.rho = rho_frontier(judge, 1.0, profile_response_time_s, at_profile.holds);
  if (!f.rho.holds_throughout) {
    const VariedJudgement beyond = judge(f.rho.first_failing_s, 1.0);
    f.binding_rule = beyond.first_rule;
    f.binding_ref = beyond.first_rule_ref;
  }
  f.brake_scale_cap = std::max(1.0, kMaxBrakeMps2 / std::max(follower_brake_min_mps2, 0.1));
  if (!f.holds_at_profile) f.needed_brake_scale = brake_frontier(judge, profile_response_time_s, f.follower_brake_min_mps2, f.brake_scale_cap);
  for (const double scale : curve_brake_scales) {
    if (scale == 1.0) {
      f.curve.push_back({scale, f.rho});
      continue;
    }
    const VariedJudgement j = judge(profile_response_time_s, scale);
    f.curve.push_back({scale, rho_frontier(judge, scale, profile_response_time_s, j.holds)});
  }
  f.words = frontier_words(f);
  return f;
}

}  // namespace mg
