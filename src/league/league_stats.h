// The statistics of a league table: a binomial share's confidence interval and the quantiles of a
// sample.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace mg::league {

// z of a two-sided 95 % interval: the 97.5 % quantile of the standard normal distribution.
inline constexpr double kZ95 = 1.959963984540054;

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

// The Wilson score interval of a share k/n (E. B. Wilson, "Probable inference, the law of
// succession, and statistical inference", JASA 22, 1927): centre (p + z^2/2n) / (1 + z^2/n),
// half-width z sqrt(p (1 - p)/n + z^2/4n^2) / (1 + z^2/n). Unlike the normal approximation it
// stays inside [0, 1] and is not empty at k = 0 or k = n. n = 0 gives [0, 1].
Interval wilson_interval(std::uint64_t k, std::uint64_t n, double z = kZ95);

// The q-quantile (q in [0, 1]) of a sorted sample, interpolating linearly between the closest
// ranks (Hyndman & Fan's definition 7, numpy's and R's default); none for an empty sample.
std::optional<double> quantile(const std::vector<double>& sorted, double q);

}  // namespace mg::league
