#include "cli/command.h"

#include <iostream>

#include <CLI/CLI.hpp>

namespace mg::cli {

const std::map<std::string, Command>& commands() {
  static const std::map<std::string, Command> registry = [] {
    std::map<std::string, Command> by_name;
    for (Command c : {audit_command(), check_command(), check_trace_command(), corpus_command(), fuzz_command(), league_command(), params_command(), plan_command(), replay_command(),
                      report_command(), reproduce_paper_command(), rss_command()}) {
      std::string name = c.name;
      by_name.emplace(std::move(name), std::move(c));
    }
    return by_name;
  }();
  return registry;
}

bool parse_args(CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 wants them reversed
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return false;
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  return true;
}

}  // namespace mg::cli
