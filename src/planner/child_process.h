// The one adapter over POSIX child processes: an exec planner runs as
// `/bin/sh -c COMMAND` in a process group of its own, talks JSON Lines over pipes bound to its
// stdin and stdout, and writes its stderr to a log file. Everything else of mergeguard
// sees lines, timeouts and a one-line account of how the child ended; nothing else spawns,
// polls or kills.
#pragma once

#include <sys/types.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace mg {

// The command could not be started (no /bin/sh, no file descriptors, an unwritable log).
struct ChildStartError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class IoStatus { kDone, kTimeout, kClosed };

// SIGKILLs the process group of every child not yet ended. Async-signal-safe (kill(2) over a
// fixed table of atomics): for a signal handler that is about to end mergeguard at once, which
// would otherwise leave a child that ignores the end of its input running.
void kill_all_child_groups() noexcept;

class ChildProcess {
 public:
  // Starts `command` through /bin/sh (exec'd into when it is a single simple command) in a new
  // process group. Its stderr is appended to
  // `stderr_path`, or inherited when that is empty. Throws ChildStartError.
  ChildProcess(const std::string& command, const std::string& stderr_path);
  // Ends the child (end(): no process of its group is left).
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // Sends `line` and a newline within timeout_s (a child that stops reading fills the pipe);
  // kClosed when the child no longer reads (it exited or closed its stdin).
  IoStatus write_line(std::string_view line, double timeout_s);
  // The next line (without its newline) into `line` within timeout_s; kClosed when the child closed
  // its stdout (it exited) before a complete line, or sent more than kMaxLineBytes without one.
  IoStatus read_line(std::string& line, double timeout_s);
  // Closes the child's stdin, gives it grace_s to exit on its own, then SIGKILLs its process group
  // and reaps it. Idempotent.
  void end(double grace_s = 0.2);
  // How the child ended, for a finding: "exited with status 3", "was killed by signal 11
  // (Segmentation fault)", or "is still running" (after a short wait for its exit status).
  std::string exit_description();
  pid_t pid() const { return pid_; }

  static constexpr std::size_t kMaxLineBytes = 64 * 1024 * 1024;

 private:
  // Waits up to wait_s for the child to exit, without reaping it (its zombie keeps the process
  // group id from being reused until end() has killed the group). True once it has exited.
  bool exited(double wait_s);
  void close_input();

  pid_t pid_ = -1;
  int in_fd_ = -1;         // our ends of the pipes to its stdin and from its stdout (non-blocking)
  int out_fd_ = -1;
  bool exited_ = false;
  bool reaped_ = false;
  int exit_code_ = 0;      // siginfo si_code (CLD_EXITED, CLD_KILLED, ...) once exited_
  int exit_status_ = 0;    // ... and si_status: the exit status or the signal
  std::string buffer_;     // bytes read past the last returned line
};

}  // namespace mg
