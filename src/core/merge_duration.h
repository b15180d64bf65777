// The shortest comfortable lane change, shared by RCPP's Definition 1 search and the `progress`
// rule, so that the merges the rule offers take no less time than the planner's comfortable ones
// (docs/spec_rules.md, point 27; docs/planner.md).
#pragma once

namespace mg {

// The shortest merge (2 % to 98 % of the lane width W) whose peak lateral acceleration stays
// within lat_accel_mps2 at any constant speed v. The logistic path of slope kappa spans
// 2 ln(49)/kappa <= v rho and its peak lateral acceleration is v^2 W kappa^2 / (6 sqrt 3), so
// rho >= 2 ln(49) / sqrt(6 sqrt 3 a / W), whatever v.
double shortest_comfortable_merge_s(double width_m, double lat_accel_mps2);

// A declared rho_m below shortest_comfortable_merge_s is raised to kShortestMergeFactor times that
// duration (the factor leaves room for a speed change during the merge).
inline constexpr double kShortestMergeFactor = 1.05;
double merge_duration_base_s(double rho_m_s, double width_m, double lat_accel_mps2);

}  // namespace mg
