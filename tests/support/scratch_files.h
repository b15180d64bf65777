// Scratch directories and whole-file reads for the tests that write files. One copy for the
// suite, so that test files do not each keep their own (and a module's tests still compile as
// one unit, MG_UNITY_BUILD).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mg::test {

// A path under the system's temporary directory that nothing occupies, unique to this process
// and call (temp/mg_<name>_<pid>_<n>): for a directory the code under test must create itself.
inline std::filesystem::path unused_path(const std::string& name) {
  static int counter = 0;
  const auto path = std::filesystem::temp_directory_path() /
                    ("mg_" + name + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  std::filesystem::remove_all(path);
  return path;
}

// An empty directory at unused_path(name).
inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = unused_path(name);
  std::filesystem::create_directories(dir);
  return dir;
}

// The whole content of a file (empty when it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace mg::test
