#include "planner/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

extern char** environ;

namespace mg {
namespace {

using Clock = std::chrono::steady_clock;

std::string errno_text(const std::string& what, int err) { return what + ": " + std::strerror(err); }

// Closes its file descriptors on every path out of the constructor.
struct Fds {
  int to_child[2] = {-1, -1}, from_child[2] = {-1, -1}, log = -1;
  ~Fds() {
    for (int fd : {to_child[0], to_child[1], from_child[0], from_child[1], log})
      if (fd >= 0) ::close(fd);
  }
};

// A write to a pipe whose reader is gone raises SIGPIPE, which would end mergeguard (or the
// program that links it) unless it ignores SIGPIPE, and the disposition is not ours to change.
// As libpq does (pq_block_sigpipe / pq_reset_sigpipe): SIGPIPE is blocked in this thread around
// the write, and one the write raised is taken back before the thread's mask is restored, unless
// one was already pending (then it is the program's).
class SigpipeBlock {
 public:
  SigpipeBlock() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_, &old_);
    sigset_t pending;
    sigpending(&pending);
    was_pending_ = sigismember(&pending, SIGPIPE) == 1;
  }
  ~SigpipeBlock() {
    sigset_t pending;
    if (broke_ && !was_pending_ && sigpending(&pending) == 0 && sigismember(&pending, SIGPIPE) == 1) {
      const timespec now{0, 0};
      while (sigtimedwait(&pipe_, nullptr, &now) < 0 && errno == EINTR) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  SigpipeBlock(const SigpipeBlock&) = delete;
  SigpipeBlock& operator=(const SigpipeBlock&) = delete;
  void broke() { broke_ = true; }  // the write failed with EPIPE

 private:
  sigset_t pipe_, old_;
  bool was_pending_ = false, broke_ = false;
};

// The child starts with default signal handling and an empty mask: mergeguard ignores SIGXFSZ
// and, during fuzz, handles SIGINT/SIGTERM/SIGHUP, and ignored dispositions survive exec.
void default_signals(posix_spawnattr_t& attr) {
  sigset_t defaults;
  sigemptyset(&defaults);
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGXFSZ, SIGCHLD}) sigaddset(&defaults, sig);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &none);
  // Its own process group (pgid = its pid): a terminal's Ctrl-C reaches mergeguard alone, which
  // ends the campaign's runs in flight first, and end() kills whatever the command started.
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
}

// An executable file, by path or found in PATH (as the shell would look it up).
bool is_program(const std::string& word) {
  if (word.find('/') != std::string::npos) return ::access(word.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::string dirs = path != nullptr ? path : "";
  for (std::size_t from = 0; from <= dirs.size();) {
    const std::size_t to = std::min(dirs.find(':', from), dirs.size());
    const std::string dir = to > from ? dirs.substr(from, to - from) : ".";
    if (::access((dir + "/" + word).c_str(), X_OK) == 0) return true;
    from = to + 1;
  }
  return false;
}

// A single command naming a program runs as `exec COMMAND`: the shell is replaced by the planner,
// so that the child's pid, exit status and signal are the planner's own (dash would fork and
// report a crash as status 128 + signal). Lists, pipelines, subshells, builtins, keywords and
// leading assignments keep their shell.
std::string shell_line(const std::string& command) {
  const std::size_t start = command.find_first_not_of(" \t");
  if (start == std::string::npos || command.find_first_of(";&|()`\n") != std::string::npos) return command;
  const std::string first = command.substr(start, command.find_first_of(" \t", start) - start);
  return is_program(first) ? "exec " + command : command;
}

int remaining_ms(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return left <= 0 ? 0 : static_cast<int>(std::min<long long>(left + 1, 1 << 30));
}

Clock::time_point deadline_after(double timeout_s) {
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
}

// The process groups of the children not yet ended, for kill_all_child_groups (0: a free slot).
// More live children than slots (one per worker: --jobs is far below) are ended as usual but
// not by the signal path.
constexpr std::size_t kGroupSlots = 1024;
std::atomic<pid_t> g_live_groups[kGroupSlots];
static_assert(std::atomic<pid_t>::is_always_lock_free);

void remember_group(pid_t pgid) {
  for (std::atomic<pid_t>& slot : g_live_groups) {
    pid_t free = 0;
    if (slot.compare_exchange_strong(free, pgid)) return;
  }
}

// Children being started and not yet in g_live_groups, and whether kill_all_child_groups has
// begun. A child is registered only once posix_spawn returns, so without them a signal handled
// on another thread in that window would end mergeguard and leave the new child running.
std::atomic<int> g_spawning{0};
std::atomic<bool> g_ending{false};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<bool>::is_always_lock_free);

