// `mergeguard league` through the built binary (env MG_CLI): the report files and the JSON with
// one entry per planner, the worst runs' cases that replay, an exec planner beside registered
// ones, bad usage (exit 2, one line naming the option), and SIGTERM (exit 3, the report of the
// scenarios every planner completed). Waits are bounded and signals follow observed events.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.h"
#include "tests/support/scratch_files.h"

namespace mg {
namespace {

namespace fs = std::filesystem;

nlohmann::json without_timing(nlohmann::json j) {
  for (const char* key : {"seconds", "jobs", "date"}) j.erase(key);
  return j;
}

TEST(LeagueCli, WritesTheReportWithOneEntryPerPlannerAndCasesThatReplay) {
  const fs::path dir = test::fresh_dir("league_cli_report");
  const auto r = test::run_cli({"league", "--planners", "rcpp,mobil,frenet", "--runs", "8", "--seed", "1", "--jobs", "2",
                                "--report", dir.string(), "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("scenarios"), 8);
  ASSERT_EQ(j.at("planners").size(), 3u);
  EXPECT_EQ(j.at("planners")[0].at("planner"), "rcpp");
  EXPECT_EQ(j.at("planners")[2].at("planner"), "frenet");
  for (const auto& p : j.at("planners")) {
    EXPECT_EQ(p.at("scenarios"), 8);
    for (const char* key : {"failing", "failing_share", "failing_share_ci95", "failures_by_rule", "failures_by_party",
                            "merge_rate", "merge_time_s", "path_length_m", "peak_lat_accel_mps2", "halted_s", "worst_cases"})
      EXPECT_TRUE(p.contains(key)) << key;
  }
  for (const char* file : {"league.json", "league.md", "league.html", "league.svg"}) EXPECT_TRUE(fs::exists(dir / file)) << file;
  EXPECT_EQ(without_timing(nlohmann::json::parse(test::slurp(dir / "league.json"))), without_timing(j));
  const std::string md = test::slurp(dir / "league.md");
  EXPECT_NE(md.find("| planner | scenarios | failing | failing share [95 % CI]"), std::string::npos) << md;
  EXPECT_NE(test::slurp(dir / "league.html").find("<svg"), std::string::npos);
  int cases = 0;
  for (const auto& p : j.at("planners"))
    for (const auto& w : p.at("worst_cases")) {
      ++cases;
      ASSERT_TRUE(w.at("case").is_string());
      EXPECT_TRUE(fs::exists(dir / w.at("case").get<std::string>()));
      if (w.at("liability_report").is_string()) {
        EXPECT_TRUE(fs::exists(dir / w.at("liability_report").get<std::string>()));
      }
    }
  ASSERT_GT(cases, 0);  // the baselines fail somewhere in 8 scenarios
  const auto replayed = test::run_cli({"replay", (dir / "cases").string()});
  EXPECT_EQ(replayed.exit_code, 0) << replayed.out << replayed.err;
  fs::remove_all(dir);
}

TEST(LeagueCli, TheSameSeedAndRunsGiveTheSameLeagueWhateverTheJobs) {
  auto league = [](const std::string& jobs) {
    const auto r = test::run_cli({"league", "--planners", "tripfield,mobil", "--runs", "10", "--seed", "4", "--jobs", jobs, "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return without_timing(nlohmann::json::parse(r.out));
  };
  EXPECT_EQ(league("1"), league("2"));
}

TEST(LeagueCli, AnExecPlannerPlaysBesideTheRegisteredOnes) {
  const std::string fake = std::string("exec:") + MG_FAKE_EXEC_PLANNER + " echo";
  const auto r = test::run_cli({"league", "--planners", "rcpp," + fake, "--runs", "4", "--jobs", "2", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("planners").size(), 2u);
  EXPECT_EQ(j.at("planners")[1].at("planner"), fake);
  EXPECT_EQ(j.at("planners")[1].at("scenarios"), 4);
  EXPECT_EQ(j.at("planner_processes").at("hellos").at(fake).at("name"), "fake-echo");
}

TEST(LeagueCli, BadUsageIsOneLineNamingTheOptionAndExitsTwo) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"league", "--runs", "3"}, "--planners"},
      {{"league", "--planners", "rcpp,nope", "--runs", "3"}, "--planners"},
      {{"league", "--planners", "rcpp,rcpp", "--runs", "3"}, "--planners"},
      {{"league", "--planners", "rcpp", "--runs", "0"}, "--runs"},
      {{"league", "--planners", "rcpp", "--jobs", "0", "--runs", "3"}, "--jobs"},
      {{"league", "--planners", "rcpp", "--runs", "3", "--time", "5"}, "--time"},
      {{"league", "--planners", "rcpp", "--runs", "3", "--planner-start-timeout", "nan"}, "--planner-start-timeout"},
      {{"league", "--planners", std::string("exec:") + MG_FAKE_EXEC_PLANNER + " no-hello", "--runs", "3"}, "--planners"},
  };
  for (const auto& [args, option] : bad) {
    const auto r = test::run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args[2] << ": " << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

// A league with a long budget in a child process; SIGTERM once its progress line shows.
TEST(LeagueCli, SigtermStopsTheLeagueWhichStillWritesItsReport) {
  const fs::path dir = test::fresh_dir("league_cli_sigterm");
  const std::string err_path = (dir / "err").string();
  std::vector<std::string> args = {"league", "--planners", "rcpp,mobil", "--time", "600", "--jobs", "2",
                                   "--report", (dir / "report").string(), "--json"};
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
  for (int i = 0; i < 30000 && test::slurp(err_path).find("league: ") == std::string::npos; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(pid, SIGTERM);
  int status = 0;
  for (int i = 0; i < 30000 && ::waitpid(pid, &status, WNOHANG) != pid; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 3) << test::slurp(err_path);
  const auto j = nlohmann::json::parse(test::slurp(dir / "report" / "league.json"));
  EXPECT_EQ(j.at("interrupted"), true);
  EXPECT_EQ(j.at("signal"), "SIGTERM");
  EXPECT_EQ(j.at("planners")[0].at("scenarios"), j.at("scenarios"));
  EXPECT_EQ(j.at("planners")[1].at("scenarios"), j.at("scenarios"));
  EXPECT_EQ(nlohmann::json::parse(test::slurp(dir / "out")).at("scenarios"), j.at("scenarios"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mg
