#include "rules/feasible_gaps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "core/merge_duration.h"
#include "core/rss.h"
#include "rules/definition1_gap.h"
#include "rules/monitor.h"

namespace mg {

namespace {

// Where lane vehicle k is rho_s from now: braking at its observed deceleration, if any, to a stop,
// else at its speed; and no farther than where the vehicle ahead of it (gaps[g + 1].leader, and so
// on up the lane) then is, less half their lengths: it cannot drive through it. A leader behind a
// vehicle racing toward a stopped one must brake for the stopped one, not for where the racing one
// would be at its speed (a campaign finding: the rule offered the gap behind such a leader while
// the planner, predicting the chain, found every merge into it blocked).
double end_x_m(const ObservedTrace& t, std::size_t step, const std::vector<GapIndices>& gaps, std::size_t g,
               double rho_s) {
  const auto& v = t.steps[step].vehicles;
  const auto own_end_m = [&](std::size_t k) {
    const ObservedState& s = v[k];
    return s.x_m + speed_change_distance_m(std::max(s.vx_mps, 0.0), 0.0, 0.0, std::max(-s.accel_mps2, 0.0), rho_s);
  };
  // From the front of the lane back to gaps[g].leader.
  std::size_t front = g;
  while (front + 1 < gaps.size() && gaps[front + 1].leader >= 1) ++front;
  double end_m = own_end_m(static_cast<std::size_t>(gaps[front].leader));
  for (std::size_t j = front; j > g; --j) {
    const std::size_t k = static_cast<std::size_t>(gaps[j - 1].leader), ahead = static_cast<std::size_t>(gaps[j].leader);
    end_m = std::min(own_end_m(k), end_m - 0.5 * (t.vehicles[k].size.length_m + t.vehicles[ahead].size.length_m));
  }
  return end_m;
}

}  // namespace

bool leader_holds_speed(const ObservedTrace& t, const RuleParams& p, std::size_t step,
                        const std::vector<GapIndices>& gaps, std::size_t g, double rho_s) {
  const GapIndices& gap = gaps[g];
  if (gap.leader < 1) return true;
  const auto& v = t.steps[step].vehicles;
  const ObservedState& l = v[static_cast<std::size_t>(gap.leader)];
  if (l.accel_mps2 < -p.progress_leader_braking_mps2) return false;
  if (g + 1 >= gaps.size() || gaps[g + 1].leader < 1) return true;
  const std::size_t li = static_cast<std::size_t>(gap.leader), ai = static_cast<std::size_t>(gaps[g + 1].leader);
  const ObservedState& a = v[ai];
  const double va = std::max(a.vx_mps, 0.0), vl = std::max(l.vx_mps, 0.0);
  const double a_end_m = end_x_m(t, step, gaps, g + 1, rho_s);
  const double d_lon_m = rss_longitudinal_m({vl, va, t.vehicles[li].size.length_m, t.vehicles[ai].size.length_m,
                                             t.params.rss.response_time_s, t.vehicles[li].limits.accel_max_mps2,
                                             t.vehicles[li].limits.brake_min_mps2, t.vehicles[ai].limits.brake_max_mps2});
  return a_end_m - (l.x_m + vl * rho_s) >= d_lon_m;
}

namespace {

// Definition 1.1 counts on the gap's follower accelerating at most at its declared a_accel^max. A
// follower seen accelerating harder (beyond accel_tolerance_mps2: declared_limits holds it liable)
// voids that: the gap in front of it closes faster than the definition bounds, and an ego that
// does not merge into it is not letting a right of way pass.
bool follower_within_limits(const ObservedTrace& t, const RuleParams& p, std::size_t step, const GapIndices& gap) {
  if (gap.follower < 1) return true;
  const std::size_t f = static_cast<std::size_t>(gap.follower);
  // Written as "not beyond" so that a NaN acceleration excuses no wait (a loaded trace holds none).
  return !(t.steps[step].vehicles[f].accel_mps2 > t.vehicles[f].limits.accel_max_mps2 + p.accel_tolerance_mps2);
}

// The merge a gap's feasibility is shown with, judged along its whole duration, not only at
// rho / 2 and rho: the ego's centre follows the paper's sigmoid (RCPP §IV), a logistic in X, from
// its observed position to the target lane's centre, through its middle at the X the ego reaches
// at rho / 2, while its speed changes from the observed one toward v_e* at its declared rates
// (WitnessPath). At every one of kWitnessSamples + 1 instants at which the ego is laterally nearer
// a vehicle than RCPP eq. (2) (the judge's lateral RSS distance, with the ego's lateral speed on
// the path) plus progress_lateral_margin_m, it must be RCPP eq. (1)'s D_lon plus
// progress_gap_margin_m clear of it: behind every vehicle ahead of it, of the target lane at its
// observed speed (as Def. 1.2 takes the leader), of the lane beyond where braking at its b_max
// from now puts it (no part of the gap, it may brake legally while the ego is near it, and the
// ego's RSS response would then take it off its merge in mid-lane change, which sigmoid_pc_bounds
// holds against the ego), and, until rho / 2 (P_c), ahead of every target-lane vehicle behind it,
// which may accelerate at its a_accel^max (Def. 1.1). A gap that ineq. (1)/(2) admit at rho / 2
// and rho alone can still have the merge enter the RSS danger the distance rules fail on (a
// leader passing the ego, a vehicle of the lane beyond): the rule demands no merge the other rules
// would then fail. The lateral margin is the tracking slack a driven merge needs: no controller
// follows its reference path to the centimetre.
constexpr int kWitnessSamples = 40;
static_assert(kWitnessSamples % 2 == 0, "instant kWitnessSamples / 2 is the midpoint, rho / 2");
// The witness's peak lateral acceleration, bracketed by its kWitnessSamples + 1 instants, is
// refined by this many steps of a ternary search (the peak is narrow: the instants alone could
// miss it by several per cent).
constexpr int kComfortRefinements = 12;

// The paper's sigmoid starts (its heading along the road) at this fraction of the lane change, as
// RCPP's planner draws it (2 % to 98 % of W); shortest_turn_in_m starts it there too.
constexpr double kSigmoidStartFraction = 0.02;
double logit(double f) { return std::log(f / (1.0 - f)); }

// Two witnesses per duration: the logistic cut at kSigmoidStartFraction (c = 2 logit(0.98) = 2 ln 49,
// the paper's sigmoid from its 2 % point, as RCPP draws it) and a steeper one (c = 10) that crosses
// the zone of lateral closeness sooner. A flatter cut starts with a larger jump of lateral speed
// (it begins farther up the logistic) and is no merge a planner draws.
const std::array<double, 2>& witness_steepness() {
  static const std::array<double, 2> c{2.0 * logit(1.0 - kSigmoidStartFraction), 10.0};
  return c;
}

// The witness's speed profile (one duration rho and v_e*), shared by both steepnesses: from the
// ego's observed speed toward v_e* at its declared a_accel^max / a_brake^min, with the distance
// covered and the speed at the kWitnessSamples + 1 instants tau = rho k / kWitnessSamples.
class WitnessSpeed {
 public:
  WitnessSpeed(const Limits& el, double v0_mps, double ve_mps, double rho_s)
      : el_(el), v0_mps_(v0_mps), ve_mps_(ve_mps), rho_s_(rho_s) {
    for (int k = 0; k <= kWitnessSamples; ++k) {
      const double tau = tau_s(k);
      distance_m_[static_cast<std::size_t>(k)] = distance_m(tau);
      speed_mps_[static_cast<std::size_t>(k)] = speed_mps(tau);
    }
  }
  double tau_s(int k) const { return rho_s_ * k / kWitnessSamples; }
  double distance_m(int k) const { return distance_m_[static_cast<std::size_t>(k)]; }
  double speed_mps(int k) const { return speed_mps_[static_cast<std::size_t>(k)]; }
  double distance_m(double tau_s) const {
    return speed_change_distance_m(v0_mps_, ve_mps_, el_.accel_max_mps2, el_.brake_min_mps2, tau_s);
  }
  double speed_mps(double tau_s) const {
    return ve_mps_ >= v0_mps_ ? std::min(ve_mps_, v0_mps_ + el_.accel_max_mps2 * tau_s)
                              : std::max(ve_mps_, v0_mps_ - el_.brake_min_mps2 * tau_s);
  }
  double accel_mps2(double tau_s) const {
    if (ve_mps_ >= v0_mps_) return v0_mps_ + el_.accel_max_mps2 * tau_s < ve_mps_ ? el_.accel_max_mps2 : 0.0;
    return v0_mps_ - el_.brake_min_mps2 * tau_s > ve_mps_ ? -el_.brake_min_mps2 : 0.0;
  }
  double top_speed_mps() const { return std::max(v0_mps_, ve_mps_); }
  // The magnitude of the speed change's rate (0 when v_e* is the observed speed).
  double top_accel_mps2() const {
    return ve_mps_ > v0_mps_ ? el_.accel_max_mps2 : ve_mps_ < v0_mps_ ? el_.brake_min_mps2 : 0.0;
  }

