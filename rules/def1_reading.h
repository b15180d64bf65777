// A Definition 1 reading of the observable trace, as the merge-attempt judge (rules/merge_attempts.h)
// reads an attempt's decision window: at one step, for one gap and one merge duration, the
// interval of v_e* that satisfies ineq. (1.1) and (1.2) (rules/definition1_gap.h), the v_e* its
// margins are stated at (the feasible value nearest the ego's observed speed at the midpoint),
// and those margins.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "core/observed_trace.h"
#include "core/params.h"
#include "rules/definition1_gap.h"

namespace mg {

// One reading (this header's comment); margins in metres, >= 0 where the inequality holds.
struct Def1Reading {
  GapIndices gap;
  std::size_t step = 0;
  double time_s = 0.0;
  double rho_s = 0.0;
  Def1Interval interval;
  double ve_star_mps = 0.0;   // the v_e* the margins are stated at
  double observed_mps = 0.0;  // the ego's observed speed it was chosen nearest to
  double margin_11_m = std::numeric_limits<double>::infinity();
  double margin_12_m = std::numeric_limits<double>::infinity();
  double min_margin_m() const { return margin_11_m < margin_12_m ? margin_11_m : margin_12_m; }
};

// What a reading needs of the attempt it is read for.
struct ReadingSpan {
  std::optional<double> midpoint_time_s;  // when the attempt reached its midpoint, if it did
  bool ended = false;                     // aborted or completed (not cut by the trace's end)
};

// Definition 1 at step i for a gap: the first of the attempt's merge durations (def1_reading.cpp,
// reading_rhos_s) that admits a v_e*, else the one with the largest smaller margin.
Def1Reading read_def1(const ObservedTrace& t, const RuleParams& p, const ReadingSpan& a, const GapIndices& gap,
                      std::size_t i);

// Definition 1 for the pair of the ego and one vehicle of the gap entered, at a reading: ineq.
// (1.1) toward a follower, (1.2) toward a leader, at the reading's step, v_e* and rho.
double pair_margin_m(const ObservedTrace& t, const Def1Reading& r, int vehicle, bool follower);

}  // namespace mg
