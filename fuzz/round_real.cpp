#include "fuzz/round_real.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/demand.h"

namespace mg::fuzz {
namespace {

// Grids from coarse to fine; a value's "level" is the coarsest grid it lies on.
constexpr std::array<double, 11> kGrids = {1000, 100, 10, 5, 1, 0.5, 0.1, 0.05, 0.01, 0.005, 0.001};

bool on_grid(double value, double grid) {
  const double q = value / grid;
  return std::abs(q - std::round(q)) < 1e-9 * std::max(1.0, std::abs(q));
}

// 0 for the nominal value, then 1 + index of the coarsest grid, kGrids.size() + 1 off-grid.
int level(const RealRange& range, double value) {
  if (value == range.nominal) return 0;
  for (std::size_t i = 0; i < kGrids.size(); ++i)
    if (on_grid(value, kGrids[i])) return static_cast<int>(i) + 1;
  return static_cast<int>(kGrids.size()) + 1;
}

bool simpler(const RealRange& range, double candidate, double value) {
  const int lc = level(range, candidate);
  const int lv = level(range, value);
  if (lc != lv) return lc < lv;
  return std::abs(candidate - range.nominal) < std::abs(value - range.nominal);
}

}  // namespace

double snap_to_grid(double value, double resolution) {
  if (resolution >= 1.0) return std::round(value / resolution) * resolution;
  const double inverse = std::round(1.0 / resolution);
  return std::round(value * inverse) / inverse;
}

std::vector<double> real_shrinks(const RealRange& range, double value) {
  std::vector<double> candidates{range.nominal};
  for (double grid : kGrids) {
    if (grid < range.resolution) break;
    candidates.push_back(snap_to_grid(value, grid));
  }
  candidates.push_back(snap_to_grid(value + (range.nominal - value) / 2.0, range.resolution));
  std::vector<double> shrinks;
  for (double c : candidates) {
    if (c < range.lo || c > range.hi || c == value || !simpler(range, c, value)) continue;
    if (std::find(shrinks.begin(), shrinks.end(), c) == shrinks.end()) shrinks.push_back(c);
  }
  return shrinks;
}

rc::Gen<double> gen_real(const RealRange& range) {
  MG_DEMAND(range.resolution > 0.0 && range.lo <= range.nominal && range.nominal <= range.hi);
  return rc::Gen<double>([range](const rc::Random& random, int /*size*/) {
    const auto steps = static_cast<std::uint64_t>(std::llround((range.hi - range.lo) / range.resolution));
    const auto k = rc::Random(random).next() % (steps + 1);
    const double value = std::clamp(
        snap_to_grid(range.lo + static_cast<double>(k) * range.resolution, range.resolution), range.lo, range.hi);
    return rc::shrinkable::shrinkRecur(
        value, [range](double x) { return rc::seq::fromContainer(real_shrinks(range, x)); });
  });
}

}  // namespace mg::fuzz
