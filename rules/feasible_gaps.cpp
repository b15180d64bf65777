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

// Definition 1.2 counts on the gap's leader holding its speed. A leader seen braking harder than
// progress_leader_braking_mps2 does not, nor one closing on the vehicle ahead of it in its lane so
// fast that, holding its speed over rho, it would come within that vehicle's D_lon (RCPP eq. (1);
// RSS Def. 1): it must slow down for it, and the gap behind it shrinks as it does.
bool leader_holds_speed(const ObservedTrace& t, const RuleParams& p, std::size_t step, const GapIndices& gap,
                        const GapIndices& ahead, double rho_s) {
  if (gap.leader < 1) return true;
  const auto& v = t.steps[step].vehicles;
  const ObservedState& l = v[static_cast<std::size_t>(gap.leader)];
  if (l.accel_mps2 < -p.progress_leader_braking_mps2) return false;
  if (ahead.leader < 1) return true;
  const ObservedState& a = v[static_cast<std::size_t>(ahead.leader)];
  const std::size_t li = static_cast<std::size_t>(gap.leader), ai = static_cast<std::size_t>(ahead.leader);
  const double va = std::max(a.vx_mps, 0.0), vl = std::max(l.vx_mps, 0.0);
  const double a_end_m = a.x_m + speed_change_distance_m(va, 0.0, 0.0, std::max(-a.accel_mps2, 0.0), rho_s);
  const double d_lon_m = rss_longitudinal_m({vl, va, t.vehicles[li].size.length_m, t.vehicles[ai].size.length_m,
                                             t.params.rss.response_time_s, t.vehicles[li].limits.accel_max_mps2,
                                             t.vehicles[li].limits.brake_min_mps2, t.vehicles[ai].limits.brake_max_mps2});
  return a_end_m - (l.x_m + vl * rho_s) >= d_lon_m;
}

// The merge a gap's feasibility is shown with, judged along its whole duration, not only at
// rho / 2 and rho: the ego's centre follows the paper's sigmoid (RCPP §IV) in time, from its
// observed Y at the start to the target lane's centre at rho through the midpoint at rho / 2
// (the logistic of steepness c / rho, witness_steepness, cut at 0 and rho and rescaled), while
// its speed changes from the observed one toward v_e* at its declared rates. At every one of
// kWitnessSamples + 1 instants at which the ego is laterally nearer a vehicle than RCPP eq. (2)
// (the judge's lateral RSS distance, with the ego's lateral speed on the path) plus
// progress_lateral_margin_m, it must be RCPP eq. (1)'s D_lon plus progress_gap_margin_m clear of
// it: behind every vehicle ahead of it, of the target lane at its observed speed (as Def. 1.2
// takes the leader), of the lane beyond where braking at its b_max from now puts it (no part of
// the gap, it may brake legally while the ego is near it, and the ego's RSS response would then
// take it off its merge in mid-lane change, which sigmoid_pc_bounds holds against the ego), and,
// until rho / 2 (P_c), ahead of every target-lane vehicle behind it, which may accelerate at its
// a_accel^max (Def. 1.1). A gap that
// ineq. (1)/(2) admit at rho / 2 and rho alone can still have the merge enter the RSS danger the
// distance rules fail on (a leader passing the ego, a vehicle of the lane beyond): the rule
// demands no merge the other rules would then fail. The lateral margin is the tracking slack a
// driven merge needs: no controller follows its reference path to the centimetre.
constexpr int kWitnessSamples = 40;

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

// The logistic of steepness c over u in [0, 1], centred at u = 1/2, and the rise of its cut.
struct CutLogistic {
  double c;
  double at(double u) const { return 1.0 / (1.0 + std::exp(-c * (u - 0.5))); }
  double span() const { return at(1.0) - at(0.0); }
};

// The witness's peak lateral acceleration: y'' = -y0 (c/rho)^2 l(1-l)(1-2l) / span, and
// |l(1-l)(1-2l)| peaks at 1/(6 sqrt 3) (within the cut for c > 2.6). A merge above
// progress_lat_accel_max_mps2 is not offered: a comfortable lane change is what the rule demands.
double witness_peak_lat_accel_mps2(double y0_m, double rho_s, double c) {
  return std::abs(y0_m) * c * c / (6.0 * std::sqrt(3.0) * CutLogistic{c}.span() * rho_s * rho_s);
}

// The witness's speed tau_s in: from v0 toward ve at the ego's declared a_accel^max / a_brake^min.
double witness_speed_mps(const Limits& el, double v0, double ve, double tau_s) {
  return ve >= v0 ? std::min(ve, v0 + el.accel_max_mps2 * tau_s) : std::max(ve, v0 - el.brake_min_mps2 * tau_s);
}

