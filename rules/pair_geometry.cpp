#include "rules/pair_geometry.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/rss.h"
#include "rules/check.h"
#include "rules/monitor.h"

namespace mg {
namespace {

struct Kinematics {
  double x_m, y_m, vx_mps, vy_mps;  // road frame
};

Kinematics kinematics_of(const VehicleState& v) {
  if (v.yaw_rad == 0.0) return {v.x_m, v.y_m, v.vx_mps, v.vy_mps};  // main-lane vehicles: no trig
  return {v.x_m, v.y_m, v.road_vx_mps(), v.road_vy_mps()};
}

// The RSS distances of a pair are pure functions of who is rear (left) and the speeds: a pair
// whose inputs repeat, bit for bit, those of its previous step (vehicles at constant speed, no
// lateral motion: most pairs most of the time) reuses them.
struct PairMemo {
  std::size_t rear = 0, left = 0;
  std::uint64_t v_rear = 0, v_front = 0, vy_left = 0, vy_right = 0;
  double d_lon_m = std::numeric_limits<double>::quiet_NaN();
  double d_lat_m = std::numeric_limits<double>::quiet_NaN();
};

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

// Kinematics ki, kj of vehicles i and j (0 = ego).
PairGeometry geometry_of(const Scenario& s, const Kinematics& ki, const Kinematics& kj, std::size_t i, std::size_t j,
                         PairMemo& memo) {
  PairGeometry g;
  const bool i_rear = ki.x_m <= kj.x_m;
  const bool i_left = ki.y_m >= kj.y_m;
  g.rear = i_rear ? i : j;
  g.front = i_rear ? j : i;
  g.left = i_left ? i : j;
  g.right = i_left ? j : i;
  const Kinematics& r = i_rear ? ki : kj;
  const Kinematics& f = i_rear ? kj : ki;
  const Kinematics& l = i_left ? ki : kj;
  const Kinematics& rt = i_left ? kj : ki;
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
  g.dy_m = l.y_m - rt.y_m;
  if (std::isnan(memo.d_lat_m) || memo.left != g.left || memo.vy_left != bits(l.vy_mps) ||
      memo.vy_right != bits(rt.vy_mps)) {
    memo.left = g.left;
    memo.vy_left = bits(l.vy_mps);
    memo.vy_right = bits(rt.vy_mps);
    // Lateral limits: the ego's when it is in the pair (the only vehicle that moves laterally).
    const Limits& lat = limits_of(s, i == 0 || j == 0 ? 0 : g.left);
    memo.d_lat_m = rss_lateral_m({l.vy_mps, rt.vy_mps, size_of(s, g.left).width_m, size_of(s, g.right).width_m, T,
                                  lat.lat_accel_max_mps2, lat.lat_brake_min_mps2, s.params.rss.fluctuation_margin_m});
  }
  g.d_lat_m = memo.d_lat_m;
  return g;
}

}  // namespace

PairGeometry pair_geometry(const Scenario& s, const TraceStep& step, std::size_t i, std::size_t j) {
  PairMemo fresh;
  return geometry_of(s, kinematics_of(state_of(step, i)), kinematics_of(state_of(step, j)), i, j, fresh);
}

PairTable::PairTable(const Scenario& s, const Trace& t) {
  const std::size_t n = s.vehicles.size() + 1;
  pairs_ = n * (n - 1) / 2;
  geometry_.reserve(t.steps.size() * pairs_);
  std::vector<Kinematics> k(n);
  std::vector<PairMemo> memo(pairs_);
  for (std::size_t step = 0; step < t.steps.size(); ++step) {
    for (std::size_t v = 0; v < n; ++v) k[v] = kinematics_of(state_of(t.steps[step], v));
    std::size_t p = 0;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) geometry_.push_back(geometry_of(s, k[i], k[j], i, j, memo[p++]));
    }
  }
}

}  // namespace mg
