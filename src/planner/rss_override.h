// RCPP's response stage (RSS proper response, spec §4; as ad-rss-lib resolves its response after
// checking): when a vehicle ahead is within both RSS distances, the command of the earlier stages
// is overridden to brake at least b_min toward the RSS following speed.
#pragma once

#include "planner/rcpp_decision.h"

namespace mg {

void apply_proper_response(const WorldSnapshot& w, RcppCycle& out);

}  // namespace mg
