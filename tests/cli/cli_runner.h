// Runs the built mergeguard binary (path in env MG_CLI, set by CTest) with stdin text, and
// captures exit code, stdout and stderr. Shared by all CLI tests.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace mg::test {

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// args are passed through /bin/sh quoted; stdin_text is fed on standard input.
CliResult run_cli(const std::vector<std::string>& args, const std::string& stdin_text = "");

}  // namespace mg::test
