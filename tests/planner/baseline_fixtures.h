// What the baselines' tests (mobil_test.cpp, frenet_test.cpp) share: the default docs/baselines.md
// gives a parameter, so that a test can hold it to the planner's own table; a drawn real number;
// the on-ramp they plan on. One copy, so that the module's tests still compile as one unit
// (MG_UNITY_BUILD).
#pragma once

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include <rapidcheck.h>

#include "core/scenario.h"

namespace mg::test {

// A real number drawn in tenths from [lo_tenths / 10, hi_tenths / 10] (inside a property).
inline double real_in(int lo_tenths, int hi_tenths) { return *rc::gen::inRange(lo_tenths, hi_tenths + 1) / 10.0; }

// A straight on-ramp: the ego in the side lane at x = 0, 20 m/s, the side lane ending at 200 m,
// speed limit 25 m/s, no other vehicle.
inline Scenario ramp() {
  Scenario s;
  s.road.side_lane_end_x_m = 200.0;
  s.road.speed_limit_mps = 25.0;
  s.ego.x_m = 0.0;
  s.ego.y_m = -s.road.lane_width_m;
  s.ego.speed_mps = 20.0;
  return s;
}

// The number in the default column of the row "| `name` | default | ..." of docs/baselines.md.
inline std::optional<double> documented_default(const std::string& name) {
  std::ifstream in(std::string(MG_SOURCE_DIR) + "/docs/baselines.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string row = "| `" + name + "` | ";
  const std::size_t at = text.str().find(row);
  if (at == std::string::npos) return std::nullopt;
  return std::strtod(text.str().c_str() + at + row.size(), nullptr);
}

}  // namespace mg::test