struct WitnessLateral {
  double y_m, vy_mps;
};
// The witness's Y and lateral speed at tau_s, of the cut logistic `logistic` with its value at
// u = 0 `l0` and its rise `span` (both constant per steepness, computed once per witness).
WitnessLateral witness_lateral(double y0_m, double rho_s, const CutLogistic& logistic, double l0, double span,
                               double tau_s) {
  const double l = logistic.at(tau_s / rho_s);
  const double frac = (l - l0) / span;
  return {y0_m * (1.0 - frac), -y0_m * logistic.c * l * (1.0 - l) / (rho_s * span)};
}

// The lateral half of a witness merge (one duration, one steepness), which does not depend on
// v_e*: the instants at which the ego on the witness path is laterally nearer a vehicle than
// RCPP eq. (2) plus progress_lateral_margin_m, with the vehicle, in instant order.
// witness_merge_clear then judges only these (instant, vehicle) pairs for each v_e*.
struct NearPair {
  int k;          // instant index, tau = rho k / kWitnessSamples
  std::size_t o;  // vehicle index
};
std::vector<NearPair> witness_near_pairs(const ObservedTrace& t, const RuleParams& p, std::size_t step, double rho,
                                         double c) {
  const auto& v = t.steps[step].vehicles;
  const ObservedState& ego = v[0];
  const Limits& el = t.vehicles[0].limits;
  const double T = t.params.rss.response_time_s;
  const CutLogistic logistic{c};
  const double l0 = logistic.at(0.0), span = logistic.span();
  std::vector<NearPair> near;
  for (int k = 0; k <= kWitnessSamples; ++k) {
    const WitnessLateral lat = witness_lateral(ego.y_m, rho, logistic, l0, span, rho * k / kWitnessSamples);
    for (std::size_t o = 1; o < v.size(); ++o) {
      const ObservedState& ov = v[o];
      const bool o_left = ov.y_m >= lat.y_m;
      const double d_lat = rss_lateral_m({o_left ? 0.0 : lat.vy_mps, o_left ? lat.vy_mps : 0.0,
                                          size_of(t, o_left ? o : 0).width_m, size_of(t, o_left ? 0 : o).width_m, T,
                                          el.lat_accel_max_mps2, el.lat_brake_min_mps2,
                                          t.params.rss.fluctuation_margin_m});
      // Written as "not clear" so that a NaN lateral distance counts as near: judged, not skipped.
      if (!(std::abs(ov.y_m - lat.y_m) >= d_lat + p.progress_lateral_margin_m)) near.push_back({k, o});
    }
  }
  return near;
}

// The longitudinal half at v_e*: at every near pair, D_lon plus progress_gap_margin_m behind a
// vehicle ahead (of the target lane at its observed speed, of the lane beyond braking at its b_max
// from now), and until rho / 2 ahead of a target-lane vehicle behind (accelerating at its
// a_accel^max).
bool witness_merge_clear(const ObservedTrace& t, const RuleParams& p, std::size_t step, double rho, double ve,
                         const std::vector<NearPair>& near) {
  const auto& v = t.steps[step].vehicles;
  const ObservedState& ego = v[0];
  const Limits& el = t.vehicles[0].limits;
  const double v0 = std::max(ego.vx_mps, 0.0);
  const double T = t.params.rss.response_time_s;
  const double half_lane = 0.5 * t.road.lane_width_m;
  int at_k = -1;
  double tau = 0.0, x = 0.0, ve_now = 0.0;
  for (const NearPair& n : near) {
    if (n.k != at_k) {
      at_k = n.k;
      tau = rho * n.k / kWitnessSamples;
      x = ego.x_m + speed_change_distance_m(v0, ve, el.accel_max_mps2, el.brake_min_mps2, tau);
      ve_now = witness_speed_mps(el, v0, ve, tau);
    }
    const ObservedState& ov = v[n.o];
    const double vo = std::max(ov.vx_mps, 0.0);
    const double xo = ov.x_m + vo * tau;
    const bool target_lane = std::abs(ov.y_m) < half_lane;
    if (xo >= x) {  // ahead: the ego is the rear vehicle
      // A vehicle of the lane beyond may brake at its b_max at any time while the ego is near it
      // (witness_merge_clear's comment): kept behind where that braking from now puts it.
      double xa = xo, va = vo;
      if (!target_lane) {
        const double b = std::max(limits_of(t, n.o).brake_max_mps2, -ov.accel_mps2);
        xa = ov.x_m + speed_change_distance_m(vo, 0.0, 0.0, b, tau);
        va = std::max(0.0, vo - b * tau);
      }
      const double d_lon = rss_longitudinal_m({ve_now, va, size_of(t, 0).length_m, size_of(t, n.o).length_m, T,
                                               el.accel_max_mps2, el.brake_min_mps2, limits_of(t, n.o).brake_max_mps2});
      if (!(xa - x >= d_lon + p.progress_gap_margin_m)) return false;
      continue;
    }
    if (!target_lane || tau > 0.5 * rho + kTieS) continue;  // past P_c the follower keeps D_lon
    const Limits& ol = limits_of(t, n.o);
    const double xf = ov.x_m + vo * tau + 0.5 * ol.accel_max_mps2 * tau * tau;
    const double vf = vo + ol.accel_max_mps2 * tau;
    const double d_lon = rss_longitudinal_m({vf, ve_now, size_of(t, n.o).length_m, size_of(t, 0).length_m, T,
                                             ol.accel_max_mps2, ol.brake_min_mps2, el.brake_max_mps2});
    if (x - xf < d_lon + p.progress_gap_margin_m) return false;
  }
  return true;
}

