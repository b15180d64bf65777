// The three public CommonRoad recordings of the project's shared data
// (../shared/data/commonroad/ beside the repository: see docs/audit.md for their sources).
#pragma once

#include <string>

namespace mg::test {

inline std::string recording_path(const std::string& file) {
  return std::string(MG_SOURCE_DIR) + "/../shared/data/commonroad/" + file;
}

}  // namespace mg::test
