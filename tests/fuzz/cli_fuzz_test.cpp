// `mergeguard fuzz` and `mergeguard replay` through the built binary (env MG_CLI): the JSON
// summary contract, exit codes, determinism across --jobs, SIGINT, replay and --update.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fuzz/corpus_case.h"

namespace mg::fuzz {
namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

fs::path scratch(const std::string& tag) {
  const auto dir = fs::temp_directory_path() / ("mg_cli_fuzz_" + std::to_string(::getpid()) + "_" + tag);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Runs MG_CLI with args; `interrupt_after_s` > 0 sends `signal` (SIGINT) after that many seconds.
CliRun run_cli(const std::vector<std::string>& args, double interrupt_after_s = 0.0, int signal = SIGINT) {
  const char* cli = std::getenv("MG_CLI");
  if (cli == nullptr) throw std::runtime_error("MG_CLI is not set (run through ctest)");
  const auto dir = scratch("io");
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
  if (interrupt_after_s > 0.0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(interrupt_after_s));
    ::kill(pid, signal);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(out_path);
  r.err = slurp(err_path);
  fs::remove_all(dir);
  return r;
}

std::vector<std::string> fuzz_args(const fs::path& corpus, const std::string& runs, const std::string& jobs) {
  return {"fuzz", "--planner", "tripfield", "--runs", runs, "--jobs", jobs, "--seed", "3", "--max-vehicles", "2",
          "--shrink-attempts", "15", "--corpus", corpus.string(), "--json"};
}

TEST(CliFuzz, JsonSummaryHasTheContractKeysAndExitCodeMatches) {
  const auto corpus = scratch("contract");
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
  const auto a = scratch("jobs1"), b = scratch("jobs2");
  auto one = nlohmann::json::parse(run_cli(fuzz_args(a, "6", "1")).out);
  auto two = nlohmann::json::parse(run_cli(fuzz_args(b, "6", "2")).out);
  for (auto* j : {&one, &two})
    for (const char* timing : {"seconds", "scenarios_per_second", "date", "jobs", "corpus", "new_cases"}) j->erase(timing);
  for (auto* j : {&one, &two})
    for (auto& s : j->at("signature_list")) s.erase("case");
  EXPECT_EQ(one, two);
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(CliFuzz, BadUsageExitsTwo) {
  EXPECT_EQ(run_cli({"fuzz", "--shard", "2/2", "--runs", "1"}).exit_code, 2);
  EXPECT_EQ(run_cli({"fuzz", "--planner", "nope", "--runs", "1"}).exit_code, 2);
  EXPECT_EQ(run_cli({"fuzz", "--runs", "1", "--time", "1"}).exit_code, 2);
  EXPECT_EQ(run_cli({"fuzz", "--jobs", "0", "--runs", "1"}).exit_code, 2);
  EXPECT_EQ(run_cli({"replay", "/nonexistent/case.json"}).exit_code, 2);
}

TEST(CliFuzz, SigintStopsCleanlyAndStillReports) {
  const auto dir = scratch("sigint");
  const CliRun r = run_cli({"fuzz", "--planner", "tripfield", "--time", "600", "--corpus", (dir / "cases").string(),
                         "--report", (dir / "report").string(), "--json"},
                        3.0);
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.exit_code << " " << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("interrupted").get<bool>());
  EXPECT_TRUE(fs::exists(dir / "report" / "report.json"));
  for (const auto& path : j.at("new_cases")) EXPECT_NO_THROW(load_case(path.get<std::string>()));
  fs::remove_all(dir);
}

TEST(CliFuzz, SigkillNeverLeavesABrokenCase) {
  const auto dir = scratch("sigkill");
  for (double after_s : {1.5, 4.0}) {
    const CliRun r = run_cli({"fuzz", "--planner", "tripfield", "--time", "600", "--jobs", "2", "--seed",
                              std::to_string(static_cast<int>(after_s * 10)), "--corpus", (dir / "cases").string()},
                             after_s, SIGKILL);
    EXPECT_EQ(r.exit_code, 128 + SIGKILL);
  }
  ASSERT_TRUE(fs::exists(dir / "cases")) << "no case written before the kill";
  for (const std::string& file : case_files((dir / "cases").string())) EXPECT_NO_THROW(load_case(file)) << file;
  EXPECT_EQ(run_cli({"replay", (dir / "cases").string()}).exit_code, 0);
  fs::remove_all(dir);
}

TEST(CliReplay, NamesACaseThatDoesNotReproduceAndUpdateRecordsTheNewVerdict) {
  const auto corpus = scratch("replay");
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
