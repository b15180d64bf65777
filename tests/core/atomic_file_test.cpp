// write_file_atomic (core/atomic_file.h): complete files or nothing, and no temporary file left
// behind; remove_stale_temporaries deletes only the leftovers of writers that no longer run.
#include "core/atomic_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/support/scratch_files.h"

namespace mg {
namespace {

namespace fs = std::filesystem;

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicFile, NewAndReplacedFilesHoldExactlyTheContentAndNothingElseIsLeft) {
  const auto dir = test::fresh_dir("atomic");
  const auto file = dir / "sub" / "case.json";
  write_file_atomic(file.string(), "first\n");
  EXPECT_EQ(test::slurp(file), "first\n");
  write_file_atomic(file.string(), "second, longer\n");
  EXPECT_EQ(test::slurp(file), "second, longer\n");
  EXPECT_EQ(entries(file.parent_path()), 1u);
  fs::remove_all(dir);
}

TEST(AtomicFile, AnUnwritableTargetIsAnErrorNamingThePath) {
  try {
    write_file_atomic("/proc/mergeguard_x/report.json", "x");
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("/proc/mergeguard_x"), std::string::npos) << e.what();
  }
}

TEST(AtomicFile, StaleTemporariesOfDeadWritersAreRemovedAndLiveOnesKept) {
  const auto dir = test::fresh_dir("atomic");
  // A pid above the kernel's limit (pid_max <= 2^22) never runs.
  const auto dead = dir / "a.json.tmp.99999999.0";
  const auto live = dir / ("b.json.tmp." + std::to_string(::getpid()) + ".3");
  const auto other = dir / "c.json";
  for (const auto& p : {dead, live, other}) std::ofstream(p) << "x";
  EXPECT_EQ(remove_stale_temporaries(dir.string()), 1);
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mg
