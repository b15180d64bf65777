#include "fuzz/report_merge.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "fake_check.h"
#include "fuzz/campaign_report.h"
#include "tests/support/scratch_files.h"

namespace mg::fuzz {
namespace {

namespace fs = std::filesystem;

CampaignOptions options(int shard, int shards, std::uint64_t seed = 11) {
  CampaignOptions o;
  o.seed = seed;
  o.runs = 300;
  o.planner = "fake";
  o.corpus_dir = "";
  o.gen.max_vehicles = 3;
  o.shard_index = shard;
  o.shard_count = shards;
  return o;
}

std::string write_summary(const fs::path& dir, const std::string& name, const CampaignOptions& o,
                          const nlohmann::json& planner_process = nullptr) {
  CampaignResult r = run_campaign(o, [] { return CheckFn(test::fake_check); });
  r.planner_process = planner_process;
  const std::string path = (dir / name).string();
  std::ofstream(path) << campaign_summary_json(o, r).dump(2);
  return path;
}

nlohmann::json without_timing(nlohmann::json j) {
  for (const char* k : {"seconds", "scenarios_per_second", "first_failure_s", "first_new_failure_s", "date", "jobs"}) j.erase(k);
  return j;
}

TEST(ReportMerge, TheShardsOfACampaignMergeIntoExactlyTheUnshardedSummary) {
  const auto dir = mg::test::fresh_dir("report_merge_test_exact");
  const std::string whole = write_summary(dir, "whole.json", options(0, 1));
  const std::vector<std::string> parts = {write_summary(dir, "s2.json", options(2, 3)), write_summary(dir, "s0.json", options(0, 3)),
                                          write_summary(dir, "s1.json", options(1, 3))};
  const MergedReport m = merge_reports(parts, false);
  EXPECT_TRUE(m.complete());
  EXPECT_EQ(m.shards, (std::vector<int>{0, 1, 2}));
  std::ifstream in(whole);
  const auto expected = without_timing(nlohmann::json::parse(in));
  EXPECT_EQ(without_timing(campaign_summary_json(m.options, m.result)), expected);
  EXPECT_GT(m.result.failing_scenarios, 0u);  // the planted failure: signatures, counts and margins merged
  fs::remove_all(dir);
}

TEST(ReportMerge, GuidedShardsSumTheirGuidedRunsAndAShardOfAnotherSearchIsRefused) {
  const auto dir = mg::test::fresh_dir("report_merge_test_guided");
  auto guided = [](int shard) {
    CampaignOptions o = options(shard, 2);
    o.runs = 400;
    o.search = SearchMode::kGuided;
    o.guided.batch_runs = 16;
    return o;
  };
  const std::string s0 = write_summary(dir, "g0.json", guided(0));
  const std::string s1 = write_summary(dir, "g1.json", guided(1));
  const MergedReport m = merge_reports({s0, s1}, false);
  const CampaignResult r0 = merge_reports({s0}, true).result, r1 = merge_reports({s1}, true).result;
  EXPECT_GT(r0.guided_runs, 0u);
  EXPECT_EQ(m.result.guided_runs, r0.guided_runs + r1.guided_runs);
  EXPECT_EQ(m.result.guided_failing_scenarios, r0.guided_failing_scenarios + r1.guided_failing_scenarios);
  EXPECT_EQ(m.options.search, SearchMode::kGuided);
  EXPECT_EQ(m.result.first_failure_run, std::min(r0.first_failure_run, r1.first_failure_run));
  CampaignOptions random_shard = guided(1);
  random_shard.search = SearchMode::kRandom;
  const std::string r = write_summary(dir, "r1.json", random_shard);
  EXPECT_THROW(merge_reports({s0, r}, false), InputError);
  fs::remove_all(dir);
}

// An exec planner's shards: the merged report names the planner process once, with every shard's
// stderr logs in shard order; shards of different planner builds (hello) are not one campaign.
TEST(ReportMerge, AnExecPlannersShardsKeepItsProcessAndEveryShardsLogs) {
  const auto dir = mg::test::fresh_dir("report_merge_test_process");
  const auto process = [](const std::string& version, const std::string& log) {
    return nlohmann::json{{"hello", {{"name", "py"}, {"version", version}}}, {"logs", {log}}};
  };
  const std::string s1 = write_summary(dir, "s1.json", options(1, 2), process("1", "w1.log"));
  const std::string s0 = write_summary(dir, "s0.json", options(0, 2), process("1", "w0.log"));
  const MergedReport m = merge_reports({s1, s0}, false);
  EXPECT_EQ(m.result.planner_process,
            (nlohmann::json{{"hello", {{"name", "py"}, {"version", "1"}}}, {"logs", {"w0.log", "w1.log"}}}));
  EXPECT_EQ(campaign_summary_json(m.options, m.result).at("planner_process"), m.result.planner_process);

  const std::string other = write_summary(dir, "other.json", options(1, 2), process("2", "w1.log"));
  try {
    merge_reports({s0, other}, false);
    ADD_FAILURE() << "shards of two planner versions merged";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/planner_process/hello"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(ReportMerge, RefusesShardsOfDifferentCampaignsAMissingShardAndADuplicate) {
  const auto dir = mg::test::fresh_dir("report_merge_test_refuse");
  const std::string s0 = write_summary(dir, "s0.json", options(0, 2));
  const std::string s1 = write_summary(dir, "s1.json", options(1, 2));
  const std::string other_seed = write_summary(dir, "o1.json", options(1, 2, 12));
  EXPECT_THROW(merge_reports({s0, other_seed}, false), InputError);
  EXPECT_THROW(merge_reports({s0}, false), InputError);
  EXPECT_THROW(merge_reports({s0, s0, s1}, false), InputError);
  const MergedReport partial = merge_reports({s1}, true);
  EXPECT_FALSE(partial.complete());
  std::ofstream(dir / "broken.json") << "{\"planner\": \"fake\"}";
  try {
    merge_reports({s0, (dir / "broken.json").string()}, false);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// A shard whose fields have the wrong JSON type is refused naming the file and the key, never
// with the JSON library's own message.
TEST(ReportMerge, AFieldOfTheWrongTypeIsRefusedNamingTheFileAndTheKey) {
  const auto dir = mg::test::fresh_dir("report_merge_test_types");
  const std::string s0 = write_summary(dir, "s0.json", options(0, 2));
  const auto mutated = [&](const std::string& name, const std::string& key, const nlohmann::json& value) {
    std::ifstream in(s0);
    nlohmann::json j = nlohmann::json::parse(in);
    j[key] = value;
    std::ofstream((dir / name).string()) << j.dump();
    return (dir / name).string();
  };
  for (const auto& [key, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"planner", 5}, {"interrupted", "no"}, {"seconds", "soon"}, {"new_cases", {1, 2}}, {"margins", 3}}) {
    const std::string bad = mutated("bad_" + key + ".json", key, value);
    try {
      merge_reports({bad}, true);
      ADD_FAILURE() << key << ": expected an InputError";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("bad_" + key + ".json"), std::string::npos) << what;
      EXPECT_NE(what.find("/" + key), std::string::npos) << what;
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mg::fuzz
