#include "cli/cli_main.h"

#include <csignal>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/fatal_signals.h"

namespace mg {
namespace {

// One line whatever the exception says (library messages may hold newlines).
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

int usage(std::ostream& out) {
  out << "usage: mergeguard <command> [options]\n\ncommands:\n";
  for (const auto& [name, cmd] : cli::commands())
    if (!cmd.hidden) out << "  mergeguard " << cmd.usage << "\n";
  out << "\nexit codes: 0 holds, 1 violation found, 2 bad input, usage or I/O, 3 fuzz interrupted by a signal\n";
  return cli::kExitBadInput;
}

}  // namespace

int cli_main(int argc, char** argv) {
  // Beyond a file-size limit (ulimit -f) a write then fails with EFBIG, reported like any other
  // I/O error, instead of the signal killing the process mid-file.
  std::signal(SIGXFSZ, SIG_IGN);
  cli::install_fatal_signal_handlers();
  if (argc < 2) return usage(std::cerr);
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    usage(std::cout);
    return cli::kExitOk;
  }
  auto it = cli::commands().find(name);
  if (it == cli::commands().end()) {
    std::cerr << "mergeguard: unknown command '" << name << "'\n";
    return usage(std::cerr);
  }
  const std::vector<std::string> args(argv + 2, argv + argc);
  // The CLI boundary: whatever goes wrong (bad input, an unwritable path, a full disk, an
  // exhausted allocator) ends as one line on stderr and exit 2, never as an escaped exception.
  try {
    return it->second.run(args);
  } catch (const std::exception& e) {
    std::cerr << "mergeguard " << name << ": " << one_line(e.what()) << "\n";
  } catch (...) {
    std::cerr << "mergeguard " << name << ": unexpected error\n";
  }
  return cli::kExitBadInput;
}

}  // namespace mg
