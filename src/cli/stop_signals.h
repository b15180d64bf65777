// How the long-running commands (`fuzz`, `league`) stop and report progress. SIGINT (Ctrl-C),
// SIGTERM (what Kubernetes, Slurm and CI runners send on preemption or time-out) and SIGHUP (a
// closed terminal) stop the work after the runs in flight, and the command still writes its report
// and summary; a second one kills mergeguard at once, and its planner processes with it
// (cli/fatal_signals.h).
#pragma once

#include <atomic>
#include <csignal>
#include <functional>
#include <iterator>
#include <string>

#include "fuzz/campaign.h"

namespace mg::cli {

// Installs the stop handlers for its lifetime (the previous ones are restored on scope exit) and
// clears the stop flag. One guard at a time.
class StopSignalGuard {
 public:
  static constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
  StopSignalGuard();
  ~StopSignalGuard();
  StopSignalGuard(const StopSignalGuard&) = delete;
  StopSignalGuard& operator=(const StopSignalGuard&) = delete;

  // Set by the first signal: what a campaign's `stop` points to.
  static const std::atomic<bool>* stop_flag();
  // "SIGTERM" and so on for the signal that stopped the work; empty when none did.
  static std::string stop_signal_name();

 private:
  struct sigaction previous_[std::size(kSignals)] {};
};

// "HH:MM:SS".
std::string clock_time(double seconds);

// One status line on stderr, "<label>: N scenarios (R/s), V violations, S signatures, elapsed,
// left": rewritten in place on a terminal, one line per 10 s in logs.
std::function<void(const fuzz::CampaignProgress&)> progress_printer(const std::string& label, bool tty);

}  // namespace mg::cli
