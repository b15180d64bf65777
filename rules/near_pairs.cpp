#include "rules/near_pairs.h"

#include <algorithm>
#include <numeric>

namespace mg {

const std::vector<NearPairs::Pair>& NearPairs::find(const std::vector<double>& lo, const std::vector<double>& hi,
                                                    double cut_m) {
  const std::size_t n = lo.size();
  if (order_.size() != n) {
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), std::size_t{0});
  }
  // Insertion sort: vehicles rarely change their X order from one step to the next.
  const auto before = [&lo](std::size_t a, std::size_t b) { return lo[a] < lo[b] || (lo[a] == lo[b] && a < b); };
  for (std::size_t k = 1; k < n; ++k) {
    const std::size_t v = order_[k];
    std::size_t m = k;
    for (; m > 0 && before(v, order_[m - 1]); --m) order_[m] = order_[m - 1];
    order_[m] = v;
  }
  pairs_.clear();
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      const double apart_m = lo[order_[b]] - hi[order_[a]];  // grows with b: lo is sorted
      if (apart_m > 0.0 && apart_m >= cut_m) break;
      pairs_.emplace_back(std::min(order_[a], order_[b]), std::max(order_[a], order_[b]));
    }
  }
  std::sort(pairs_.begin(), pairs_.end());
  return pairs_;
}

}  // namespace mg
