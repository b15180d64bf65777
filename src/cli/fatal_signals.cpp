#include "cli/fatal_signals.h"

#include <signal.h>

#include "planner/child_process.h"

namespace mg::cli {

extern "C" void end_planners_and_die(int sig) {
  kill_all_child_groups();
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(sig, &dfl, nullptr);
  raise(sig);
}

void install_fatal_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = end_planners_and_die;
  sigemptyset(&sa.sa_mask);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &sa, nullptr);
}

}  // namespace mg::cli