// Past the side lane's end the road's right edge is the lane line (on_road): on the witness, a
// corner of the ego's body that comes within progress_gap_margin_m of the end (or past it) must
// be across the line, Y >= -W/2, with the body on the path's heading. A merge whose midpoint
// alone is short of the end could leave the rear of the body in the side lane past it: the ego
// would have had to leave the road to take it.
bool witness_leaves_side_lane(const ObservedTrace& t, const RuleParams& p, std::size_t step, double rho, double c,
                              double ve) {
  const ObservedState& ego = t.steps[step].vehicles[0];
  const Limits& el = t.vehicles[0].limits;
  const VehicleSize& size = t.vehicles[0].size;
  const double v0 = std::max(ego.vx_mps, 0.0);
  const double hl = 0.5 * size.length_m, hw = 0.5 * size.width_m;
  const double limit_x = t.road.side_lane_end_x_m - p.progress_gap_margin_m;
  const double line_y = -0.5 * t.road.lane_width_m;
  if (ego.x_m + speed_change_distance_m(v0, ve, el.accel_max_mps2, el.brake_min_mps2, rho) + hl < limit_x)
    return true;  // the front is still short of it when the merge ends
  const CutLogistic logistic{c};
  const double l0 = logistic.at(0.0), span = logistic.span();
  for (int k = 0; k <= kWitnessSamples; ++k) {
    const double tau = rho * k / kWitnessSamples;
    const double x = ego.x_m + speed_change_distance_m(v0, ve, el.accel_max_mps2, el.brake_min_mps2, tau);
    if (x + hl < limit_x) continue;
    const WitnessLateral lat = witness_lateral(ego.y_m, rho, logistic, l0, span, tau);
    const double psi = std::atan2(lat.vy_mps, std::max(witness_speed_mps(el, v0, ve, tau), 1e-6));
    const double cs = std::cos(psi), sn = std::sin(psi);
    for (const double sl : {-1.0, 1.0}) {  // the rear and front right corners (the left ones are higher)
      const double corner_x = x + sl * hl * cs + hw * sn;
      const double corner_y = lat.y_m + sl * hl * sn - hw * cs;
      // Written as "not across" so that a NaN counts against the witness.
      if (corner_x >= limit_x && !(corner_y >= line_y)) return false;
    }
  }
  return hw <= -line_y;  // after rho: on the lane centre, heading along the road
}

}  // namespace