 private:
  const Limits& el_;
  double v0_mps_, ve_mps_, rho_s_;
  std::array<double, kWitnessSamples + 1> distance_m_{}, speed_mps_{};
};

// One witness merge (one duration rho, steepness c and v_e*), in X as the paper draws it: the
// logistic of steepness kappa centred at X_mid = X(rho / 2), cut at the ego's X now and at X(rho)
// and rescaled to run from its observed Y to the target lane's centre (Y = 0). kappa = (c / 2) /
// the shorter half: with c = 2 ln 49 the logistic spans 2 % to 98 % over the shorter half, as
// RCPP's planner bounds its kappa by both halves, and the longer half runs flat at its end. Its
// lateral acceleration is the path's, driven on the speed profile: Y''(X) v^2 + Y'(X) a. A
// sigmoid in time instead would put the steep part of an accelerating merge at its mean speed
// rather than at the higher speed the ego drives it at, and demand merges no planner that draws
// the paper's path can take within the comfort bound.
class WitnessPath {
 public:
  struct At {
    double x_m, v_mps, y_m, vy_mps;
  };
  WitnessPath(const ObservedState& ego, const WitnessSpeed& speed, double c) : speed_(speed) {
    x0_m_ = ego.x_m;
    y0_m_ = ego.y_m;
    const double first_m = speed.distance_m(kWitnessSamples / 2), second_m = speed.distance_m(kWitnessSamples) - first_m;
    x_mid_m_ = x0_m_ + first_m;
    kappa_per_m_ = 0.5 * c / std::min(first_m, second_m);
    l0_ = logistic(x0_m_);
    span_ = logistic(x0_m_ + first_m + second_m) - l0_;
  }
  double tau_s(int k) const { return speed_.tau_s(k); }
  // The ego on the witness at instant k (tau = rho k / kWitnessSamples).
  At at(int k) const {
    const double x = x0_m_ + speed_.distance_m(k), v = speed_.speed_mps(k);
    const double l = logistic(x);
    return {x, v, y0_m_ * (1.0 - (l - l0_) / span_), slope(l) * v};
  }
  // The peak curvature of its path, |Y''| at its steepest (small slopes, as for shortest_turn_in_m):
  // |Y0| kappa^2 / (6 sqrt 3 span).
  double peak_curvature_per_m() const { return std::abs(y0_m_) * kappa_per_m_ * kappa_per_m_ / (6.0 * std::sqrt(3.0) * span_); }
  // |Y''(X) v^2 + Y'(X) a| at most limit_mps2 over the whole merge: by its bound when that
  // suffices, else at the kWitnessSamples + 1 instants and, around the largest, by
  // kComfortRefinements steps of a ternary search between the instants next to it (the lateral
  // acceleration has one peak per half of the merge, which its samples bracket). The bound:
  // |Y''| v^2 + |Y'| |a| = |Y0| kappa / span * l (1 - l) (A |1 - 2 l| + B) with A = kappa v_max^2
  // and B the speed change's rate; with u = |1 - 2 l| that is (1 - u^2) (A u + B) / 4, largest at
  // u = (sqrt(B^2 + 3 A^2) - B) / (3 A). Written as "within" so that a degenerate path (no
  // distance to a half: kappa infinite, a NaN) is no comfortable merge.
  bool comfortable(double limit_mps2) const {
    const double v_max = speed_.top_speed_mps();
    const double A = kappa_per_m_ * v_max * v_max, B = speed_.top_accel_mps2();
    const double u = A > 0.0 ? (std::sqrt(B * B + 3.0 * A * A) - B) / (3.0 * A) : 0.0;
    const double bound = std::abs(y0_m_) * kappa_per_m_ / span_ * 0.25 * (1.0 - u * u) * (A * u + B);
    if (bound <= limit_mps2) return true;
    if (!std::isfinite(bound)) return false;
    int k_peak = 0;
    double peak = -1.0;
    for (int k = 0; k <= kWitnessSamples; ++k) {
      const double a = lat_accel_mps2(speed_.tau_s(k), logistic(x0_m_ + speed_.distance_m(k)), speed_.speed_mps(k));
      if (!(a <= limit_mps2)) return false;
      if (a > peak) peak = a, k_peak = k;
    }
    double lo = speed_.tau_s(std::max(k_peak - 1, 0)), hi = speed_.tau_s(std::min(k_peak + 1, kWitnessSamples));
    for (int i = 0; i < kComfortRefinements; ++i) {
      const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
      const double a1 = lat_accel_mps2(m1, logistic(x0_m_ + speed_.distance_m(m1)), speed_.speed_mps(m1));
      const double a2 = lat_accel_mps2(m2, logistic(x0_m_ + speed_.distance_m(m2)), speed_.speed_mps(m2));
      if (!(a1 <= limit_mps2 && a2 <= limit_mps2)) return false;
      if (a1 < a2) lo = m1;
      else hi = m2;
    }
    return true;
  }