// Starting and registering one child. The stop signals are blocked in this thread meanwhile, so
// that their handler runs on another thread (which waits for this section) or, in a single
// thread, after it; a child asked for once the handler has begun is not started at all
// (ending()). The atomics are sequentially consistent: either the handler sees this section or
// the section sees the handler's flag.
class SpawnSection {
 public:
  SpawnSection() {
    sigset_t stop;
    sigemptyset(&stop);
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stop, sig);
    pthread_sigmask(SIG_BLOCK, &stop, &previous_);
    g_spawning.fetch_add(1);
  }
  ~SpawnSection() {
    g_spawning.fetch_sub(1);
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }
  SpawnSection(const SpawnSection&) = delete;
  SpawnSection& operator=(const SpawnSection&) = delete;
  static bool ending() { return g_ending.load(); }

 private:
  sigset_t previous_{};
};

void forget_group(pid_t pgid) {
  for (std::atomic<pid_t>& slot : g_live_groups) {
    pid_t mine = pgid;
    if (slot.compare_exchange_strong(mine, 0)) return;
  }
}

// poll() for `events` until the deadline; EINTR (a signal handled by mergeguard) retries.
IoStatus wait_for(int fd, short events, Clock::time_point deadline) {
  for (;;) {
    pollfd p{fd, events, 0};
    const int n = ::poll(&p, 1, remaining_ms(deadline));
    if (n > 0) return (p.revents & (events | POLLHUP)) ? IoStatus::kDone : IoStatus::kClosed;
    if (n == 0) return IoStatus::kTimeout;
    if (errno != EINTR) return IoStatus::kClosed;
  }
}

}  // namespace

ChildProcess::ChildProcess(const std::string& command, const std::string& stderr_path) {
  Fds fds;
  // Pipes, not a socket pair: a request and its reply cost half the time through pipes (a call
  // is two wake-ups of processes that often share a core; docs/performance.md).
  if (::pipe2(fds.to_child, O_CLOEXEC) != 0 || ::pipe2(fds.from_child, O_CLOEXEC) != 0)
    throw ChildStartError(errno_text("pipe", errno));
  // Our ends only: each end of a pipe is a file description of its own.
  if (::fcntl(fds.to_child[1], F_SETFL, O_NONBLOCK) != 0 || ::fcntl(fds.from_child[0], F_SETFL, O_NONBLOCK) != 0)
    throw ChildStartError(errno_text("fcntl", errno));
  if (!stderr_path.empty()) {
    fds.log = ::open(stderr_path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fds.log < 0) throw ChildStartError(errno_text("cannot open the planner log " + stderr_path, errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds.to_child[0], STDIN_FILENO);  // dup2 clears FD_CLOEXEC
  posix_spawn_file_actions_adddup2(&actions, fds.from_child[1], STDOUT_FILENO);
  if (fds.log >= 0) posix_spawn_file_actions_adddup2(&actions, fds.log, STDERR_FILENO);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  default_signals(attr);
  std::string sh = "/bin/sh", dash_c = "-c", cmd = shell_line(command);
  char* argv[] = {sh.data(), dash_c.data(), cmd.data(), nullptr};
  int err = 0;
  {
    const SpawnSection section;
    err = SpawnSection::ending() ? ECANCELED : ::posix_spawn(&pid_, "/bin/sh", &actions, &attr, argv, environ);
    if (err == 0) remember_group(pid_);
  }
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (err != 0) throw ChildStartError(errno_text("cannot start /bin/sh -c '" + command + "'", err));
  std::swap(in_fd_, fds.to_child[1]);
  std::swap(out_fd_, fds.from_child[0]);
}

ChildProcess::~ChildProcess() { end(); }

void kill_all_child_groups() noexcept {
  g_ending.store(true);
  // A child being started on another thread is registered within microseconds; a bounded wait
  // (nanosleep is async-signal-safe) keeps a stuck thread from holding the end up.
  for (int waited_ms = 0; g_spawning.load() > 0 && waited_ms < 1000; ++waited_ms) {
    timespec one_ms{0, 1'000'000};
    ::nanosleep(&one_ms, nullptr);
  }
  for (std::atomic<pid_t>& slot : g_live_groups)
    if (const pid_t pgid = slot.load(); pgid > 0) ::kill(-pgid, SIGKILL);
}

IoStatus ChildProcess::write_line(std::string_view line, double timeout_s) {
  if (in_fd_ < 0) return IoStatus::kClosed;
  std::string data(line);
  data.push_back('\n');
  const Clock::time_point deadline = deadline_after(timeout_s);
  SigpipeBlock block;
  std::size_t sent = 0;
  while (sent < data.size()) {
    const ssize_t n = ::write(in_fd_, data.data() + sent, data.size() - sent);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
    } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      const IoStatus s = wait_for(in_fd_, POLLOUT, deadline);
      if (s != IoStatus::kDone) return s;
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      if (n < 0 && errno == EPIPE) block.broke();
      return IoStatus::kClosed;
    }
  }
  return IoStatus::kDone;
}

