// Minimising a failing scenario while it keeps its failure signature: greedy descent over
// RapidCheck's shrink tree (the first simpler candidate that still fails is taken, until no
// candidate does), then, if three or more vehicles are left, removal of each vehicle and each
// pair, within a budget. Candidates the loader would reject are skipped, so the
// result is always a valid, self-contained scenario.
#pragma once

#include <atomic>
#include <functional>

#include <rapidcheck.h>

#include "core/scenario.h"

namespace mg::fuzz {

struct ShrinkBudget {
  int max_attempts = 600;                  // checked candidates
  double max_seconds = 60.0;               // wall clock
  const std::atomic<bool>* stop = nullptr; // e.g. SIGINT: stop early, keep the best so far
};

struct ShrinkOutcome {
  Scenario scenario;
  int steps = 0;        // accepted simplifications
  int attempts = 0;     // candidates checked
  // A local minimum: no shrink-tree candidate kept the failure and, when three or more vehicles
  // were left, neither did removing any one or any two of them (budget not hit).
  bool minimal = false;
};

// `keeps_failure(s)` is true when s still fails with the same signature. `start` must fail.
ShrinkOutcome shrink_scenario(const rc::Shrinkable<Scenario>& start,
                              const std::function<bool(const Scenario&)>& keeps_failure,
                              const ShrinkBudget& budget);

// True when scenario_from_json(scenario_to_json(s)) accepts s.
bool is_loadable(const Scenario& s);

}  // namespace mg::fuzz
