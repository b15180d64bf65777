#include "cli_runner.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "tests/support/scratch_files.h"

namespace mg::test {
namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

CliResult run_cli(const std::vector<std::string>& args, const std::string& stdin_text) {
  const char* cli = std::getenv("MG_CLI");
  if (!cli) throw std::runtime_error("MG_CLI is not set (run the tests through ctest)");
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("mg_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "in") << stdin_text; }
  // Every run is bounded in time: a hang shows up as exit code 124.
  std::string cmd = "timeout 120 ";
  cmd += quote(cli);
  for (const auto& a : args) cmd += " " + quote(a);
  cmd += " < " + quote((dir / "in").string()) + " > " + quote((dir / "out").string()) + " 2> " +
         quote((dir / "err").string());
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  std::filesystem::remove_all(dir);
  return r;
}

}  // namespace mg::test
