// --planner 'exec:COMMAND' through the built binary, with the test planner
// process tests/planner/exec_helpers/fake_exec_planner.cpp: a planner that misbehaves is a
// finding (check exit 1, a planner_responds corpus case that replays), one that cannot start is
// a usage error (exit 2, one line), campaigns are deterministic across --jobs, and neither the
// end of a campaign nor Ctrl-C leaves a planner process behind. Waits are bounded, never timed.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "tests/support/scratch_files.h"
#include "tests/support/std4_scenario.h"

namespace mg {
namespace {

namespace fs = std::filesystem;

const std::string kScenario = test::kStd4Path;

// A marker in the command line tells this test's planner processes from any other.
std::string marker(const std::string& tag) { return "mgmark" + std::to_string(::getpid()) + tag; }

std::string fake(const std::string& mode, const std::string& tag) {
  return std::string("exec:") + MG_FAKE_EXEC_PLANNER + " " + mode + " " + marker(tag);
}

bool marked_process_alive(const std::string& tag) {
  const std::string m = marker(tag);
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::ifstream in(entry.path() / "cmdline");
    std::stringstream cmd;
    cmd << in.rdbuf();
    if (cmd.str().find(m) != std::string::npos) return true;
  }
  return false;
}

// Bounded poll (5 s): processes killed at exit may take a moment to be reaped by init.
bool marked_processes_gone(const std::string& tag) {
  for (int i = 0; i < 500; ++i) {
    if (!marked_process_alive(tag)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(ExecPlannerCli, CheckWithACorrectPlannerRunsTheScenario) {
  const auto r = test::run_cli({"check", kScenario, "--planner", fake("echo", "c0"), "--json"});
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("planner"), fake("echo", "c0"));
  EXPECT_TRUE(marked_processes_gone("c0"));
}

TEST(ExecPlannerCli, CheckReportsAMisbehavingPlannerAsAViolation) {
  const auto r = test::run_cli({"check", kScenario, "--planner", fake("hang", "c1"), "--planner-timeout", "0.3"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("VIOLATED planner_responds (planner_timeout)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("did not answer observe within 0.3 s"), std::string::npos) << r.out;
  EXPECT_TRUE(marked_processes_gone("c1"));
}

TEST(ExecPlannerCli, APlannerThatCannotStartIsAUsageError) {
  for (const std::string& planner : {fake("no-hello", "c2"), std::string("exec:/nonexistent/planner")}) {
    const auto r = test::run_cli({"check", kScenario, "--planner", planner});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("before answering hello"), std::string::npos) << r.err;
  }
  EXPECT_TRUE(marked_processes_gone("c2"));
}

TEST(ExecPlannerCli, TheTimeoutsMustBeSecondsInRange) {
  for (const std::string option : {"--planner-timeout", "--planner-start-timeout"})
    for (const char* bad : {"nan", "inf", "0", "-1", "1e9", "x"}) {
      const auto r = test::run_cli({"check", kScenario, option, bad});
      EXPECT_EQ(r.exit_code, 2) << option << " " << bad;
      EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
    }
}

// Start-up is not a call: a planner that takes 3 s to answer hello (one loading a model) starts
// with the default options, though a call may take 1 s; one that never answers hello is still a
// usage error, once the start timeout has passed.
TEST(ExecPlannerCli, APlannerThatTakesSecondsToStartStartsWithTheDefaultOptions) {
  const auto r = test::run_cli({"check", kScenario, "--planner", fake("slow-hello", "c7"), "--json"});
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("planner"), fake("slow-hello", "c7"));
  EXPECT_TRUE(marked_processes_gone("c7"));
}

TEST(ExecPlannerCli, APlannerThatNeverAnswersHelloIsAUsageErrorAfterTheStartTimeout) {
  const auto r = test::run_cli({"check", kScenario, "--planner", fake("silent-hello", "c8"), "--planner-start-timeout", "0.5"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("did not answer hello within 0.5 s"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one line
  EXPECT_TRUE(marked_processes_gone("c8"));
}

TEST(ExecPlannerCli, ACrashIsShrunkIntoACaseThatReplaysThroughTheSameCommand) {
  const fs::path corpus = test::fresh_dir("exec_cli_crash");
  const auto r = test::run_cli({"fuzz", "--planner", fake("crash", "c3"), "--runs", "3", "--jobs", "2", "--seed", "1",
                                "--shrink-attempts", "5", "--corpus", corpus.string(), "--report", (corpus / "report").string(),
                                "--json"});
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto summary = nlohmann::json::parse(r.out);
  EXPECT_EQ(summary.at("violations"), 3);
  EXPECT_EQ(summary.at("failures_by_property").at("planner_responds"), 3);
  EXPECT_EQ(summary.at("planner_process").at("hello").at("name"), "fake-crash");
  EXPECT_GE(summary.at("planner_process").at("logs").size(), 2u);  // one per worker at least
  ASSERT_EQ(summary.at("new_cases").size(), 1u);
  const std::string case_path = summary.at("new_cases")[0];
  std::ifstream in(case_path);
  const auto c = nlohmann::json::parse(in);
  EXPECT_EQ(c.at("planner"), fake("crash", "c3"));
  EXPECT_EQ(c.at("planner_hello").at("name"), "fake-crash");
  EXPECT_EQ(c.at("signature").at("rule"), "planner_exit");
  const auto replayed = test::run_cli({"replay", case_path});
  EXPECT_EQ(replayed.exit_code, 0) << replayed.out << replayed.err;
  // Against a fixed planner the case no longer fails: replay says so (exit 1).
  const auto fixed = test::run_cli({"replay", case_path, "--planner", fake("echo", "c3")});
  EXPECT_EQ(fixed.exit_code, 1) << fixed.out << fixed.err;
  EXPECT_NE(fixed.out.find("DOES NOT REPRODUCE"), std::string::npos) << fixed.out;
  EXPECT_TRUE(marked_processes_gone("c3"));
}

// The example users copy (examples/python_planner/): a short campaign finds its flaws, and every
// case it writes replays through the same command.
TEST(ExecPlannerCli, ThePythonExampleIsFoundFaultyAndItsCasesReplay) {
  if (std::system("python3 -c pass > /dev/null 2>&1") != 0) GTEST_SKIP() << "no python3 (the quick start installs it)";
  const fs::path dir = test::fresh_dir("exec_cli_python");
  const std::string planner = "exec:python3 " + std::string(MG_SOURCE_DIR) + "/examples/python_planner/planner.py";
  const auto r = test::run_cli({"fuzz", "--planner", planner, "--runs", "12", "--jobs", "2", "--seed", "1",
                                "--shrink-attempts", "10", "--corpus", (dir / "corpus").string(), "--json"});
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto summary = nlohmann::json::parse(r.out);
  EXPECT_GT(summary.at("violations").get<int>(), 0);
  EXPECT_EQ(summary.at("planner_process").at("hello").at("name"), "python-naive-gap");
  const auto replayed = test::run_cli({"replay", (dir / "corpus").string()});
  EXPECT_EQ(replayed.exit_code, 0) << replayed.out << replayed.err;
  fs::remove_all(dir);
}

TEST(ExecPlannerCli, CampaignsAreDeterministicAcrossJobs) {
  auto summary = [](const std::string& jobs) {
    const auto r = test::run_cli({"fuzz", "--planner", fake("echo", "c4"), "--runs", "6", "--jobs", jobs, "--seed", "2",
                                  "--max-vehicles", "2", "--shrink-attempts", "5", "--corpus", "", "--json"});
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
    auto j = nlohmann::json::parse(r.out);
    for (const char* timing : {"seconds", "scenarios_per_second", "date", "jobs", "first_failure_s", "first_new_failure_s", "planner_process"}) j.erase(timing);
    return j;
  };
  EXPECT_EQ(summary("1"), summary("2"));
  EXPECT_TRUE(marked_processes_gone("c4"));
}

// `mergeguard fuzz --planner PLANNER --time 600 --jobs 2 EXTRA... --corpus ""` as a child process
// (stdout and stderr to files in `dir`), returned once its campaign has started.
pid_t start_campaign(const fs::path& dir, const std::string& planner, const std::vector<std::string>& extra) {
  const std::string err_path = (dir / "err").string();
  std::vector<std::string> args = {"fuzz", "--planner", planner, "--time", "600", "--jobs", "2"};
  args.insert(args.end(), extra.begin(), extra.end());
  args.insert(args.end(), {"--corpus", ""});
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(::open((dir / "out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
    ::dup2(::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
    const char* cli = std::getenv("MG_CLI");
    std::vector<char*> argv = {const_cast<char*>(cli)};
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(cli, argv.data());
    ::_exit(127);
  }
  auto started = [&] {
    std::ifstream in(err_path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str().find("fuzz: ") != std::string::npos;
  };
  for (int i = 0; i < 30000 && !started(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return pid;
}

int wait_for_exit(pid_t pid) {
  int status = 0;
  for (int i = 0; i < 30000 && ::waitpid(pid, &status, WNOHANG) != pid; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return status;
}

TEST(ExecPlannerCli, CtrlCLeavesNoPlannerProcess) {
  const fs::path dir = test::fresh_dir("exec_cli_sigint");
  const pid_t pid = start_campaign(dir, fake("echo", "c5"), {});
  ::kill(pid, SIGINT);
  const int status = wait_for_exit(pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 3) << status;
  EXPECT_TRUE(marked_processes_gone("c5"));
  fs::remove_all(dir);
}

// A second Ctrl-C while the first waits for the calls in flight ends mergeguard at once, and the
// planner processes with it, even one that ignores the end of its input (stubborn).
TEST(ExecPlannerCli, ASecondCtrlCEndsEvenAPlannerThatIgnoresTheEndOfItsInput) {
  const fs::path dir = test::fresh_dir("exec_cli_sigint2");
  const pid_t pid = start_campaign(dir, fake("stubborn", "c6"), {"--planner-timeout", "5"});
  // Once a planner runs, a call of 0.3 s is nearly always in flight: the first Ctrl-C then has
  // something to wait for (sent before, it could end the campaign before the second arrives).
  for (int i = 0; i < 3000 && !marked_process_alive("c6"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ::kill(pid, SIGINT);  // the campaign now waits for its calls in flight, each 0.3 s
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ::kill(pid, SIGINT);
  const int status = wait_for_exit(pid);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
  EXPECT_TRUE(marked_processes_gone("c6"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mg
