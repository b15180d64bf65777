#include "rules/definition1_gap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/rss.h"

namespace mg {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// X of the ego after tau under the bounded-rate model, expressed as the X at which the paper's
// model ("X + v_e* tau") puts it there.
double real_position_x_m(const ObservedTrace& t, const ObservedState& ego, double ve_star, double tau) {
  const Limits& lim = t.vehicles[0].limits;
  return ego.x_m + speed_change_distance_m(std::max(ego.vx_mps, 0.0), ve_star, lim.accel_max_mps2,
                                           lim.brake_min_mps2, tau) -
         ve_star * tau;
}

// The ego's speed after tau under the bounded-rate model.
double real_speed_mps(const ObservedTrace& t, const ObservedState& ego, double ve_star, double tau) {
  const Limits& lim = t.vehicles[0].limits;
  const double v = std::max(ego.vx_mps, 0.0);
  const double rate = ve_star >= v ? lim.accel_max_mps2 : lim.brake_min_mps2;
  return ve_star >= v ? std::min(ve_star, v + rate * tau) : std::max(ve_star, v - rate * tau);
}

// RCPP ineq. (1): X_o + v_o rho/2 + a_o rho^2/8 <= X + v_e* rho/2 - D_lon, the follower as the
// rear vehicle at its speed after accelerating for rho/2, the ego in front at v_ego (v_e* in the
// paper's model, the speed it has really reached in the bounded-rate one).
double ineq1_m(const ObservedTrace& t, double ego_x_m, const ObservedState& fo, int k, double ve, double rho,
               double v_ego) {
  const Limits& lim = t.vehicles[k].limits;
  const double v_o = std::max(fo.vx_mps, 0.0);
  const double d_lon = rss_longitudinal_m({v_o + lim.accel_max_mps2 * rho / 2.0, std::max(v_ego, 0.0),
                                           t.vehicles[k].size.length_m, t.vehicles[0].size.length_m,
                                           t.params.rss.response_time_s, lim.accel_max_mps2, lim.brake_min_mps2,
                                           t.vehicles[0].limits.brake_max_mps2});
  const double lhs = fo.x_m + v_o * rho / 2.0 + lim.accel_max_mps2 * rho * rho / 8.0;
  return ego_x_m + ve * rho / 2.0 - d_lon - lhs;
}

// RCPP ineq. (2) over tau: X + v_e* tau <= X_o + v_o tau - D_lon, the ego as the rear vehicle at
// v_ego (as in ineq1_m).
double ineq2_m(const ObservedTrace& t, double ego_x_m, const ObservedState& lo, int k, double ve, double tau,
               double v_ego) {
  const double v_o = std::max(lo.vx_mps, 0.0);
  const Limits& ego = t.vehicles[0].limits;
  const double d_lon = rss_longitudinal_m({std::max(v_ego, 0.0), v_o, t.vehicles[0].size.length_m,
                                           t.vehicles[k].size.length_m, t.params.rss.response_time_s,
                                           ego.accel_max_mps2, ego.brake_min_mps2,
                                           t.vehicles[k].limits.brake_max_mps2});
  return (lo.x_m + v_o * tau - d_lon) - (ego_x_m + ve * tau);
}

}  // namespace

double speed_change_distance_m(double v, double v_star, double accel, double brake, double tau) {
  const double rate = v_star >= v ? accel : brake;
  const double t_change = rate > 0.0 ? std::min(std::abs(v_star - v) / rate, tau) : 0.0;
  const double v_end = v + (v_star >= v ? 1.0 : -1.0) * rate * t_change;
  return (v + v_end) / 2.0 * t_change + v_end * (tau - t_change);
}

double def1_1_margin_m(const ObservedTrace& t, std::size_t step, int follower, double ve, double rho) {
  if (follower < 1) return kInf;
  const ObservedState& ego = t.steps[step].vehicles[0];
  const ObservedState& fo = t.steps[step].vehicles[static_cast<std::size_t>(follower)];
  return std::min(ineq1_m(t, ego.x_m, fo, follower, ve, rho, ve),
                  ineq1_m(t, real_position_x_m(t, ego, ve, 0.5 * rho), fo, follower, ve, rho,
                          real_speed_mps(t, ego, ve, 0.5 * rho)));
}

double def1_2_margin_m(const ObservedTrace& t, std::size_t step, int leader, double ve, double rho) {
  if (leader < 1) return kInf;
  const ObservedState& ego = t.steps[step].vehicles[0];
  const ObservedState& lo = t.steps[step].vehicles[static_cast<std::size_t>(leader)];
  const auto at = [&](double f) {
    return std::min(ineq2_m(t, ego.x_m, lo, leader, ve, f * rho, ve),
                    ineq2_m(t, real_position_x_m(t, ego, ve, f * rho), lo, leader, ve, f * rho,
                            real_speed_mps(t, ego, ve, f * rho)));
  };
  return std::min(at(1.0), at(0.5));
}

namespace {

constexpr double kBisectionTolerance = 1e-6;

// The smallest v in [lo, hi] with pred(v) true, pred being false then true (monotone); hi + 1
// when pred(hi) is false. Found by bisection to within kBisectionTolerance, one halving per
// refine(), so that a caller comparing it with another stops as soon as the comparison is
// decided; value() is the same number however it was reached (the same midpoints in order).
template <class Pred>
class FirstTrue {
 public:
  FirstTrue(double lo, double hi, Pred pred) : pred_(std::move(pred)) {
    if (pred_(lo)) {
      lo_ = hi_ = lo;
    } else if (!pred_(hi)) {
      lo_ = hi_ = hi + 1.0;
    } else {
      lo_ = lo;
      hi_ = hi;
      done_ = !(hi_ - lo_ > kBisectionTolerance);
    }
  }
  bool done() const { return done_; }
  // The result is in (lower(), upper()] until done(), then upper().
  double lower() const { return lo_; }
  double upper() const { return hi_; }
  void refine() {
    const double mid = 0.5 * (lo_ + hi_);
    (pred_(mid) ? hi_ : lo_) = mid;
    done_ = !(hi_ - lo_ > kBisectionTolerance);
  }
  double value() {
    while (!done_) refine();
    return hi_;
  }

