// What a campaign report says for people (fuzz/campaign_report.h).
#include "fuzz/campaign_report.h"

#include <string>

#include <gtest/gtest.h>

namespace mg::fuzz {
namespace {

// An exec planner's process is named by what it said in `hello`, with its logs, in words rather
// than as the summary's JSON; an in-process planner has no such line.
TEST(CampaignReport, AnExecPlannersProcessIsNamedByItsHelloAndItsLogs) {
  CampaignResult r;
  EXPECT_EQ(planner_process_text(r), "");
  r.planner_process = {{"hello", {{"name", "python-naive-gap"}, {"version", "1"}}},
                       {"logs", {"out/planner-worker-0.log", "out/planner-worker-1.log"}}};
  EXPECT_EQ(planner_process_text(r),
            "Planner process: python-naive-gap version 1 (from its hello); its stderr logs: "
            "out/planner-worker-0.log out/planner-worker-1.log");
}

}  // namespace
}  // namespace mg::fuzz
