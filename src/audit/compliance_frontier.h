// The compliance frontier of a judged merge (docs/audit.md "Compliance frontier"): the largest
// response time rho at which the merge holds with the profile's braking and acceleration
// limits, found by bisection over rho with the same judgement as the verdict (the trace judged
// again by the rules with another rho); the braking a follower would need at the profile's rho
// (every vehicle's b_min and b_max scaled together, scanned in steps of kBrakeStepMps2 of the
// follower's b_min); and the rule that binds just beyond the frontier. Assumes, as the bisection must, that a merge holding at some rho holds at
// every shorter one (and with harder braking): a longer response lengthens every RSS distance
// and Definition 1's gaps.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mg {

inline constexpr double kMaxFrontierResponseTimeS = 5.0;  // RssParams' range ends there
inline constexpr double kMaxBrakeMps2 = 15.0;             // no scaled braking limit exceeds this
inline constexpr double kFrontierResolutionS = 0.005;
inline constexpr double kBrakeStepMps2 = 0.5;  // the needed braking is scanned in these steps

// The judgement at (rho, brake scale): whether it holds, and otherwise the rule that fails first
// and its reference (for the binding rule; "" when it holds).
struct VariedJudgement {
  bool holds = false;
  std::string first_rule;
  std::string first_rule_ref;
};
using JudgeAt = std::function<VariedJudgement(double response_time_s, double brake_scale)>;

// The largest rho in [0, kMaxFrontierResponseTimeS] at which judge(rho, scale) holds, to within
// kFrontierResolutionS; nullopt when it fails even at 0. `hint_s`: a rho already judged (the
// profile's), which narrows the bisection.
struct RhoFrontier {
  std::optional<double> max_response_time_s;
  bool holds_throughout = false;  // holds up to kMaxFrontierResponseTimeS
  double first_failing_s = 0.0;   // the smallest rho found failing (when not throughout)
};
RhoFrontier rho_frontier(const JudgeAt& judge, double brake_scale, double hint_s, bool holds_at_hint);

struct FrontierCurvePoint {
  double brake_scale = 1.0;
  RhoFrontier rho;
};

struct ComplianceFrontier {
  double profile_response_time_s = 1.0;
  bool holds_at_profile = false;
  RhoFrontier rho;                    // at the profile's braking limits (scale 1)
  // The smallest scale of b_min and b_max above 1, up to kMaxBrakeMps2 / b_min, at which a merge
  // violated at the profile's rho holds; nullopt: none.
  std::optional<double> needed_brake_scale;
  double follower_brake_min_mps2 = 4.0;  // the b_min the scale applies to (the follower's class)
  double brake_scale_cap = 1.0;
  std::string binding_rule, binding_ref;  // fails first just beyond the frontier ("" if none)
  std::vector<FrontierCurvePoint> curve;  // the frontier at each of the sweep's brake scales
  std::string words;                      // "violated at rho = 1 s; holds for rho <= 0.35 s; ..."
};

ComplianceFrontier compliance_frontier(const JudgeAt& judge, double profile_response_time_s, double follower_brake_min_mps2,
                                       const std::vector<double>& curve_brake_scales);

// "0.35 s", "1 s": a response time for the words.
std::string seconds_text(double s);

}  // namespace mg
