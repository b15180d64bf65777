// Longitudinal and lateral RSS geometry of every vehicle pair at every trace step (RCPP eq. 1,
// 2), computed once per check and shared by the RSS monitors and the reports.
#pragma once

#include <cstddef>
#include <vector>

#include "core/scenario.h"
#include "sim/trace.h"

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

PairGeometry pair_geometry(const Scenario& s, const TraceStep& step, std::size_t i, std::size_t j);

// All pairs (i < j, in the order i = 0..n-1, j = i+1..n-1) at all steps.
class PairTable {
 public:
  PairTable(const Scenario& s, const Trace& t);
  std::size_t pairs() const { return pairs_; }
  const PairGeometry& at(std::size_t step, std::size_t pair) const { return geometry_[step * pairs_ + pair]; }
  // Pair index of vehicles i < j among n vehicles.
  static std::size_t index(std::size_t n, std::size_t i, std::size_t j) { return i * (2 * n - i - 1) / 2 + (j - i - 1); }

 private:
  std::size_t pairs_ = 0;
  std::vector<PairGeometry> geometry_;
};

}  // namespace mg