// RCPP §IV: the merge path is a sigmoid (a logistic across the lanes) driven within the sideslip
// rule, |beta| <= sideslip_max_rad, so its curvature is at most c = tan(beta_max) / l_r
// (kinematic sideslip atan(l_r c)). l_r, the centre of gravity's distance to the rear axle, is not
// declared; half the ego's length bounds it from above, so c is the smallest any car may need. A
// logistic of amplitude A (the ego's Y to the target lane's centre) and steepness kappa has peak
// curvature A kappa^2 / (6 sqrt 3) at small slopes, so the steepest within the bound has kappa =
// sqrt(6 sqrt 3 c / A). The turn-in is the X it takes from a heading along the road (its
// kSigmoidStartFraction point) to the lane line: (logit(f_line) - logit(start)) / kappa, f_line =
// (-W/2 - Y) / A. One arc of the same curvature would reach the line sooner, but it arrives
// turned across the lane and is no merge the paper's planner draws.
namespace {

// The steepest logistic of amplitude |y_m| whose peak curvature stays within the sideslip bound
// (above), and where the lane line lies on it (f_line, the fraction of the lane change).
struct SteepestSigmoid {
  double kappa_per_m = 0.0;
  double f_line = 0.0;
};
SteepestSigmoid steepest_sigmoid(const ObservedTrace& t, const RuleParams& p, double y_m) {
  const double amplitude_m = std::abs(y_m);
  const double c = std::tan(p.sideslip_max_rad) / (0.5 * t.vehicles[0].size.length_m);
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
// lane more sharply than the sideslip bound allows.
double shortest_turn_out_m(const ObservedTrace& t, const RuleParams& p, double y_m) {
  if (y_m >= -0.5 * t.road.lane_width_m || y_m == 0.0) return 0.0;
  const SteepestSigmoid s = steepest_sigmoid(t, p, y_m);
  const double f_line = std::clamp(s.f_line, kSigmoidStartFraction, 1.0 - kSigmoidStartFraction);
  return (logit(1.0 - kSigmoidStartFraction) - logit(f_line)) / s.kappa_per_m;
}

namespace {

// Some v_e* of the interval, its midpoint within the turn-in and the room, whose witness merge
// (witness_merge_clear, either steepness within progress_lat_accel_max_mps2) is clear along its
// whole duration.
constexpr int kWitnessSpeeds = 8;
// The turn-in and the room bound the distance to the midpoint, the turn-out the distance from the
// midpoint to the merge's end.
struct WitnessRoom {
  double turn_in_m, room_m, turn_out_m;
};
template <class ToMid, class ToEnd>
bool witness_exists(const ObservedTrace& t, const RuleParams& p, std::size_t step, double rho, const Def1Interval& in,
                    const ToMid& to_mid_m, const ToEnd& to_end_m, const WitnessRoom& r) {
  // The steepnesses within the bound depend on the duration and the ego's Y only, not on v_e*.
  std::array<bool, 2> comfortable{};
  for (std::size_t k = 0; k < comfortable.size(); ++k)
    comfortable[k] = witness_peak_lat_accel_mps2(t.steps[step].vehicles[0].y_m, rho, witness_steepness()[k]) <=
                     p.progress_lat_accel_max_mps2;
  if (!comfortable[0] && !comfortable[1]) return false;
  std::array<std::optional<std::vector<NearPair>>, 2> near;  // built when first needed
  for (int j = 0; j <= kWitnessSpeeds; ++j) {
    const double ve = in.ve_lo_mps + (in.ve_hi_mps - in.ve_lo_mps) * j / kWitnessSpeeds;
    const double mid = to_mid_m(ve);
    if (mid < r.turn_in_m || mid > r.room_m || to_end_m(ve) - mid < r.turn_out_m) continue;
    for (std::size_t k = 0; k < comfortable.size(); ++k) {
      if (!comfortable[k]) continue;
      if (!witness_leaves_side_lane(t, p, step, rho, witness_steepness()[k], ve)) continue;
      if (!near[k]) near[k] = witness_near_pairs(t, p, step, rho, witness_steepness()[k]);
      if (witness_merge_clear(t, p, step, rho, ve, *near[k])) return true;
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
                      shortest_turn_out_m(t, p, v[0].y_m)};
  const auto id = [&](int k) { return k < 1 ? -1 : t.vehicles[static_cast<std::size_t>(k)].id; };
  std::vector<FeasibleMerge> out;
  if (r.room_m < r.turn_in_m) return out;
  const std::vector<GapIndices> gaps = lane_gaps(t, step);
  const double base_rho_s = merge_duration_base_s(p.merge_duration_s, t.road.lane_width_m, p.progress_lat_accel_max_mps2);
  for (std::size_t g = 0; g < gaps.size(); ++g) {
    const GapIndices& gap = gaps[g];
    const GapIndices ahead = g + 1 < gaps.size() ? gaps[g + 1] : GapIndices{};
    // rho_m, or longer: a merge that observably takes longer holds the right of way on a reading
    // over its own duration (rules/merge_attempts.h), and from low speed only a longer one
    // reaches a midpoint the turn-in allows. A declared rho_m shorter than the shortest
    // comfortable lane change is raised to it, as RCPP's planner raises it (core/merge_duration.h).
    for (const double rho : {base_rho_s, 1.5 * base_rho_s, 2.0 * base_rho_s}) {
      if (!leader_holds_speed(t, p, step, gap, ahead, rho)) continue;
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
