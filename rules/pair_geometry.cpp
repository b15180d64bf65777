#include "rules/pair_geometry.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "core/rss.h"
#include "rules/check.h"
#include "rules/monitor.h"

namespace mg {
namespace {

using pair_detail::Kinematics;
using pair_detail::PairMemo;

Kinematics kinematics_of(const ObservedState& v) { return {v.x_m, v.y_m, v.vx_mps, v.vy_mps}; }

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

// The lateral half of geometry_of: left/right, dy and D_lat (RCPP eq. 2).
void lateral_of(const ObservedTrace& s, const Kinematics& ki, const Kinematics& kj, std::size_t i, std::size_t j,
                PairMemo& memo, PairGeometry& g) {
  const bool i_left = ki.y_m >= kj.y_m;
  g.left = i_left ? i : j;
  g.right = i_left ? j : i;
  const Kinematics& l = i_left ? ki : kj;
  const Kinematics& rt = i_left ? kj : ki;
  g.dy_m = l.y_m - rt.y_m;
  if (std::isnan(memo.d_lat_m) || memo.left != g.left || memo.vy_left != bits(l.vy_mps) ||
      memo.vy_right != bits(rt.vy_mps)) {
    memo.left = g.left;
    memo.vy_left = bits(l.vy_mps);
    memo.vy_right = bits(rt.vy_mps);
    // Lateral limits: the ego's when it is in the pair (the only vehicle that moves laterally).
    const Limits& lat = limits_of(s, i == 0 || j == 0 ? 0 : g.left);
    memo.d_lat_m = rss_lateral_m({l.vy_mps, rt.vy_mps, size_of(s, g.left).width_m, size_of(s, g.right).width_m,
                                  s.params.rss.response_time_s, lat.lat_accel_max_mps2, lat.lat_brake_min_mps2,
                                  s.params.rss.fluctuation_margin_m});
  }
  g.d_lat_m = memo.d_lat_m;
}

// Kinematics ki, kj of vehicles i and j (0 = ego).
PairGeometry geometry_of(const ObservedTrace& s, const Kinematics& ki, const Kinematics& kj, std::size_t i, std::size_t j,
                         PairMemo& memo) {
  PairGeometry g;
  const bool i_rear = ki.x_m <= kj.x_m;
  g.rear = i_rear ? i : j;
  g.front = i_rear ? j : i;
  const Kinematics& r = i_rear ? ki : kj;
  const Kinematics& f = i_rear ? kj : ki;
  const double T = s.params.rss.response_time_s;
  g.gap_m = f.x_m - r.x_m;
  const double v_rear = std::max(r.vx_mps, 0.0), v_front = std::max(f.vx_mps, 0.0);
  if (std::isnan(memo.d_lon_m) || memo.rear != g.rear || memo.v_rear != bits(v_rear) || memo.v_front != bits(v_front)) {
    memo.rear = g.rear;
    memo.v_rear = bits(v_rear);
    memo.v_front = bits(v_front);
    memo.d_lon_m = rss_longitudinal_m({v_rear, v_front, size_of(s, g.rear).length_m, size_of(s, g.front).length_m, T,
                                       limits_of(s, g.rear).accel_max_mps2, limits_of(s, g.rear).brake_min_mps2,
                                       limits_of(s, g.front).brake_max_mps2});
  }
  g.d_lon_m = memo.d_lon_m;
  lateral_of(s, ki, kj, i, j, memo, g);
  return g;
}

}  // namespace

PairGeometry pair_geometry(const ObservedTrace& s, const ObservedStep& step, std::size_t i, std::size_t j) {
  PairMemo fresh;
  return pair_geometry(s, step, i, j, fresh);
}

PairGeometry pair_geometry(const ObservedTrace& s, const ObservedStep& step, std::size_t i, std::size_t j, PairMemo& memo) {
  return geometry_of(s, kinematics_of(state_of(step, i)), kinematics_of(state_of(step, j)), i, j, memo);
}

PairStepper::PairStepper(const ObservedTrace& s)
    : trace_(s), n_(s.vehicles.size()), kinematics_(n_), memo_(n_ * (n_ - 1) / 2) {}

void PairStepper::load(const ObservedStep& step) {
  for (std::size_t v = 0; v < n_; ++v) kinematics_[v] = kinematics_of(state_of(step, v));
}

bool pair_lat_unsafe(const ObservedTrace& s, const ObservedStep& step, std::size_t i, std::size_t j, PairMemo& memo) {
  PairGeometry g;
  lateral_of(s, kinematics_of(state_of(step, i)), kinematics_of(state_of(step, j)), i, j, memo, g);
  return g.lat_unsafe();
}

bool PairStepper::lat_unsafe(std::size_t p, std::size_t i, std::size_t j) {
  PairGeometry g;
  lateral_of(trace_, kinematics_[i], kinematics_[j], i, j, memo_[p], g);
  return g.lat_unsafe();
}

PairGeometry PairStepper::at(std::size_t p, std::size_t i, std::size_t j) {
  return geometry_of(trace_, kinematics_[i], kinematics_[j], i, j, memo_[p]);
}

}  // namespace mg
