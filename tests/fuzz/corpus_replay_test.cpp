// CI replays the whole corpus: every case in corpus/cases reproduces its
// recorded verdict, violations and failed properties from its JSON alone.
#include <gtest/gtest.h>

#include "check/checked_run.h"
#include "fuzz/corpus_case.h"
#include "fuzz/replay.h"
#include "rules/check.h"

namespace mg::fuzz {
namespace {

TEST(CorpusReplay, EveryCaseInTheCorpusReproduces) {
  const auto files = case_files(std::string(MG_SOURCE_DIR) + "/corpus/cases");
  for (const std::string& file : files) {
    const CorpusCase c = load_case(file);
    const std::string planner = c.signature.planner;
    const ReplayResult r = replay_case(c, [&](const Scenario& s) { return check_scenario(s, planner); });
    std::string why;
    for (const std::string& d : r.differences) why += "\n  " + d;
    EXPECT_TRUE(r.reproduces) << file << why;
  }
}

}  // namespace
}  // namespace mg::fuzz
