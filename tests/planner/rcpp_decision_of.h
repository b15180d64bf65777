// RCPP's decision behind a command, for the tests of RCPP's behaviour (planner/rcpp_decision.h).
#pragma once

#include <gtest/gtest.h>

#include "planner/rcpp_decision.h"

namespace mg {

// A copy of the decision; an empty one, and a test failure, when another planner made the command.
inline RcppDecision decision_of(const PlanOutput& out) {
  const RcppDecision* d = rcpp_decision(out.annotation);
  if (!d) {
    ADD_FAILURE() << "the command carries no RCPP decision (mode " << out.mode << ")";
    return {};
  }
  return *d;
}

}  // namespace mg
