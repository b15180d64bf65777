#include "planner/sigmoid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/demand.h"

namespace mg {
namespace {

const double kSixRootThree = 6.0 * std::sqrt(3.0);

}  // namespace

std::vector<double> even_grid(double lo, double hi, int n) {
  std::vector<double> v;
  for (int i = 0; i < even_grid_size(lo, hi, n); ++i) v.push_back(even_grid_at(lo, hi, n, i));
  return v;
}

// RCPP §II-C, f_sig.
double Sigmoid::y_at_m(double x_m) const {
  return width_m / (1.0 + std::exp(-kappa_per_m * (x_m - pc_m))) + offset_m;
}

Sigmoid merge_sigmoid(double lane_width_m, double ego_y_m, double kappa_per_m, double pc_m) {
  const Sigmoid paper{lane_width_m, kappa_per_m, pc_m, -lane_width_m};
  // Rescaled only from beyond the paper's path's start (its kSigmoidEndFraction point), and from
  // well short of the lane line.
  const double line_y = -0.5 * lane_width_m;
  if (!(ego_y_m > -lane_width_m + kSigmoidEndFraction * lane_width_m) || !(ego_y_m < line_y - 0.1 * lane_width_m))
    return paper;
  const double amplitude_m = -ego_y_m;
  const double line_fraction = (line_y - ego_y_m) / amplitude_m;
  return Sigmoid{amplitude_m, kappa_per_m, pc_m - std::log(line_fraction / (1.0 - line_fraction)) / kappa_per_m, ego_y_m};
}

double Sigmoid::x_at_fraction_m(double fraction) const {
  MG_DEMAND(fraction > 0.0 && fraction < 1.0);
  return pc_m + std::log(fraction / (1.0 - fraction)) / kappa_per_m;
}

double sigmoid_peak_lat_accel_mps2(double speed_mps, double width_m, double kappa_per_m) {
  return speed_mps * speed_mps * width_m * kappa_per_m * kappa_per_m / kSixRootThree;
}

double kappa_comfort_max_per_m(double speed_mps, double width_m, double lat_accel_mps2) {
  if (speed_mps <= 0.0) return std::numeric_limits<double>::infinity();
  return std::sqrt(kSixRootThree * lat_accel_mps2 / width_m) / speed_mps;
}

namespace {
constexpr int kPeakSamples = 40;
constexpr double kPeakSpan = 4.0;
// The samples of peak_lat_accel_along_mps2 sit at fixed u = kappa (x - P_c), so the logistic
// values there do not depend on the sigmoid: computed once (the exp was a tenth of a std-4 run).
// curvature: sgm (1 - sgm) |1 - 2 sgm|, y'' / (W kappa^2); max_curvature, the largest.
struct PeakSampleTable {
  double u[kPeakSamples + 1];
  double sgm[kPeakSamples + 1];
  double curvature[kPeakSamples + 1];
  double max_curvature = 0.0;
  PeakSampleTable() {
    for (int i = 0; i <= kPeakSamples; ++i) {
      u[i] = kPeakSpan * (2.0 * i / kPeakSamples - 1.0);
      sgm[i] = 1.0 / (1.0 + std::exp(-u[i]));
      curvature[i] = sgm[i] * (1.0 - sgm[i]) * std::abs(1.0 - 2.0 * sgm[i]);
      max_curvature = std::max(max_curvature, curvature[i]);
    }
  }
};
// Relative slack on bounds computed from the tabulated curvature instead of y'' itself.
constexpr double kCurvatureSlack = 1e-9;
const PeakSampleTable kPeakTable;
}  // namespace

double peak_lat_accel_along_mps2(const Sigmoid& sig, const SpeedRamp& ramp, double ramp_origin_x_m) {
  // The squared speed is monotone along the path (one ramp), so the samples are visited from the
  // fast end: each one's squared speed bounds every later one's, and a sample whose curvature term
  // times that bound cannot beat the peak so far is skipped (the result is the same). The test
  // runs first on the tabulated curvature with a relative slack far above the rounding of y''.
  const bool slowing = ramp.v_target_mps < ramp.v0_mps;
  double v_sq_bound = ramp.top_speed_squared_m2ps2();
  const double w_kappa_sq = sig.width_m * sig.kappa_per_m * sig.kappa_per_m * (1.0 + kCurvatureSlack);
  double peak = 0.0;
  for (int n = 0; n <= kPeakSamples; ++n) {
    const int i = slowing ? n : kPeakSamples - n;
    if (v_sq_bound * w_kappa_sq * kPeakTable.curvature[i] <= peak) continue;
    const double sgm = kPeakTable.sgm[i];
    const double ypp = sig.width_m * sig.kappa_per_m * sig.kappa_per_m * sgm * (1.0 - sgm) * std::abs(1.0 - 2.0 * sgm);
    if (v_sq_bound * ypp <= peak) continue;
    const double x = sig.pc_m + kPeakTable.u[i] / sig.kappa_per_m;
    v_sq_bound = ramp.speed_squared_at_distance_m2ps2(std::max(0.0, x - ramp_origin_x_m));
    peak = std::max(peak, v_sq_bound * ypp);
  }
  return peak;
}

double peak_lat_accel_bound_mps2(const Sigmoid& sig, const SpeedRamp& ramp) {
  return ramp.top_speed_squared_m2ps2() * sig.width_m * sig.kappa_per_m * sig.kappa_per_m * kPeakTable.max_curvature * (1.0 + kCurvatureSlack);
}

std::vector<PathPoint> sample_straight(double y_m, double x_from_m, double x_to_m, double step_m) {
  return sample_path(x_from_m, x_to_m, step_m, [=](double) { return y_m; });
}

std::optional<SigmoidChoice> choose_sigmoid(const std::vector<double>& params,
                                            const std::function<KappaRange(double)>& kappa_range, int n_kappa,
                                            const std::function<double(double, double)>& cost) {
  std::optional<SigmoidChoice> best;
  for (const double param : params) {
    const KappaRange range = kappa_range(param);
    if (!range || range->first > range->second) continue;
    for (int i = 0; i < even_grid_size(range->first, range->second, n_kappa); ++i) {
      const double kappa = even_grid_at(range->first, range->second, n_kappa, i);
      const double c = cost(param, kappa);
      if (!std::isfinite(c)) continue;  // inadmissible candidate
      if (!best || c < best->cost) best = SigmoidChoice{param, kappa, c};
    }
  }
  return best;
}

namespace sigmoid_detail {

std::optional<SigmoidChoice> visit_cheapest_first(const std::vector<double>& params, std::vector<Candidate>& candidates,
                                                  const std::function<double(std::size_t, double)>& cost,
                                                  double incumbent) {
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.key < b.key || (a.key == b.key && a.order < b.order);
  });
  // The incumbent wins every tie: order -1 lies before every candidate.
  SigmoidChoice best{0.0, 0.0, incumbent};
  int best_order = -1;
  for (const Candidate& c : candidates) {
    // Keys ascend, so no candidate left can beat the best once one key exceeds its cost.
    if (c.key > best.cost) break;
    if (c.key == best.cost && c.order > best_order) continue;  // at best a tie, and later
    const double cost_c = cost(static_cast<std::size_t>(c.param_index), c.kappa_per_m);
    if (!std::isfinite(cost_c)) continue;  // inadmissible candidate
    if (cost_c < best.cost || (cost_c == best.cost && c.order < best_order)) {
      best = SigmoidChoice{params[static_cast<std::size_t>(c.param_index)], c.kappa_per_m, cost_c};
      best_order = c.order;
    }
  }
  if (best_order < 0) return std::nullopt;
  return best;
}

}  // namespace sigmoid_detail

}  // namespace mg