 private:
  Pred pred_;
  double lo_ = 0.0, hi_ = 0.0;
  bool done_ = true;
};

template <class Pred>
double first_true(double lo, double hi, Pred pred) {
  return FirstTrue(lo, hi, std::move(pred)).value();
}

// v_e*'s upper end from the first speed at which (1.2) fails: `over` is within the tolerance
// above the last speed that holds, so step back for ve_hi itself to hold.
double ve_hi_of(double over, double v_max) {
  return over > v_max ? v_max : over == 0.0 ? -1.0 : over - kBisectionTolerance;
}

auto holds_11(const ObservedTrace& t, std::size_t step, const GapIndices& gap, double rho, double margin_m) {
  return [&t, step, gap, rho, margin_m](double v) { return def1_1_margin_m(t, step, gap.follower, v, rho) >= margin_m; };
}

auto fails_12(const ObservedTrace& t, std::size_t step, const GapIndices& gap, double rho, double margin_m) {
  return [&t, step, gap, rho, margin_m](double v) { return def1_2_margin_m(t, step, gap.leader, v, rho) < margin_m; };
}

}  // namespace

Def1Interval def1_interval(const ObservedTrace& t, std::size_t step, const GapIndices& gap, double rho,
                           double margin_m) {
  const double v_max = t.road.speed_limit_mps;
  Def1Interval out;
  out.ve_lo_mps = first_true(0.0, v_max, holds_11(t, step, gap, rho, margin_m));
  out.ve_hi_mps = ve_hi_of(first_true(0.0, v_max, fails_12(t, step, gap, rho, margin_m)), v_max);
  return out;
}

// Both bisections advance only until ve_lo <= ve_hi is decided. Before it is done, a bisection's
// result lies in (lower, upper]; `over` is then within (0, v_max], so ve_hi = over - tolerance,
// and rounding is monotone: ve_hi lies in [lower - tol, upper - tol] as computed.
bool def1_feasible(const ObservedTrace& t, std::size_t step, const GapIndices& gap, double rho, double margin_m) {
  const double v_max = t.road.speed_limit_mps;
  FirstTrue lo(0.0, v_max, holds_11(t, step, gap, rho, margin_m));
  FirstTrue over(0.0, v_max, fails_12(t, step, gap, rho, margin_m));
  for (;;) {
    if (lo.done() && over.done()) return lo.upper() <= ve_hi_of(over.upper(), v_max);
    const double hi_least = over.done() ? ve_hi_of(over.upper(), v_max) : over.lower() - kBisectionTolerance;
    const double hi_most = over.done() ? hi_least : over.upper() - kBisectionTolerance;
    if (lo.upper() <= hi_least) return true;                        // ve_lo <= lo.upper()
    if (lo.done() ? lo.upper() > hi_most : lo.lower() >= hi_most) return false;  // ve_lo > lo.lower()
    if (!lo.done()) lo.refine();
    if (!over.done()) over.refine();
  }
}

double def1_best_speed_mps(const ObservedTrace& t, std::size_t step, const GapIndices& gap, double rho) {
  const double v_max = t.road.speed_limit_mps;
  if (gap.follower < 1) return 0.0;     // only (1.2), which falls with v_e*
  if (gap.leader < 1) return v_max;     // only (1.1), which grows with v_e*
  const auto diff = [&](double v) {
    return def1_1_margin_m(t, step, gap.follower, v, rho) - def1_2_margin_m(t, step, gap.leader, v, rho);
  };
  const double v = first_true(0.0, v_max, [&](double s) { return diff(s) >= 0.0; });
  return std::min(v, v_max);
}

GapIndices gap_around_ego(const ObservedTrace& t, std::size_t step) {
  const auto& v = t.steps[step].vehicles;
  const double half_lane = 0.5 * t.road.lane_width_m;
  GapIndices g;
  for (std::size_t k = 1; k < v.size(); ++k) {
    if (std::abs(v[k].y_m) >= half_lane) continue;
    const int i = static_cast<int>(k);
    if (v[k].x_m <= v[0].x_m && (g.follower < 0 || v[k].x_m > v[static_cast<std::size_t>(g.follower)].x_m)) g.follower = i;
    if (v[k].x_m > v[0].x_m && (g.leader < 0 || v[k].x_m < v[static_cast<std::size_t>(g.leader)].x_m)) g.leader = i;
  }
  return g;
}

std::vector<GapIndices> lane_gaps(const ObservedTrace& t, std::size_t step) {
  const auto& v = t.steps[step].vehicles;
  std::vector<int> lane;
  for (std::size_t k = 1; k < v.size(); ++k)
    if (std::abs(v[k].y_m) < 0.5 * t.road.lane_width_m) lane.push_back(static_cast<int>(k));
  std::sort(lane.begin(), lane.end(),
            [&](int a, int b) { return v[static_cast<std::size_t>(a)].x_m < v[static_cast<std::size_t>(b)].x_m; });
  std::vector<GapIndices> out;
  for (std::size_t g = 0; g <= lane.size(); ++g)
    out.push_back({g == 0 ? -1 : lane[g - 1], g == lane.size() ? -1 : lane[g]});
  return out;
}

}  // namespace mg
