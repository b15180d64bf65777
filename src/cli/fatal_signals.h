// Signals that end mergeguard end its planner processes too: exec planners run in process groups
// of their own (planner/child_process.h), which a terminal's Ctrl-C does not reach, and a planner
// that ignores the end of its input would outlive mergeguard.
#pragma once

namespace mg::cli {

// SIGKILLs every planner process group, then dies of `sig` as if unhandled. Async-signal-safe.
extern "C" void end_planners_and_die(int sig);

// SIGINT, SIGTERM and SIGHUP run end_planners_and_die (`fuzz` stops gracefully on the first,
// cmd_fuzz.cpp, and calls it on the second).
void install_fatal_signal_handlers();

}  // namespace mg::cli
