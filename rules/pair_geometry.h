// Longitudinal and lateral RSS geometry of vehicle pairs at a trace step (RCPP eq. 1, 2), for
// the RSS monitors and the reports.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/observed_trace.h"

namespace mg {

// Geometry of vehicles i and j (0 = ego) at one trace step, with their RSS distances.
struct PairGeometry {
  std::size_t rear = 0, front = 0;  // by X
  std::size_t left = 0, right = 0;  // by Y
  double gap_m = 0.0;               // X_front - X_rear, centre to centre
  double d_lon_m = 0.0;             // RCPP eq. (1) with rear/front as above
  double dy_m = 0.0;                // Y_left - Y_right
  double d_lat_m = 0.0;             // RCPP eq. (2) (RSS Def. 4)
  bool lon_unsafe() const { return gap_m < d_lon_m; }
  bool lat_unsafe() const { return dy_m < d_lat_m; }
};

PairGeometry pair_geometry(const ObservedTrace& s, const ObservedStep& step, std::size_t i, std::size_t j);

namespace pair_detail {
struct PairMemo;
}  // namespace pair_detail
// The same for one pair along a trace: `memo` (one per pair, steps in order) reuses the RSS
// distances while their inputs repeat bit for bit; the result is the same.
PairGeometry pair_geometry(const ObservedTrace& s, const ObservedStep& step, std::size_t i, std::size_t j,
                           pair_detail::PairMemo& memo);
// pair_geometry(s, step, i, j, memo).lat_unsafe() without the longitudinal half.
bool pair_lat_unsafe(const ObservedTrace& s, const ObservedStep& step, std::size_t i, std::size_t j,
                     pair_detail::PairMemo& memo);

namespace pair_detail {
struct Kinematics {
  double x_m, y_m, vx_mps, vy_mps;  // road frame
};
// The RSS distances of a pair are pure functions of who is rear (left) and the speeds: a pair
// whose inputs repeat, bit for bit, those of its previous step (vehicles at constant speed, no
// lateral motion: most pairs most of the time) reuses them.
struct PairMemo {
  std::size_t rear = 0, left = 0;
  std::uint64_t v_rear = 0, v_front = 0, vy_left = 0, vy_right = 0;
  double d_lon_m = std::numeric_limits<double>::quiet_NaN();
  double d_lat_m = std::numeric_limits<double>::quiet_NaN();
};
}  // namespace pair_detail

// The geometry of vehicle pairs one trace step at a time: the monitors walk the trace
// in step order, so nothing is kept per step; memory is one memo per pair. Pairs are indexed
// i < j in the order i = 0..n-1, j = i+1..n-1 (index()).
class PairStepper {
 public:
  explicit PairStepper(const ObservedTrace& s);
  // Makes `step` the current step (every vehicle's road-frame kinematics).
  void load(const ObservedStep& step);
  // Vehicles i < j at the current step; p = index(n, i, j). A pair's RSS distances are reused
  // while their inputs repeat bit for bit, so the result equals pair_geometry() exactly.
  PairGeometry at(std::size_t p, std::size_t i, std::size_t j);
  // at(p, i, j).lat_unsafe() without the longitudinal half (its RSS distance).
  bool lat_unsafe(std::size_t p, std::size_t i, std::size_t j);
  std::size_t vehicles() const { return n_; }
  // Road-frame X and longitudinal speed of vehicle v at the current step, as at() uses them.
  double x_m(std::size_t v) const { return kinematics_[v].x_m; }
  double road_vx_mps(std::size_t v) const { return kinematics_[v].vx_mps; }
  // Pair index of vehicles i < j among n vehicles.
  static std::size_t index(std::size_t n, std::size_t i, std::size_t j) { return i * (2 * n - i - 1) / 2 + (j - i - 1); }

 private:
  const ObservedTrace& trace_;
  std::size_t n_ = 0;
  std::vector<pair_detail::Kinematics> kinematics_;
  std::vector<pair_detail::PairMemo> memo_;
};

}  // namespace mg
