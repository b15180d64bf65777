// `mergeguard fuzz` and `mergeguard replay` through the built binary (env MG_CLI): the JSON
// summary contract, exit codes, determinism across --jobs, stop signals, replay and --update.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fuzz/corpus_case.h"
#include "tests/support/scratch_files.h"

namespace mg::fuzz {
namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Every wait in these tests is bounded (a hung child fails the test instead of hanging CTest) and
// none asserts a duration: signals are sent on observed events, not after fixed delays, so the
// tests hold under sanitizers and on a loaded machine.
constexpr double kMaxWaitS = 300.0;

// Polls `ready` every 10 ms until it holds or `max_s` passed; false on timeout.
bool wait_until(const std::function<bool()>& ready, double max_s = kMaxWaitS) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(max_s);
  while (!ready()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

// When and how to signal the child: once `ready(err_path)` holds (bounded wait), after
// `extra_delay_s` more, send `signal`.
struct Interrupt {
  int signal = SIGINT;
  std::function<bool(const fs::path& err_path)> ready;
  double extra_delay_s = 0.0;
};

// Runs MG_CLI with args, optionally signalling it. exit_code is the exit status, 128 + the signal
// that killed it, or -1 (with a note in err) when it did not exit within kMaxWaitS.
CliRun run_cli(const std::vector<std::string>& args, const std::optional<Interrupt>& interrupt = std::nullopt) {
  const char* cli = std::getenv("MG_CLI");
  if (cli == nullptr) throw std::runtime_error("MG_CLI is not set (run through ctest)");
  const auto dir = mg::test::fresh_dir("cli_fuzz_io");
  const std::string out_path = (dir / "out").string(), err_path = (dir / "err").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
    ::dup2(::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
    std::vector<char*> argv{const_cast<char*>(cli)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(cli, argv.data());
    ::_exit(127);
  }
  int status = 0;
  bool exited = false;
  const auto child_exited = [&] { return exited || (exited = ::waitpid(pid, &status, WNOHANG) == pid); };
  std::string note;
  if (interrupt) {
    if (!wait_until([&] { return child_exited() || interrupt->ready(err_path); })) note = "\n[test: ready condition timed out]";
    if (!child_exited()) wait_until(child_exited, interrupt->extra_delay_s);
    if (!child_exited()) ::kill(pid, interrupt->signal);
  }
  if (!wait_until(child_exited)) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    note += "\n[test: the command did not exit within the bounded wait]";
  }
  CliRun r;
  r.exit_code = !note.empty() ? -1 : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = mg::test::slurp(out_path);
  r.err = mg::test::slurp(err_path) + note;
  fs::remove_all(dir);
  return r;
}

// True once the campaign has started (its first progress line, printed after the SIGINT handler
// is installed and the corpus is read).
bool campaign_started(const fs::path& err_path) {
  return mg::test::slurp(err_path).find("fuzz: ") != std::string::npos;
}

std::size_t finished_cases(const fs::path& corpus) {
  std::error_code ec;
  return fs::is_directory(corpus, ec) ? case_files(corpus.string()).size() : 0;
}

std::vector<std::string> fuzz_args(const fs::path& corpus, const std::string& runs, const std::string& jobs) {
  return {"fuzz", "--planner", "tripfield", "--runs", runs, "--jobs", jobs, "--seed", "3", "--max-vehicles", "2",
          "--shrink-attempts", "15", "--corpus", corpus.string(), "--json"};
}

TEST(CliFuzz, JsonSummaryHasTheContractKeysAndExitCodeMatches) {
  const auto corpus = mg::test::fresh_dir("cli_fuzz_contract");
  const CliRun r = run_cli(fuzz_args(corpus, "4", "2"));
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"scenarios", "seconds", "scenarios_per_second", "violations", "signatures", "new_cases"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j.at("scenarios"), 4);
  EXPECT_EQ(r.exit_code, j.at("violations").get<int>() > 0 ? 1 : 0);
  for (const auto& path : j.at("new_cases")) EXPECT_NO_THROW(load_case(path.get<std::string>()));
  fs::remove_all(corpus);
}

TEST(CliFuzz, SameSeedAndRunsGiveTheSameSummaryWhateverTheJobs) {
  const auto a = mg::test::fresh_dir("cli_fuzz_jobs1"), b = mg::test::fresh_dir("cli_fuzz_jobs2");
  auto one = nlohmann::json::parse(run_cli(fuzz_args(a, "6", "1")).out);
  auto two = nlohmann::json::parse(run_cli(fuzz_args(b, "6", "2")).out);
  for (auto* j : {&one, &two})
    for (const char* timing : {"seconds", "scenarios_per_second", "first_failure_s", "first_new_failure_s", "date", "jobs", "corpus", "new_cases"}) j->erase(timing);
  for (auto* j : {&one, &two})
    for (auto& s : j->at("signature_list")) s.erase("case");
  EXPECT_EQ(one, two);
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(CliFuzz, GuidedSearchGivesTheSameSummaryWhateverTheJobs) {
  // rcpp, 400 runs: guided runs start at run 128 (two warm-up batches of 64).
  auto args = [](const std::string& jobs) {
    return std::vector<std::string>{"fuzz", "--planner", "rcpp", "--runs", "400", "--jobs", jobs, "--seed", "5",
                                    "--search", "guided", "--corpus", "", "--json"};
  };
  const CliRun r1 = run_cli(args("1")), r2 = run_cli(args("2"));
  ASSERT_TRUE(r1.exit_code == 0 || r1.exit_code == 1) << r1.err;
  auto one = nlohmann::json::parse(r1.out), two = nlohmann::json::parse(r2.out);
  EXPECT_EQ(one.at("search"), "guided");
  EXPECT_GT(one.at("guided_runs").get<int>(), 100);
  for (auto* j : {&one, &two})
    for (const char* timing : {"seconds", "scenarios_per_second", "first_failure_s", "first_new_failure_s", "date", "jobs"}) j->erase(timing);
  EXPECT_EQ(one, two);
}

TEST(CliFuzz, BadUsageExitsTwo) {
  EXPECT_EQ(run_cli({"fuzz", "--shard", "2/2", "--runs", "1"}).exit_code, 2);
  EXPECT_EQ(run_cli({"fuzz", "--planner", "nope", "--runs", "1"}).exit_code, 2);
  EXPECT_EQ(run_cli({"fuzz", "--runs", "1", "--time", "1"}).exit_code, 2);
  EXPECT_EQ(run_cli({"fuzz", "--jobs", "0", "--runs", "1"}).exit_code, 2);
  EXPECT_EQ(run_cli({"fuzz", "--runs", "-5", "--corpus", ""}).exit_code, 2);  // not 2^64 - 5 runs
  EXPECT_EQ(run_cli({"fuzz", "--runs", "0", "--corpus", ""}).exit_code, 2);
  EXPECT_EQ(run_cli({"fuzz", "--runs", "1", "--shrink-time", "nan", "--corpus", ""}).exit_code, 2);
  EXPECT_EQ(run_cli({"replay", "/nonexistent/case.json"}).exit_code, 2);
}

// SIGINT (Ctrl-C), SIGTERM (preemption, time-outs) and SIGHUP all stop a campaign gracefully:
// exit 3 ("interrupted", distinct from 0 and 1), the summary names the signal, the report and
// every case found are written.
TEST(CliFuzz, EveryStopSignalEndsTheCampaignCleanlyWithItsReport) {
  const std::vector<std::pair<int, std::string>> signals = {{SIGINT, "SIGINT"}, {SIGTERM, "SIGTERM"}, {SIGHUP, "SIGHUP"}};
  for (const auto& [sig, name] : signals) {
    const auto dir = mg::test::fresh_dir("cli_fuzz_stop_" + name);
    // The signal goes once the first case is written: the campaign is then surely running and
    // has found something to report.
    const auto cases = dir / "cases";
    const CliRun r = run_cli({"fuzz", "--planner", "tripfield", "--time", "600", "--shrink-attempts", "20", "--corpus",
                              cases.string(), "--report", (dir / "report").string(), "--json"},
                             Interrupt{sig, [&](const fs::path&) { return finished_cases(cases) > 0; }, 0.0});
    ASSERT_EQ(r.exit_code, 3) << name << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j.at("interrupted").get<bool>()) << name;
    EXPECT_EQ(j.at("signal"), name);
    ASSERT_TRUE(fs::exists(dir / "report" / "report.json")) << name;
    const auto report = nlohmann::json::parse(std::ifstream(dir / "report" / "report.json"));
    EXPECT_EQ(report.at("signal"), name);
    EXPECT_EQ(report.at("scenarios"), j.at("scenarios")) << name << ": the final report, not a checkpoint";
    EXPECT_FALSE(j.at("new_cases").empty()) << name;
    for (const auto& path : j.at("new_cases")) EXPECT_NO_THROW(load_case(path.get<std::string>())) << name;
    fs::remove_all(dir);
  }
}

TEST(CliFuzz, AnUninterruptedSummaryHasNoSignal) {
  const auto corpus = mg::test::fresh_dir("cli_fuzz_nosignal");
  const auto j = nlohmann::json::parse(run_cli(fuzz_args(corpus, "2", "1")).out);
  EXPECT_FALSE(j.at("interrupted").get<bool>());
  EXPECT_TRUE(j.at("signal").is_null());
  fs::remove_all(corpus);
}

TEST(CliFuzz, SigkillNeverLeavesABrokenCase) {
  const auto dir = mg::test::fresh_dir("cli_fuzz_sigkill");
  // Kill moments tied to events, not to the clock: right at the start of the campaign, the
  // moment the first case is finished (another is likely being shrunk or written), and a little
  // later. Small shrink budgets make writes frequent.
  const std::vector<Interrupt> kills{{SIGKILL, campaign_started, 0.0},
                                     {SIGKILL, [&](const fs::path&) { return finished_cases(dir / "cases-1") > 0; }, 0.0},
                                     {SIGKILL, [&](const fs::path&) { return finished_cases(dir / "cases-2") > 0; }, 0.3}};
  for (std::size_t k = 0; k < kills.size(); ++k) {
    const auto cases = dir / ("cases-" + std::to_string(k));
    const CliRun r = run_cli({"fuzz", "--planner", "tripfield", "--time", "600", "--jobs", "2", "--seed",
                              std::to_string(k + 1), "--shrink-attempts", "20", "--corpus", cases.string()},
                             kills[k]);
    EXPECT_EQ(r.exit_code, 128 + SIGKILL) << r.err;
    if (!fs::exists(cases)) continue;  // killed before the first case: nothing to check
    for (const std::string& file : case_files(cases.string())) EXPECT_NO_THROW(load_case(file)) << file;
    EXPECT_EQ(run_cli({"replay", cases.string()}).exit_code, 0) << cases;
  }
  EXPECT_GT(finished_cases(dir / "cases-1"), 0u);
  fs::remove_all(dir);
}

TEST(CliReplay, NamesACaseThatDoesNotReproduceAndUpdateRecordsTheNewVerdict) {
  const auto corpus = mg::test::fresh_dir("cli_fuzz_replay");
  const auto j = nlohmann::json::parse(run_cli(fuzz_args(corpus, "6", "1")).out);
  ASSERT_FALSE(j.at("new_cases").empty()) << "the baseline should fail somewhere in 6 runs";
  const std::string path = j.at("new_cases").at(0);
  EXPECT_EQ(run_cli({"replay", corpus.string()}).exit_code, 0);
  CorpusCase c = load_case(path);
  c.verdict.violations.clear();  // pretend the recorded verdict was different
  write_case(c, path);
  const CliRun bad = run_cli({"replay", corpus.string()});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.out.find("DOES NOT REPRODUCE " + path), std::string::npos) << bad.out;
  EXPECT_EQ(run_cli({"replay", "--update", path}).exit_code, 0);
  EXPECT_EQ(run_cli({"replay", path}).exit_code, 0);
  fs::remove_all(corpus);
}

}  // namespace
}  // namespace mg::fuzz
