// Bytes -> scenario for coverage-guided fuzzers (libFuzzer, AFL++ via its libFuzzer driver):
// the bytes are read FuzzedDataProvider-style as choices and grid indices inside the same
// documented ranges as the RapidCheck generator (fuzz/scenario_spec.h), so every input decodes
// to a valid scenario; missing bytes take the nominal values (empty input = nominal scenario
// without vehicles). Small byte mutations make small scenario changes, which is what a
// coverage-guided mutator needs.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/scenario.h"
#include "fuzz/scenario_spec.h"

namespace mg::fuzz {

inline constexpr int kByteScenarioMaxVehicles = 6;

ScenarioSpec spec_from_bytes(const std::uint8_t* data, std::size_t size);
Scenario scenario_from_bytes(const std::uint8_t* data, std::size_t size);

}  // namespace mg::fuzz
