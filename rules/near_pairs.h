// Sweep and prune along X: of the vehicle pairs of one trace step, those whose X
// intervals are close enough to matter, in pair order (i < j by i, then j), found in
// O(n + pairs) for traffic that keeps its order instead of visiting all n^2 / 2 pairs.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace mg {

class NearPairs {
 public:
  using Pair = std::pair<std::size_t, std::size_t>;  // (i, j), i < j
  // Intervals [lo[v], hi[v]] of vehicles v = 0..n-1 (lo <= hi). With a the vehicle whose
  // interval starts first (the lower index on a tie), a pair is left out when
  // lo[b] - hi[a] > 0 and >= cut_m; every other pair is listed.
  const std::vector<Pair>& find(const std::vector<double>& lo, const std::vector<double>& hi, double cut_m);

 private:
  std::vector<std::size_t> order_;  // by (lo, index); kept between steps, so re-sorting is cheap
  std::vector<Pair> pairs_;
};

}  // namespace mg
