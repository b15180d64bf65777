// The three public CommonRoad recordings, kept in the repository (tests/data/commonroad/, with
// their sources and licence) so that the tests run on a clean clone.
#pragma once

#include <string>

namespace mg::test {

inline std::string recording_path(const std::string& file) {
  return std::string(MG_SOURCE_DIR) + "/tests/data/commonroad/" + file;
}

}  // namespace mg::test