 private:
  // |Y''(X) v^2 + Y'(X) a| tau_s into the merge, where the logistic is at l and the speed v_mps.
  double lat_accel_mps2(double tau_s, double l, double v_mps) const {
    const double y_xx = -y0_m_ * kappa_per_m_ * kappa_per_m_ * l * (1.0 - l) * (1.0 - 2.0 * l) / span_;
    return std::abs(y_xx * v_mps * v_mps + slope(l) * speed_.accel_mps2(tau_s));
  }
  double logistic(double x_m) const { return 1.0 / (1.0 + std::exp(-kappa_per_m_ * (x_m - x_mid_m_))); }
  double slope(double l) const { return -y0_m_ * kappa_per_m_ * l * (1.0 - l) / span_; }  // dY/dX
  const WitnessSpeed& speed_;
  double x0_m_ = 0.0, y0_m_ = 0.0, x_mid_m_ = 0.0, kappa_per_m_ = 0.0, l0_ = 0.0, span_ = 1.0;
};

// Every instant of the witness against every vehicle: where the ego is laterally nearer it than
// RCPP eq. (2) plus progress_lateral_margin_m, D_lon plus progress_gap_margin_m behind a vehicle
// ahead (of the target lane at its observed speed, of the lane beyond braking at its b_max from
// now), and until rho / 2 ahead of a target-lane vehicle behind (accelerating at its a_accel^max).
bool witness_merge_clear(const ObservedTrace& t, const RuleParams& p, std::size_t step, const WitnessPath& path) {
  const auto& v = t.steps[step].vehicles;
  const Limits& el = t.vehicles[0].limits;
  const double T = t.params.rss.response_time_s;
  const double half_lane = 0.5 * t.road.lane_width_m;
  const double ego_half_width_m = 0.5 * size_of(t, 0).width_m;
  // Every instant must be clear, so the order is free: from the midpoint back to the start, then
  // on to the end. The ego is laterally near the target lane's vehicles around its midpoint, where
  // most witnesses that are not clear fail, after a few instants.
  for (int j = 0; j <= kWitnessSamples; ++j) {
    const int k = j <= kWitnessSamples / 2 ? kWitnessSamples / 2 - j : j;
    const double tau = path.tau_s(k);
    const WitnessPath::At e = path.at(k);
    // RCPP eq. (2) is mu + (w_L + w_R) / 2 + a term of the lateral speeds alone: that term, for a
    // vehicle on either side of the ego, once per instant (eq. (2) with no widths).
    const auto d_lat_no_widths = [&](bool o_left) {
      return rss_lateral_m({o_left ? 0.0 : e.vy_mps, o_left ? e.vy_mps : 0.0, 0.0, 0.0, T, el.lat_accel_max_mps2,
                            el.lat_brake_min_mps2, t.params.rss.fluctuation_margin_m});
    };
    const double d_lat_left = d_lat_no_widths(true), d_lat_right = d_lat_no_widths(false);
    for (std::size_t o = 1; o < v.size(); ++o) {
      const ObservedState& ov = v[o];
      const bool o_left = ov.y_m >= e.y_m;
      const double d_lat = (o_left ? d_lat_left : d_lat_right) + ego_half_width_m + 0.5 * size_of(t, o).width_m;
      // Written as "clear" so that a NaN lateral distance counts as near: judged, not skipped.
      if (std::abs(ov.y_m - e.y_m) >= d_lat + p.progress_lateral_margin_m) continue;
      const double vo = std::max(ov.vx_mps, 0.0);
      const double xo = ov.x_m + vo * tau;
      const bool target_lane = std::abs(ov.y_m) < half_lane;
      if (xo >= e.x_m) {  // ahead: the ego is the rear vehicle
        // A vehicle of the lane beyond may brake at its b_max at any time while the ego is near it
        // (the comment above): kept behind where that braking from now puts it.
        double xa = xo, va = vo;
        if (!target_lane) {
          const double b = std::max(limits_of(t, o).brake_max_mps2, -ov.accel_mps2);
          xa = ov.x_m + speed_change_distance_m(vo, 0.0, 0.0, b, tau);
          va = std::max(0.0, vo - b * tau);
        }
        const double d_lon = rss_longitudinal_m({e.v_mps, va, size_of(t, 0).length_m, size_of(t, o).length_m, T,
                                                 el.accel_max_mps2, el.brake_min_mps2, limits_of(t, o).brake_max_mps2});
        if (!(xa - e.x_m >= d_lon + p.progress_gap_margin_m)) return false;
        continue;
      }
      if (!target_lane || k > kWitnessSamples / 2) continue;  // past P_c the follower keeps D_lon
      const Limits& ol = limits_of(t, o);
      const double xf = ov.x_m + vo * tau + 0.5 * ol.accel_max_mps2 * tau * tau;
      const double vf = vo + ol.accel_max_mps2 * tau;
      const double d_lon = rss_longitudinal_m({vf, e.v_mps, size_of(t, o).length_m, size_of(t, 0).length_m, T,
                                               ol.accel_max_mps2, ol.brake_min_mps2, el.brake_max_mps2});
      if (!(e.x_m - xf >= d_lon + p.progress_gap_margin_m)) return false;
    }
  }
  return true;
}

// Past the side lane's end the road's right edge is the lane line (on_road): on the witness, a
// corner of the ego's body that comes within progress_gap_margin_m of the end (or past it) must
// be across the line, Y >= -W/2, with the body on the path's heading. A merge whose midpoint
// alone is short of the end could leave the rear of the body in the side lane past it: the ego
// would have had to leave the road to take it.
bool witness_leaves_side_lane(const ObservedTrace& t, const RuleParams& p, const WitnessPath& path) {
  const VehicleSize& size = t.vehicles[0].size;
  const double hl = 0.5 * size.length_m, hw = 0.5 * size.width_m;
  const double limit_x = t.road.side_lane_end_x_m - p.progress_gap_margin_m;
  const double line_y = -0.5 * t.road.lane_width_m;
  if (path.at(kWitnessSamples).x_m + hl < limit_x) return true;  // the front is still short of it when the merge ends
  for (int k = 0; k <= kWitnessSamples; ++k) {
    const WitnessPath::At e = path.at(k);
    if (e.x_m + hl < limit_x) continue;
    const double psi = std::atan2(e.vy_mps, std::max(e.v_mps, 1e-6));
    const double cs = std::cos(psi), sn = std::sin(psi);
    for (const double sl : {-1.0, 1.0}) {  // the rear and front right corners (the left ones are higher)
      const double corner_x = e.x_m + sl * hl * cs + hw * sn;
      const double corner_y = e.y_m + sl * hl * sn - hw * cs;
      // Written as "not across" so that a NaN counts against the witness.
      if (corner_x >= limit_x && !(corner_y >= line_y)) return false;
    }
  }
  return hw <= -line_y;  // after rho: on the lane centre, heading along the road
}

}  // namespace

// RCPP §IV: the merge path is a sigmoid (a logistic across the lanes) driven within the sideslip
// rule, |beta| <= sideslip_max_rad. A driven path is tracked with some overshoot of its curvature,
// so a merge the rule demands keeps within progress_sideslip_fraction of the bound (tracking slack,
// as progress_lateral_margin_m is for the lateral position): a path at the whole bound can be
// taken only by breaking `sideslip`. Its curvature is then at most c = tan(f beta_max) / l_r
// (kinematic sideslip atan(l_r c)). l_r, the centre of gravity's distance to the rear axle, is not
// declared; half the ego's length bounds it from above, so c is the smallest any car may need. A
// logistic of amplitude A (the ego's Y to the target lane's centre) and steepness kappa has peak
// curvature A kappa^2 / (6 sqrt 3) at small slopes, so the steepest within the bound has kappa =
// sqrt(6 sqrt 3 c / A). The turn-in is the X it takes from a heading along the road (its
// kSigmoidStartFraction point) to the lane line: (logit(f_line) - logit(start)) / kappa, f_line =
// (-W/2 - Y) / A. One arc of the same curvature would reach the line sooner, but it arrives
// turned across the lane and is no merge the paper's planner draws.
namespace {

// The steepest logistic of amplitude |y_m| whose peak curvature stays within that share of the
// sideslip bound (above), and where the lane line lies on it (f_line, the fraction of the lane change).
struct SteepestSigmoid {
  double kappa_per_m = 0.0;
  double f_line = 0.0;
};
// c = tan(progress_sideslip_fraction sideslip_max_rad) / (l_e / 2): the sharpest curvature of a
// merge the rule demands (above).
double curvature_cap_per_m(const ObservedTrace& t, const RuleParams& p) {
  return std::tan(p.progress_sideslip_fraction * p.sideslip_max_rad) / (0.5 * t.vehicles[0].size.length_m);
}

SteepestSigmoid steepest_sigmoid(const ObservedTrace& t, const RuleParams& p, double y_m) {
  const double amplitude_m = std::abs(y_m);
  const double c = curvature_cap_per_m(t, p);
  return {std::sqrt(6.0 * std::sqrt(3.0) * c / amplitude_m), (-0.5 * t.road.lane_width_m - y_m) / amplitude_m};
}

}  // namespace

double shortest_turn_in_m(const ObservedTrace& t, const RuleParams& p, double y_m) {
  if (y_m >= -0.5 * t.road.lane_width_m || y_m == 0.0) return 0.0;
  const SteepestSigmoid s = steepest_sigmoid(t, p, y_m);
  if (s.f_line <= kSigmoidStartFraction) return 0.0;
  return (logit(s.f_line) - logit(kSigmoidStartFraction)) / s.kappa_per_m;
}

// The witness completes its merge by rho: a second half shorter than this turns back along the
// lane more sharply than that share of the sideslip bound allows.
double shortest_turn_out_m(const ObservedTrace& t, const RuleParams& p, double y_m) {
  if (y_m >= -0.5 * t.road.lane_width_m || y_m == 0.0) return 0.0;
  const SteepestSigmoid s = steepest_sigmoid(t, p, y_m);
  const double f_line = std::clamp(s.f_line, kSigmoidStartFraction, 1.0 - kSigmoidStartFraction);
  return (logit(1.0 - kSigmoidStartFraction) - logit(f_line)) / s.kappa_per_m;
}

namespace {

// Some v_e* of the interval, its midpoint within the turn-in and the room, whose witness merge
// (WitnessPath, either steepness, its peak curvature within curvature_cap_per_m and its peak
// lateral acceleration within progress_lat_accel_max_mps2) is clear along its whole duration. The
// turn-in bounds where the midpoint may lie; the steeper cut (c = 10) over the same first half is
// sharper than that, and is a merge the rule demands only where its own curvature keeps within
// the cap.
constexpr int kWitnessSpeeds = 8;
// The turn-in and the room bound the distance to the midpoint, the turn-out the distance from the
// midpoint to the merge's end, the curvature cap the witness's path.
struct WitnessRoom {
  double turn_in_m, room_m, turn_out_m, curvature_cap_per_m;
};
template <class ToMid, class ToEnd>
bool witness_exists(const ObservedTrace& t, const RuleParams& p, std::size_t step, double rho, const Def1Interval& in,
                    const ToMid& to_mid_m, const ToEnd& to_end_m, const WitnessRoom& r) {
  for (int j = 0; j <= kWitnessSpeeds; ++j) {
    const double ve = in.ve_lo_mps + (in.ve_hi_mps - in.ve_lo_mps) * j / kWitnessSpeeds;
    const double mid = to_mid_m(ve);
    if (mid < r.turn_in_m || mid > r.room_m || to_end_m(ve) - mid < r.turn_out_m) continue;
    const ObservedState& ego = t.steps[step].vehicles[0];
    const WitnessSpeed speed(t.vehicles[0].limits, std::max(ego.vx_mps, 0.0), ve, rho);
    for (const double c : witness_steepness()) {
      const WitnessPath path(ego, speed, c);
      // Written as "within" so that a NaN curvature is no merge.
      if (!(path.peak_curvature_per_m() <= r.curvature_cap_per_m)) continue;
      if (!path.comfortable(p.progress_lat_accel_max_mps2)) continue;
      if (!witness_leaves_side_lane(t, p, path)) continue;
      if (witness_merge_clear(t, p, step, path)) return true;
    }
  }
  return false;
}

}  // namespace

std::vector<FeasibleMerge> def1_gaps_feasible(const ObservedTrace& t, const RuleParams& p, std::size_t step) {
  const auto& v = t.steps[step].vehicles;
  const double margin = p.progress_gap_margin_m;
  const Limits& ego = t.vehicles[0].limits;
  const double v0 = std::max(v[0].vx_mps, 0.0);
  // The midpoint (the centre on the lane line) at least the turn-in ahead, and the front still
  // `margin` short of the side lane's end there (side_lane_end).
  // The second half at least the turn-out long.
  const WitnessRoom r{shortest_turn_in_m(t, p, v[0].y_m),
                      t.road.side_lane_end_x_m - margin - (v[0].x_m + 0.5 * t.vehicles[0].size.length_m),
                      shortest_turn_out_m(t, p, v[0].y_m), curvature_cap_per_m(t, p)};
  const auto id = [&](int k) { return k < 1 ? -1 : t.vehicles[static_cast<std::size_t>(k)].id; };
  std::vector<FeasibleMerge> out;
  if (r.room_m < r.turn_in_m) return out;
  const std::vector<GapIndices> gaps = lane_gaps(t, step);
  const double base_rho_s = merge_duration_base_s(p.merge_duration_s, t.road.lane_width_m, p.progress_lat_accel_max_mps2);
  // rho_m, or longer: a merge that observably takes longer holds the right of way on a reading
  // over its own duration (rules/merge_attempts.h). A declared rho_m shorter than the shortest
  // comfortable lane change is raised to it, as RCPP's planner raises it (core/merge_duration.h).
  // An ego so slow that even at its a_accel^max it cannot reach the turn-in by the midpoint of a
  // merge of 2 rho_b (from rest, a tracked path needs more room than it covers in rho_b) is
  // offered one of 3 rho_b too: it must first gain speed. Another is not: a long merge from
  // speed begins with seconds of straight driving toward a sigmoid start far ahead, which the
  // rule could not tell from waiting.
  const std::array<double, 4> durations_s{base_rho_s, 1.5 * base_rho_s, 2.0 * base_rho_s, 3.0 * base_rho_s};
  const double reach_2_rho_b_m = speed_change_distance_m(v0, t.road.speed_limit_mps, ego.accel_max_mps2, ego.brake_min_mps2, base_rho_s);
  const std::size_t n_durations = reach_2_rho_b_m < r.turn_in_m ? 4 : 3;
  for (std::size_t g = 0; g < gaps.size(); ++g) {
    const GapIndices& gap = gaps[g];
    if (!follower_within_limits(t, p, step, gap)) continue;
    for (std::size_t d = 0; d < n_durations; ++d) {
      const double rho = durations_s[d];
      if (!leader_holds_speed(t, p, step, gaps, g, rho)) continue;
      // def1_feasible is def1_interval's feasibility exactly, at a fraction of its bisections;
      // raising ve_lo below can only narrow the interval.
      if (!def1_feasible(t, step, gap, rho, margin)) continue;
      Def1Interval in = def1_interval(t, step, gap, rho, margin);
      in.ve_lo_mps = std::max(in.ve_lo_mps, p.progress_min_merge_speed_mps);
      if (!in.feasible()) continue;
      // Changing speed from the observed one toward v_e* (the bounded-rate model): the distance to
      // the midpoint grows with v_e*, so some v_e* of the interval fits iff its ends bracket it.
      const auto to_mid_m = [&](double ve) {
        return speed_change_distance_m(v0, ve, ego.accel_max_mps2, ego.brake_min_mps2, 0.5 * rho);
      };
      const auto to_end_m = [&](double ve) {
        return speed_change_distance_m(v0, ve, ego.accel_max_mps2, ego.brake_min_mps2, rho);
      };
      // Both halves grow with v_e* (its speed profile is higher at every instant).
      if (to_mid_m(in.ve_hi_mps) < r.turn_in_m || to_mid_m(in.ve_lo_mps) > r.room_m ||
          to_end_m(in.ve_hi_mps) - to_mid_m(in.ve_hi_mps) < r.turn_out_m)
        continue;
      if (!witness_exists(t, p, step, rho, in, to_mid_m, to_end_m, r)) continue;
      out.push_back({id(gap.follower), id(gap.leader), rho, in.ve_lo_mps, in.ve_hi_mps});
      break;
    }
  }
  return out;
}

}  // namespace mg