IoStatus ChildProcess::read_line(std::string& line, double timeout_s) {
  const Clock::time_point deadline = deadline_after(timeout_s);
  std::size_t scanned = 0;
  for (;;) {
    const std::size_t newline = buffer_.find('\n', scanned);
    if (newline != std::string::npos) {
      line.assign(buffer_, 0, newline);
      buffer_.erase(0, newline + 1);
      return IoStatus::kDone;
    }
    scanned = buffer_.size();
    if (out_fd_ < 0 || buffer_.size() > kMaxLineBytes) return IoStatus::kClosed;
    char chunk[65536];
    const ssize_t n = ::read(out_fd_, chunk, sizeof chunk);
    if (n > 0) {
      buffer_.append(chunk, static_cast<std::size_t>(n));
    } else if (n == 0) {
      return IoStatus::kClosed;
    } else if (errno == EAGAIN || errno == EWOULDBLOCK) {
      const IoStatus s = wait_for(out_fd_, POLLIN, deadline);
      if (s != IoStatus::kDone) return s;
    } else if (errno != EINTR) {
      return IoStatus::kClosed;
    }
  }
}

bool ChildProcess::exited(double wait_s) {
  const Clock::time_point deadline = deadline_after(wait_s);
  while (!exited_ && pid_ > 0) {
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) != 0 && errno != EINTR) break;
    if (info.si_pid == pid_) {
      exited_ = true;
      exit_code_ = info.si_code;
      exit_status_ = info.si_status;
    } else if (Clock::now() >= deadline) {
      break;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  return exited_;
}

void ChildProcess::end(double grace_s) {
  if (pid_ <= 0 || reaped_) return;
  close_input();  // end of input: a well-behaved planner exits now
  exited(grace_s);
  ::kill(-pid_, SIGKILL);  // the group: whatever the shell or the planner started
  forget_group(pid_);      // before the reap frees the group id for reuse
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  if (!exited_) {
    exited_ = true;
    exit_code_ = WIFSIGNALED(status) ? CLD_KILLED : CLD_EXITED;
    exit_status_ = WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status);
  }
  reaped_ = true;
  if (out_fd_ >= 0) ::close(out_fd_);
  out_fd_ = -1;
}

void ChildProcess::close_input() {
  if (in_fd_ >= 0) ::close(in_fd_);
  in_fd_ = -1;
}

std::string ChildProcess::exit_description() {
  if (!exited(0.5)) return "is still running";
  if (exit_code_ == CLD_EXITED) return "exited with status " + std::to_string(exit_status_);
  return "was killed by signal " + std::to_string(exit_status_) + " (" + ::strsignal(exit_status_) + ")";
}

}  // namespace mg
