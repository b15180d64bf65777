#include "cli/stop_signals.h"

#include <cstdio>
#include <iostream>

#include "cli/fatal_signals.h"

namespace mg::cli {
namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_stop_signal{0};

extern "C" void on_stop_signal(int sig) {  // lock-free atomics and kill(2) only: async-signal-safe
  if (g_stop.load()) end_planners_and_die(sig);  // the second: no more waiting
  g_stop_signal.store(sig);
  g_stop.store(true);
}

}  // namespace

StopSignalGuard::StopSignalGuard() {
  g_stop = false;
  g_stop_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  for (std::size_t k = 0; k < std::size(kSignals); ++k) sigaction(kSignals[k], &sa, &previous_[k]);
}

StopSignalGuard::~StopSignalGuard() {
  for (std::size_t k = 0; k < std::size(kSignals); ++k) sigaction(kSignals[k], &previous_[k], nullptr);
}

const std::atomic<bool>* StopSignalGuard::stop_flag() { return &g_stop; }

std::string StopSignalGuard::stop_signal_name() {
  const int sig = g_stop_signal.load();
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return sig == 0 ? "" : "signal " + std::to_string(sig);
  }
}

std::string clock_time(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  return buf;
}

std::function<void(const fuzz::CampaignProgress&)> progress_printer(const std::string& label, bool tty) {
  return [label, tty, last_logged = -1e9](const fuzz::CampaignProgress& p) mutable {
    if (!tty && p.elapsed_s - last_logged < 10.0) return;
    last_logged = p.elapsed_s;
    char line[256];
    std::snprintf(line, sizeof line, "%s: %llu scenarios (%.1f/s), %llu violations, %zu signatures, %s elapsed, %s left",
                  label.c_str(), static_cast<unsigned long long>(p.scenarios), p.elapsed_s > 0 ? p.scenarios / p.elapsed_s : 0.0,
                  static_cast<unsigned long long>(p.failing_scenarios), p.signatures, clock_time(p.elapsed_s).c_str(),
                  p.remaining_s ? clock_time(*p.remaining_s).c_str() : "--:--:--");
    std::cerr << (tty ? "\r" : "") << line << (tty ? "\033[K" : "\n") << std::flush;
  };
}

}  // namespace mg::cli
