// prepare_output_dir / check_output_file (core/output_path.h): the one check every writing
// command makes before any work; each refusal is one line naming the option, path and reason.
#include "core/output_path.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/support/scratch_files.h"

namespace mg {
namespace {

namespace fs = std::filesystem;

std::string refusal(const std::string& dir) {
  try {
    prepare_output_dir("--report", dir);
  } catch (const OutputPathError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputPath, ACreatableDirectoryIsCreatedWithItsParentsAndLeftEmpty) {
  const auto dir = test::fresh_dir("outpath");
  const auto target = dir / "a" / "b";
  EXPECT_NO_THROW(prepare_output_dir("--report", target.string()));
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_TRUE(fs::is_empty(target));
  fs::remove_all(dir);
}

TEST(OutputPath, UncreatableFileAndBelowAFilePathsAreRefusedWithTheirReason) {
  const auto dir = test::fresh_dir("outpath");
  const auto file = dir / "f";
  std::ofstream(file) << "x";
  EXPECT_EQ(refusal("/proc/mergeguard_x"), "--report /proc/mergeguard_x: cannot create the directory (No such file or directory)");
  EXPECT_EQ(refusal(file.string()), "--report " + file.string() + ": exists and is not a directory");
  EXPECT_NE(refusal((file / "x").string()).find("cannot create the directory (Not a directory)"), std::string::npos);
  EXPECT_NE(refusal("").find("empty path"), std::string::npos);
  fs::remove_all(dir);
}

TEST(OutputPath, AFileToRewriteMustNotBeADirectory) {
  const auto dir = test::fresh_dir("outpath");
  EXPECT_THROW(check_output_file("--update", dir.string()), OutputPathError);
  EXPECT_NO_THROW(check_output_file("--update", (dir / "case.json").string()));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mg
