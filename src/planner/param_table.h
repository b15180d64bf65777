// A planner's own parameter table: every parameter's name, unit, default (the parameter struct's
// initial value), valid range and meaning, declared beside the planner (not in core/params.h,
// which holds RCPP's and the suite's parameters). The baselines (planner/mobil_planner.h,
// planner/frenet_planner.h) declare theirs here; docs/baselines.md lists the same rows, and the
// tests check that every default lies in its range and that the document names every row.
#pragma once

#include <string>
#include <vector>

namespace mg {

template <class P>
struct ParamRow {
  const char* name;
  double (*get)(const P&);  // the parameter's value in a P
  double lo = 0.0;          // closed range [lo, hi]
  double hi = 0.0;
  const char* unit = "";
  const char* meaning = "";

  double value(const P& p) const { return get(p); }
};

// Whether every parameter of `p` lies in its row's range (NaN does not).
template <class P>
bool params_in_range(const std::vector<ParamRow<P>>& table, const P& p) {
  for (const ParamRow<P>& row : table) {
    const double v = row.value(p);
    if (!(v >= row.lo && v <= row.hi)) return false;
  }
  return true;
}

// The first parameter of `p` outside its range, "name = value not in [lo, hi]"; empty if none.
template <class P>
std::string first_out_of_range(const std::vector<ParamRow<P>>& table, const P& p) {
  for (const ParamRow<P>& row : table) {
    const double v = row.value(p);
    if (!(v >= row.lo && v <= row.hi))
      return std::string(row.name) + " = " + std::to_string(v) + " not in [" + std::to_string(row.lo) + ", " +
             std::to_string(row.hi) + "]";
  }
  return "";
}

}  // namespace mg
