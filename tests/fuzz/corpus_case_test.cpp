#include "fuzz/corpus_case.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "fake_check.h"
#include "fuzz/scenario_gen.h"
#include "tests/support/scratch_files.h"

namespace mg::fuzz {
namespace {

namespace fs = std::filesystem;

CorpusCase sample_case() {
  CorpusCase c;
  c.scenario = generate_scenario(run_seed(5, 0), {}).value();
  MainVehicle v;
  v.x_m = c.scenario.ego.x_m + 10.0;
  c.scenario.vehicles = {v};
  const RunOutcome o = run_properties(c.scenario, test::fake_check, "fake", true);
  c.verdict = verdict_of(o);
  c.failure = o.failures.at(0);
  c.signature = signature_of("fake", c.failure);
  c.provenance = {"mergeguard fuzz", 5, 0, 3, 10, true, "2026-01-01T00:00:00Z"};
  return c;
}

TEST(CorpusCase, RoundTripsThroughJson) {
  const CorpusCase c = sample_case();
  const CorpusCase back = case_from_json(case_to_json(c), "test");
  EXPECT_EQ(back.signature, c.signature);
  EXPECT_EQ(back.scenario, c.scenario);
  EXPECT_EQ(back.verdict.violations, c.verdict.violations);
  EXPECT_EQ(back.verdict.failed_properties, c.verdict.failed_properties);
  EXPECT_EQ(back.verdict.trace_digest, c.verdict.trace_digest);
  EXPECT_EQ(back.provenance.run_index, 0u);
  EXPECT_EQ(back.failure.rule, "fake_proximity");
}

TEST(CorpusCase, RecordsEverythingDesignSection9Asks) {
  const auto j = case_to_json(sample_case());
  for (const char* key : {"format_version", "scenario", "planner", "property", "verdict", "provenance"})
    EXPECT_TRUE(j.contains(key)) << key;
  const auto& v = j.at("verdict").at("violations").at(0);
  for (const char* key : {"rule", "liable", "time_s", "margin"}) EXPECT_TRUE(v.contains(key)) << key;
  for (const char* key : {"campaign_seed", "run_index", "shrink_steps", "date"})
    EXPECT_TRUE(j.at("provenance").contains(key)) << key;
}

TEST(CorpusCase, AFutureFormatVersionIsAnInputError) {
  auto j = case_to_json(sample_case());
  j["format_version"] = kCorpusFormatVersion + 1;
  j["a_key_from_the_future"] = true;
  try {
    case_from_json(j, "future.json");
    FAIL() << "accepted a future format version";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("future.json: /format_version: format version 2 is newer"), std::string::npos)
        << e.what();
  }
}

TEST(CorpusCase, InvalidCasesAreRejectedWithTheirPath) {
  auto j = case_to_json(sample_case());
  j["planner"] = "other";
  EXPECT_THROW(case_from_json(j, "x"), InputError);
  j = case_to_json(sample_case());
  j["verdict"]["violations"][0]["margin"] = "big";
  EXPECT_THROW(case_from_json(j, "x"), InputError);
  j = case_to_json(sample_case());
  j["scenario"]["ego"]["speed_mps"] = -1;
  EXPECT_THROW(case_from_json(j, "x"), InputError);
  j = case_to_json(sample_case());
  j["extra"] = 1;
  EXPECT_THROW(case_from_json(j, "x"), InputError);
}

TEST(CorpusCase, WritesAtomicallyAndListsOnlyFinishedJsonFiles) {
  const auto dir = mg::test::fresh_dir("corpus_test_list");
  const CorpusCase c = sample_case();
  write_case(c, (dir / "b.json").string());
  write_case(c, (dir / "a.json").string());
  std::ofstream(dir / "c.json.tmp.123.0") << "{ half";  // a temporary file of an interrupted write
  std::ofstream(dir / "notes.txt") << "hello";
  const auto files = case_files(dir.string());
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(fs::path(files[0]).filename(), "a.json");
  EXPECT_EQ(corpus_signatures(dir.string()), (std::set<Signature>{c.signature}));
  EXPECT_EQ(load_case(files[1]).scenario, c.scenario);
  fs::remove_all(dir);
}

TEST(CorpusCase, AMissingCorpusHasNoSignaturesButAMissingCaseIsAnError) {
  EXPECT_TRUE(corpus_signatures("/nonexistent/mg_corpus").empty());
  EXPECT_THROW(case_files("/nonexistent/mg_case.json"), InputError);
}

}  // namespace
}  // namespace mg::fuzz
