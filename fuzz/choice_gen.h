// RapidCheck generator picking one of a few weighted options, independent of the size, that
// shrinks toward the earlier options (list the simplest first). rc::gen::element and
// rc::gen::weightedElement do not shrink at all, and rc::gen::inRange collapses at size 0.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "core/demand.h"

namespace mg::fuzz {

template <typename T>
rc::Gen<T> gen_choice(std::vector<std::pair<std::uint64_t, T>> weighted) {
  MG_DEMAND(!weighted.empty());
  return rc::Gen<T>([weighted](const rc::Random& random, int /*size*/) {
    std::uint64_t total = 0;
    for (const auto& [w, v] : weighted) total += w;
    std::uint64_t pick = rc::Random(random).next() % total;
    std::size_t index = 0;
    while (pick >= weighted[index].first) pick -= weighted[index++].first;
    const auto values = weighted;
    return rc::shrinkable::map(
        rc::shrinkable::shrinkRecur(index, [](std::size_t i) { return rc::shrink::towards<std::size_t>(i, 0); }),
        [values](std::size_t i) { return values[i].second; });
  });
}

// Integer uniform in [lo, hi], shrinking toward lo, independent of the size.
inline rc::Gen<std::uint64_t> gen_uint(std::uint64_t lo, std::uint64_t hi) {
  MG_DEMAND(lo <= hi);
  return rc::Gen<std::uint64_t>([lo, hi](const rc::Random& random, int /*size*/) {
    const std::uint64_t value = lo + rc::Random(random).next() % (hi - lo + 1);
    return rc::shrinkable::shrinkRecur(value, [lo](std::uint64_t x) { return rc::shrink::towards<std::uint64_t>(x, lo); });
  });
}

}  // namespace mg::fuzz
