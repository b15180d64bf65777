// The sigmoid planner of RCPP §II-C (spec §6): the merge path
//   y(X) = W / (1 + exp(-kappa (X - P_c))) + b,
// the comfort bound on kappa, and the choice of (P_c, kappa) among candidates scored by a cost
// (the potential field along the path plus the Definition 1 cost; docs/planner.md).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "core/merge_duration.h"
#include "planner/definition1.h"
#include "planner/planner.h"

namespace mg {

struct Sigmoid {
  double width_m = 0.0;      // W, lane-centre to lane-centre (merge_sigmoid: the ego's Y to the target's centre)
  double kappa_per_m = 0.0;  // slope parameter, > 0
  double pc_m = 0.0;         // the logistic's midpoint: P_c for the paper's path (merge_sigmoid: lane_line_x_m)
  double offset_m = 0.0;     // b, the start lane's centre (merge_sigmoid: the ego's Y)
  double y_at_m(double x_m) const;
  // x where the path has covered `fraction` (0..1) of W: P_c + ln(f/(1-f))/kappa.
  double x_at_fraction_m(double fraction) const;
  // x where the path reaches y_m, strictly between its ends.
  double x_at_y_m(double y_m) const { return x_at_fraction_m((y_m - offset_m) / width_m); }
};

// The merge path of an ego at ego_y_m in the side lane (centre -W) crossing the lane line (-W/2)
// at pc_m with slope kappa_per_m: the paper's sigmoid across the lane, from the side lane's
// centre, for an ego at or below that centre; for an ego nearer the lane (off its centre at the
// start, or held after an abort), the same logistic from the ego's Y to the target lane's centre,
// shifted so that it crosses the lane line at pc_m, where Definition 1 put P_c (its own midpoint
// lies beyond). The paper's path from the side lane's centre either took such an ego away from
// the lane first or, held at the ego's Y until the sigmoid came up to it, met it with a kink of
// its heading that the tracker took a second late: the merge crossed the lane line metres past
// P_c, and the judge read Definition 1 over the longer merge it saw (def1_1_gap, a campaign
// finding). The same logistic so rescaled is how `progress`'s witness merges from the ego's
// offset (rules/feasible_gaps.cpp).
Sigmoid merge_sigmoid(double lane_width_m, double ego_y_m, double kappa_per_m, double pc_m);
// Where a merge path crosses the lane line (-W/2): P_c.
inline double lane_line_x_m(const Sigmoid& sig, double lane_width_m) { return sig.x_at_y_m(-0.5 * lane_width_m); }

// Peak lateral acceleration of the logistic path at constant speed v: v^2 W kappa^2 / (6 sqrt 3)
// (max |y''| = W kappa^2/(6 sqrt 3) at X - P_c = +-ln(2 + sqrt 3)/kappa; spec §6).
double sigmoid_peak_lat_accel_mps2(double speed_mps, double width_m, double kappa_per_m);
// The largest kappa with sigmoid_peak_lat_accel <= lat_accel_mps2 (infinite at speed 0).
double kappa_comfort_max_per_m(double speed_mps, double width_m, double lat_accel_mps2);
// The merge durations the Definition 1 searches try, as multiples of a base duration: rho_m itself
// first; longer ones for slow egos (e.g. merging from standstill after Def. 1.3), whose trackable
// sigmoid does not fit in rho_m, and for egos that must drop behind a vehicle passing them
// (docs/planner.md). The base is merge_duration_base_s (core/merge_duration.h) of rho_m and the
// comfort bound; the progress rule tries the factors up to 2 of the same base, with its own bound
// (rules.progress_lat_accel_max_mps2, by default the planner's), so it offers no merge at a
// duration the planner does not try.
inline constexpr double kMergeDurationFactors[] = {1.0, 1.5, 2.0, 3.0};

// Peak lateral acceleration along a sigmoid driven with a speed profile (the ramp starting at
// ramp_origin_x_m): max of v(x)^2 |y''(x)| over points within +-4/kappa of P_c, y'' = W kappa^2
// s(1-s)(1-2s) for the logistic s (RCPP §II-C; equals sigmoid_peak_lat_accel_mps2 at fixed v).
double peak_lat_accel_along_mps2(const Sigmoid& sig, const SpeedRamp& ramp, double ramp_origin_x_m);
// A bound that is never below it, wherever the ramp starts: the ramp's top speed at the sharpest
// sample (with a relative slack far above rounding). Increasing in kappa.
double peak_lat_accel_bound_mps2(const Sigmoid& sig, const SpeedRamp& ramp);

// Fraction of W within which the path counts as "at" a lane centre: the sigmoid starts within
// kSigmoidEndFraction of the side lane at the ego (so the path is continuous with the ego's
// position) and the merge is complete at 1 - kSigmoidEndFraction.
inline constexpr double kSigmoidEndFraction = 0.02;

// Samples the path from x_from to x_to (inclusive, step_m apart), strictly increasing in X.
std::vector<PathPoint> sample_straight(double y_m, double x_from_m, double x_to_m, double step_m);

// `param` is the candidate parameter that fixes the sigmoid's P_c: P_c itself (Definition 2), or
// v_e* (Definition 1), whose speed ramp puts P_c where the ego is at rho/2.
struct SigmoidChoice {
  double param = 0.0;
  double kappa_per_m = 0.0;
  double cost = 0.0;
};

// n values evenly over [lo, hi], both ends exact (the midpoint when n == 1 or hi <= lo):
// even_grid_size of them, value i being even_grid_at.
std::vector<double> even_grid(double lo, double hi, int n);
inline int even_grid_size(double lo, double hi, int n) { return n <= 1 || hi <= lo ? 1 : n; }
inline double even_grid_at(double lo, double hi, int n, int i) {
  if (n <= 1 || hi <= lo) return 0.5 * (lo + hi);
  return i == n - 1 ? hi : lo + (hi - lo) * i / (n - 1);
}

// Grid search: for each parameter value the admissible kappa range from kappa_range(param)
// (nullopt: none), n_kappa values evenly over it, each scored by cost(param, kappa) (a
// non-finite cost marks an inadmissible candidate). Returns the cheapest (first on ties, so the
// result is deterministic), nullopt when no candidate is admissible.
using KappaRange = std::optional<std::pair<double, double>>;
std::optional<SigmoidChoice> choose_sigmoid(const std::vector<double>& params,
                                            const std::function<KappaRange(double)>& kappa_range, int n_kappa,
                                            const std::function<double(double, double)>& cost);

// The same choice as choose_sigmoid (the cheapest admissible candidate, the first in its order on
// ties), found by visiting the candidates cheapest lower bound first and stopping once no bound
// left lies below the cheapest cost found: a search whose cost is mostly an expensive admissibility
// test evaluates few candidates beyond the chosen one. Candidates are named by the index of their
// parameter. The bounds must hold in floating point:
//   param_floor(i) <= bound(i, kappa) <= cost(i, kappa) for every kappa of i's range
// (a NaN bound counts as no bound). kappa_range(i) is asked only of parameters whose floor lies
// below `incumbent`, the cost of a choice made before this search (a candidate at that cost or
// above loses to it): nullopt is returned when nothing beats it.
template <class Floor, class Range, class Bound, class Cost>
std::optional<SigmoidChoice> choose_sigmoid_best_first(const std::vector<double>& params, const Floor& param_floor,
                                                       const Range& kappa_range, int n_kappa, const Bound& bound,
                                                       const Cost& cost,
                                                       double incumbent = std::numeric_limits<double>::infinity());

// choose_sigmoid_best_first's implementation.
namespace sigmoid_detail {

// One candidate of the best-first search: `order` is its place in choose_sigmoid's order.
struct Candidate {
  double key = 0.0;  // a lower bound on its cost
  int order = 0;
  int param_index = 0;
  double kappa_per_m = 0.0;
};

inline double as_lower_bound(double b) { return std::isnan(b) ? -std::numeric_limits<double>::infinity() : b; }

// Sorts the candidates by key, then by order; returns the choice of the visit of
// choose_sigmoid_best_first.
std::optional<SigmoidChoice> visit_cheapest_first(const std::vector<double>& params, std::vector<Candidate>& candidates,
                                                  const std::function<double(std::size_t, double)>& cost,
                                                  double incumbent);

}  // namespace sigmoid_detail

template <class Floor, class Range, class Bound, class Cost>
std::optional<SigmoidChoice> choose_sigmoid_best_first(const std::vector<double>& params, const Floor& param_floor,
                                                       const Range& kappa_range, int n_kappa, const Bound& bound,
                                                       const Cost& cost, double incumbent) {
  using sigmoid_detail::as_lower_bound;
  std::vector<sigmoid_detail::Candidate> candidates;
  candidates.reserve(params.size() * static_cast<std::size_t>(std::max(n_kappa, 1)));
  for (std::size_t i = 0; i < params.size(); ++i) {
    // A parameter none of whose candidates can beat the incumbent is not expanded.
    if (as_lower_bound(param_floor(i)) >= incumbent) continue;
    const KappaRange range = kappa_range(i);
    if (!range || range->first > range->second) continue;
    for (int k = 0; k < even_grid_size(range->first, range->second, n_kappa); ++k) {
      const double kappa = even_grid_at(range->first, range->second, n_kappa, k);
      candidates.push_back({as_lower_bound(bound(i, kappa)), static_cast<int>(candidates.size()), static_cast<int>(i), kappa});
    }
  }
  return sigmoid_detail::visit_cheapest_first(params, candidates, cost, incumbent);
}

}  // namespace mg
