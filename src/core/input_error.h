// Errors raised while validating input at the boundary (JSON files, stdin, command line).
// The message is one line: "<source>: <json path>: <what is wrong>"; the CLI prints it and exits 2.
#pragma once

#include <stdexcept>
#include <string>

namespace mg {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& source, const std::string& json_path, const std::string& what)
      : std::runtime_error(source + ": " + (json_path.empty() ? std::string("/") : json_path) + ": " + what) {}
};

}  // namespace mg
