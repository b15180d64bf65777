// The whole mergeguard command line as a library function (docs/package.md): the
// `mergeguard` binary is `return mg::cli_main(argc, argv);`, and a program that links
// mergeguard::mergeguard, registers its own planners (planner/planner_registry.h) and then calls
// cli_main is the same command line with those planners accepted by --planner and by replay.
#pragma once

namespace mg {

// argv[0] is the program, argv[1] the subcommand (`--help` lists them). Returns the exit code
// (0 holds, 1 violation found, 2 bad input, usage or I/O, 3 a campaign stopped by a signal);
// every error ends as one line on stderr, never as an exception. Sets SIGXFSZ to ignored and,
// during `fuzz`, handles SIGINT, SIGTERM and SIGHUP (a campaign stops and still writes its report).
int cli_main(int argc, char** argv);

}  // namespace mg
