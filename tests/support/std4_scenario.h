// The benchmarks' std-4 scenario (corpus/scenarios/bench_std4.json: the ego on the ramp and three
// main-lane vehicles), loaded once per test executable.
#pragma once

#include <string>

#include "core/scenario.h"

namespace mg::test {

inline const std::string kStd4Path = std::string(MG_SOURCE_DIR) + "/corpus/scenarios/bench_std4.json";

inline const Scenario& std4() {
  static const Scenario s = load_scenario(kStd4Path);
  return s;
}

}  // namespace mg::test
