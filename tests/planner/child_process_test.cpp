// The child process adapter (planner/child_process.h): lines both ways, timeouts, how a child
// ended, and that end() leaves no process of the child's group behind. Timeouts are generous
// upper bounds only: nothing here asserts how fast something happens.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "planner/child_process.h"

#include <pthread.h>
#include <signal.h>
#include "process_probe.h"

namespace mg {
namespace {

TEST(ChildProcess, LinesGoThereAndBack) {
  ChildProcess child("cat", "");
  ASSERT_EQ(child.write_line("first", 5.0), IoStatus::kDone);
  ASSERT_EQ(child.write_line("second", 5.0), IoStatus::kDone);
  std::string line;
  ASSERT_EQ(child.read_line(line, 5.0), IoStatus::kDone);
  EXPECT_EQ(line, "first");
  ASSERT_EQ(child.read_line(line, 5.0), IoStatus::kDone);
  EXPECT_EQ(line, "second");
}

TEST(ChildProcess, ASilentChildTimesOutAndEndLeavesNoProcess) {
  ChildProcess child("sleep 100 & sleep 100", "");
  const long pgid = child.pid();
  std::string line;
  EXPECT_EQ(child.read_line(line, 0.1), IoStatus::kTimeout);
  child.end(0.0);
  EXPECT_TRUE(test::group_gone_soon(pgid));
}

TEST(ChildProcess, AnExitIsReportedWithItsStatus) {
  ChildProcess child("exit 4", "");
  std::string line;
  EXPECT_EQ(child.read_line(line, 5.0), IoStatus::kClosed);
  EXPECT_EQ(child.exit_description(), "exited with status 4");
}

TEST(ChildProcess, ACrashIsReportedWithItsSignal) {
  ChildProcess child("kill -SEGV $$", "");
  std::string line;
  EXPECT_EQ(child.read_line(line, 5.0), IoStatus::kClosed);
  EXPECT_EQ(child.exit_description().rfind("was killed by signal 11", 0), 0u) << child.exit_description();
}

TEST(ChildProcess, ASingleCommandReplacesTheShellSoItsSignalIsSeen) {
  ChildProcess direct("sh -c 'kill -ABRT $$'", "");  // without exec, dash would report status 134
  std::string line;
  EXPECT_EQ(direct.read_line(line, 5.0), IoStatus::kClosed);
  EXPECT_EQ(direct.exit_description().rfind("was killed by signal 6", 0), 0u) << direct.exit_description();
}

TEST(ChildProcess, WritingToAChildThatExitedIsNoSigpipe) {
  ChildProcess child("exit 0", "");
  std::string line;
  ASSERT_EQ(child.read_line(line, 5.0), IoStatus::kClosed);
  ASSERT_EQ(child.exit_description(), "exited with status 0");  // its stdin is closed by now
  EXPECT_EQ(child.write_line(std::string(4096, 'x'), 5.0), IoStatus::kClosed);  // and this process is alive
  // Nothing of the write's SIGPIPE is left: the thread's mask is as it was, no signal pending.
  sigset_t mask, pending;
  pthread_sigmask(SIG_BLOCK, nullptr, &mask);
  sigpending(&pending);
  EXPECT_EQ(sigismember(&mask, SIGPIPE), 0);
  EXPECT_EQ(sigismember(&pending, SIGPIPE), 0);
}

TEST(ChildProcess, ASigpipeAlreadyPendingForTheProgramStaysPending) {
  sigset_t pipe, old;
  sigemptyset(&pipe);
  sigaddset(&pipe, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe, &old);
  pthread_kill(pthread_self(), SIGPIPE);  // the program's own, blocked and pending
  {
    ChildProcess child("exit 0", "");
    std::string line;
    ASSERT_EQ(child.read_line(line, 5.0), IoStatus::kClosed);
    ASSERT_EQ(child.exit_description(), "exited with status 0");  // its stdin is closed by now
    EXPECT_EQ(child.write_line("x", 5.0), IoStatus::kClosed);
  }
  sigset_t mask, pending;
  pthread_sigmask(SIG_BLOCK, nullptr, &mask);
  sigpending(&pending);
  EXPECT_EQ(sigismember(&mask, SIGPIPE), 1);
  EXPECT_EQ(sigismember(&pending, SIGPIPE), 1);
  const timespec now{0, 0};
  EXPECT_EQ(sigtimedwait(&pipe, nullptr, &now), SIGPIPE);
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
}

TEST(ChildProcess, StderrGoesToTheLogFile) {
  const std::string log = ::testing::TempDir() + "child_process_stderr.log";
  std::remove(log.c_str());
  {
    ChildProcess child("echo to-the-log >&2; exit 0", log);
    std::string line;
    EXPECT_EQ(child.read_line(line, 5.0), IoStatus::kClosed);
  }
  std::FILE* f = std::fopen(log.c_str(), "r");
  ASSERT_NE(f, nullptr);
  char buf[64] = {};
  EXPECT_NE(std::fgets(buf, sizeof buf, f), nullptr);
  std::fclose(f);
  EXPECT_EQ(std::string(buf), "to-the-log\n");
}

TEST(ChildProcess, AnUnwritableLogIsAStartError) {
  EXPECT_THROW(ChildProcess("cat", "/nonexistent-dir/x.log"), ChildStartError);
}

// Once the signal path has killed every child's group, a child asked for by another thread is
// not started (it would outlive mergeguard). In a death test's own process: it ends the rest.
TEST(ChildProcessDeathTest, NoChildStartsOnceTheSignalPathHasKilledTheGroups) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        kill_all_child_groups();
        try {
          ChildProcess child("cat", "");
        } catch (const ChildStartError& e) {
          std::fprintf(stderr, "%s\n", e.what());
          std::_Exit(7);
        }
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(7), "cannot start /bin/sh -c 'cat'");
}

}  // namespace
}  // namespace mg
