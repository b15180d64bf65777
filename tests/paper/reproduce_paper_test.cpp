// `mergeguard reproduce-paper` end to end: the files appear and the metrics are
// internally consistent — computed by the run, never written down here.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(ReproducePaper, WritesConsistentMetricsFiguresAndReport) {
  const char* cli = std::getenv("MG_CLI");
  if (cli == nullptr) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  const fs::path out = fs::temp_directory_path() / ("mg_paper_" + std::to_string(::getpid()));
  fs::remove_all(out);
  const std::string cmd = std::string(cli) + " reproduce-paper --out " + out.string() + " --scenario " +
                          MG_SOURCE_DIR "/corpus/scenarios/paper_merge.json > " + (out.string() + ".log") + " 2>&1";
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 0) << read(out.string() + ".log");

  const nlohmann::json m = nlohmann::json::parse(read(out / "metrics.json"));
  for (const char* planner : {"tripfield", "rcpp", "rcpp-coop"}) {
    const auto& p = m.at("planners").at(planner);
    EXPECT_TRUE(p.at("merged").get<bool>()) << planner;
    EXPECT_FALSE(p.at("collision").get<bool>()) << planner;
    EXPECT_LE(p.at("sideslip_min_rad").get<double>(), p.at("sideslip_max_rad").get<double>());
    EXPECT_LE(p.at("ego_speed_min_mps").get<double>(), p.at("ego_speed_max_mps").get<double>());
    EXPECT_GE(p.at("obstacle_speed_min_mps").get<double>(), 0.0);
    EXPECT_GE(p.at("path_length_m").get<double>(), 0.0);
  }
  const auto& tf = m["planners"]["tripfield"];
  for (const char* rcpp : {"rcpp", "rcpp-coop"}) {
    const auto& p = m["planners"][rcpp];
    EXPECT_LE(p["merge_time_s"].get<double>(), tf["merge_time_s"].get<double>()) << rcpp;
    EXPECT_LE(p["path_length_m"].get<double>(), tf["path_length_m"].get<double>()) << rcpp;
    EXPECT_EQ(p["lateral_reversals"].get<int>(), 0) << rcpp << " oscillates";
    const double saving = m.at("merge_time_saving_pct").at(rcpp).get<double>();
    const double expected = 100.0 * (tf["merge_time_s"].get<double>() - p["merge_time_s"].get<double>()) /
                            tf["merge_time_s"].get<double>();
    EXPECT_NEAR(saving, expected, 1e-9);
    EXPECT_GE(m.at("path_length_reduction_pct").at(rcpp).get<double>(), 0.0);
  }
  // The chosen scenario reproduces at least 13 of the 15 rows with default planners,
  // and the cooperative run really cooperates (the last row).
  EXPECT_GE(m.at("claims_reproduced").get<int>(), 13);
  ASSERT_EQ(m.at("claims").size(), 15u);
  EXPECT_TRUE(m["claims"][14]["reproduced"].get<bool>()) << m["claims"][14]["ours"];
  EXPECT_TRUE(m["claims"][13]["reproduced"].get<bool>()) << "steady coop ego speed: " << m["claims"][13]["ours"];
  EXPECT_FALSE(m.at("right_of_way").at("rcpp-coop").empty());
  for (const char* svg : {"fig4_paths.svg", "fig5_motion.svg", "fig_right_of_way.svg"}) {
    const std::string text = read(out / svg);
    EXPECT_NE(text.find("<svg"), std::string::npos) << svg;
    EXPECT_NE(text.find("RCPP cooperative"), std::string::npos) << svg << " names the cooperative run";
  }
  EXPECT_NE(read(out / "fig5_motion.svg").find("paper: TriPField below 9 m/s"), std::string::npos)
      << "the paper's ranges are drawn as bands";
  EXPECT_NE(read(out / "fig4_paths.svg").find("merge zone: RCPP cooperative"), std::string::npos);
  const std::string report = read(out / "report.md");
  EXPECT_NE(report.find("72.3 %"), std::string::npos) << "the paper's figure is in the table";
  EXPECT_NE(report.find("Merge time"), std::string::npos);
  fs::remove_all(out);
  fs::remove(out.string() + ".log");
}

TEST(ReproducePaper, SearchWithAMissingScenarioIsBadInput) {
  const char* cli = std::getenv("MG_CLI");
  if (cli == nullptr) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  const std::string cmd = std::string(cli) + " reproduce-paper --search --scenario /nonexistent.json --search-out " +
                          (fs::temp_directory_path() / "mg_paper_search.md").string() + " > /dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
}

TEST(ReproducePaper, SearchRefusesAnUnwritableOutputBeforeSearching) {
  const char* cli = std::getenv("MG_CLI");
  if (cli == nullptr) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  const std::string cmd = std::string(cli) + " reproduce-paper --search --search-out /nonexistent/dir/search.md " +
                          "--scenario " MG_SOURCE_DIR "/corpus/scenarios/paper_merge.json > /dev/null 2>&1";
  const auto start = std::chrono::steady_clock::now();
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10)) << "refused before the search";
}

TEST(ReproducePaper, MissingScenarioIsBadInput) {
  const char* cli = std::getenv("MG_CLI");
  if (cli == nullptr) GTEST_SKIP() << "MG_CLI not set (run through ctest)";
  const std::string cmd = std::string(cli) + " reproduce-paper --scenario /nonexistent.json --out " +
                          (fs::temp_directory_path() / "mg_paper_none").string() + " > /dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
}

}  // namespace
