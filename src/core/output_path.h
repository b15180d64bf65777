// Output paths are checked before any work starts: a campaign or a check must not run
// for hours and then fail on its report directory. Each check throws OutputPathError with one
// line naming the option, the path and the reason; the CLI prints it and exits 2.
#pragma once

#include <stdexcept>
#include <string>

namespace mg {

class OutputPathError : public std::runtime_error {
 public:
  OutputPathError(const std::string& option, const std::string& path, const std::string& why)
      : std::runtime_error(option + " " + path + ": " + why) {}
};

// Makes `dir` a directory (with its parents) if it is not one, and proves it writable by creating
// and removing a probe file in it. `option` names the command-line option, e.g. "--report".
void prepare_output_dir(const std::string& option, const std::string& dir);

// `file` will be (re)written in place: it must not be a directory, and its directory must be
// writable (files are written beside the target and renamed over it).
void check_output_file(const std::string& option, const std::string& file);

}  // namespace mg
