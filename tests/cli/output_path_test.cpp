// Every command that writes checks its output paths before any work: a path that
// cannot be created (/proc/x), a file where a directory is expected, or a directory below a file
// gives exit 2 and one line naming the option and the path, nothing on stdout, nothing written.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "cli_runner.h"
#include "tests/support/scratch_files.h"
#include "tests/support/std4_scenario.h"

namespace mg::test {
namespace {

namespace fs = std::filesystem;

const std::string kScenario = kStd4Path;

struct BadPath {
  std::string path;
  std::string reason;  // expected in the message
};

// The unwritable paths every writing command is run against, in a fresh scratch directory.
std::vector<BadPath> bad_paths(const fs::path& scratch) {
  const fs::path file = scratch / "a_file";
  std::ofstream(file) << "not a directory\n";
  return {{"/proc/mergeguard_x", "cannot create the directory"},
          {file.string(), "exists and is not a directory"},
          {(file / "below").string(), "cannot create the directory"}};
}

void expect_refused(const std::vector<std::string>& args, const std::string& option, const BadPath& bad) {
  const CliResult r = run_cli(args);
  const std::string what = args[0] + " " + option + " " + bad.path;
  EXPECT_EQ(r.exit_code, 2) << what << ": " << r.err;
  ASSERT_FALSE(r.err.empty()) << what;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << what << ": one line expected: " << r.err;
  EXPECT_NE(r.err.find(option + " " + bad.path), std::string::npos) << what << ": must name the option and path: " << r.err;
  EXPECT_NE(r.err.find(bad.reason), std::string::npos) << what << ": " << r.err;
  EXPECT_TRUE(r.out.empty()) << what << ": nothing on stdout on error";
}

TEST(OutputPaths, CheckRefusesAnUnwritableReportDirectoryBeforeSimulating) {
  const auto dir = fresh_dir("output_path");
  for (const BadPath& bad : bad_paths(dir)) expect_refused({"check", kScenario, "--report", bad.path}, "--report", bad);
  fs::remove_all(dir);
}

TEST(OutputPaths, FuzzRefusesAnUnwritableCorpusOrReportBeforeTheCampaign) {
  const auto dir = fresh_dir("output_path");
  for (const BadPath& bad : bad_paths(dir)) {
    expect_refused({"fuzz", "--runs", "1", "--corpus", bad.path}, "--corpus", bad);
    expect_refused({"fuzz", "--runs", "1", "--corpus", "", "--report", bad.path}, "--report", bad);
  }
  EXPECT_FALSE(fs::exists(dir / "corpus"));
  fs::remove_all(dir);
}

TEST(OutputPaths, ReproducePaperRefusesAnUnwritableOutputDirectory) {
  const auto dir = fresh_dir("output_path");
  for (const BadPath& bad : bad_paths(dir)) expect_refused({"reproduce-paper", "--out", bad.path}, "--out", bad);
  fs::remove_all(dir);
}

TEST(OutputPaths, CorpusAndReportMergeRefuseAnUnwritableTarget) {
  const auto dir = fresh_dir("output_path");
  const std::string cases = (fs::path(MG_SOURCE_DIR) / "corpus" / "cases").string();
  const fs::path summary = dir / "report.json";
  std::ofstream(summary) << "{}";
  for (const BadPath& bad : bad_paths(dir)) {
    expect_refused({"corpus", "merge", cases, "--into", bad.path}, "--into", bad);
    expect_refused({"report", "merge", summary.string(), "--out", bad.path}, "--out", bad);
  }
  fs::remove_all(dir);
}

TEST(OutputPaths, ReplayUpdateRefusesACaseInAReadOnlyDirectory) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only directories";
  const auto dir = fresh_dir("output_path");
  const fs::path cases = fs::path(MG_SOURCE_DIR) / "corpus" / "cases";
  const fs::path any_case = fs::directory_iterator(cases)->path();
  const fs::path copy = dir / "ro" / any_case.filename();
  fs::create_directories(copy.parent_path());
  fs::copy_file(any_case, copy);
  fs::permissions(copy.parent_path(), fs::perms::owner_read | fs::perms::owner_exec);
  expect_refused({"replay", "--update", copy.string()}, "--update", {copy.parent_path().string(), "not writable"});
  fs::permissions(copy.parent_path(), fs::perms::owner_all);
  fs::remove_all(dir);
}

TEST(OutputPaths, AWritableReportDirectoryIsCreatedWithItsParents) {
  const auto dir = fresh_dir("output_path");
  const fs::path report = dir / "new" / "nested";
  const CliResult r = run_cli({"check", kScenario, "--report", report.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(report / "report.html"));
  for (const auto& entry : fs::directory_iterator(report))
    EXPECT_EQ(entry.path().filename().string().rfind(".mergeguard-probe", 0), std::string::npos) << "probe left behind";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mg::test
