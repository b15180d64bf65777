// What a league measures of one run besides its verdict, read from the observable trace alone
// (never from what the planner says it did), with the rules' own thresholds: whether and when the
// ego's merge completed (rules/merge_phases.h), the length of the path it drove to complete it, its
// peak lateral acceleration and the time it spent halted.
#pragma once

#include <optional>

#include "core/observed_trace.h"
#include "core/params.h"

namespace mg::league {

struct RunMetrics {
  bool merged = false;                   // the observed merge completed
  std::optional<double> merge_time_s;    // from the run's first step to the completion
  // The ego's arc length over the completed merge, from the observed start of that attempt to its
  // completion (the manoeuvre's length, as RCPP §IV measures it).
  std::optional<double> path_length_m;
  double peak_lat_accel_mps2 = 0.0;      // max |dv_Y/dt| between consecutive steps, road frame
  double halted_s = 0.0;                 // time with the ego's speed below rules.halted_speed_mps
};

// The ego is the trace's vehicle 0. A trace of fewer than two steps gives zeros.
RunMetrics run_metrics(const ObservedTrace& trace, const RuleParams& rules);

}  // namespace mg::league
