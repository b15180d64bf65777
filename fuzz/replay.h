// Replaying a corpus case from its JSON alone (spec §9, §10 `mergeguard replay`): re-run the
// scenario with the case's planner and compare verdict, violations and failed properties.
#pragma once

#include <string>
#include <vector>

#include "fuzz/corpus_case.h"
#include "fuzz/properties.h"

namespace mg::fuzz {

// Tolerances for numbers that may differ between builds (compilers, sanitizers, -ffast-math-free
// but differently fused arithmetic): a violation's first time and its margin.
inline constexpr double kReplayTimeToleranceS = 0.1;
inline constexpr double kReplayMarginAbsTolerance = 0.01;
inline constexpr double kReplayMarginRelTolerance = 0.01;

struct ReplayResult {
  bool reproduces = false;
  std::vector<std::string> differences;  // one line each; empty when it reproduces
  CaseVerdict actual;
};

// Differences between a recorded and a replayed verdict: holds, collision and its liable party,
// the violated rules with their liable parties (time and margin within the tolerances above),
// and the failed property signatures. The trace digest is informative and not compared.
std::vector<std::string> compare_verdicts(const CaseVerdict& expected, const CaseVerdict& actual);

// `check` must simulate with the case's planner. Determinism is always re-checked.
ReplayResult replay_case(const CorpusCase& c, const CheckFn& check);

}  // namespace mg::fuzz
