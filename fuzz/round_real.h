// RapidCheck generator of real numbers on a fixed grid inside a documented range, shrinking
// toward a nominal value and toward rounder numbers (spec §9: "shrink toward round numbers").
#pragma once

#include <rapidcheck.h>

namespace mg::fuzz {

// A realistic range [lo, hi] sampled on a grid of `resolution`; `nominal` is the simplest value
// (the one shrinking aims for first). resolution > 0; lo <= nominal <= hi.
struct RealRange {
  double lo = 0.0;
  double hi = 1.0;
  double nominal = 0.0;
  double resolution = 0.01;
};

// Uniform on the grid of `range`, independent of the RapidCheck size. Every shrink is strictly
// simpler: on a coarser grid (1000, 100, 10, 5, 1, 0.5, 0.1, ...) or, on the same grid, closer to
// the nominal value; so shrinking always terminates.
rc::Gen<double> gen_real(const RealRange& range);

// Shrink candidates of `value` inside `range`, simplest first (exposed for tests).
std::vector<double> real_shrinks(const RealRange& range, double value);

// `value` rounded to the grid of `resolution` so that decimal grids print exactly (20.1, not
// 20.100000000000001).
double snap_to_grid(double value, double resolution);

}  // namespace mg::fuzz
