#include "league/league_stats.h"

#include <algorithm>
#include <cmath>

#include "core/demand.h"

namespace mg::league {

Interval wilson_interval(std::uint64_t k, std::uint64_t n, double z) {
  MG_DEMAND(k <= n && z > 0.0);
  if (n == 0) return {0.0, 1.0};
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(k) / nn;
  const double z2 = z * z;
  const double denominator = 1.0 + z2 / nn;
  const double centre = (p + z2 / (2.0 * nn)) / denominator;
  const double half = z * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn)) / denominator;
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::optional<double> quantile(const std::vector<double>& sorted, double q) {
  MG_DEMAND(q >= 0.0 && q <= 1.0);
  if (sorted.empty()) return std::nullopt;
  const double h = q * static_cast<double>(sorted.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

}  // namespace mg::league
