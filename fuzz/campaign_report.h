// Campaign reports: a JSON summary and the same content as Markdown and HTML:
// scenarios run, rate, failures by property, rule and liable party, the signatures with their
// corpus cases (and liability reports when written), and each rule's coverage and margin
// distribution.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/campaign.h"

namespace mg::fuzz {

// The summary printed by `mergeguard fuzz --json` and saved as report.json. Only "seconds",
// "scenarios_per_second" and "date" depend on timing.
nlohmann::json campaign_summary_json(const CampaignOptions& options, const CampaignResult& result);

// The lines a reader must see first (rule_coverage.h): the rules that can apply to the planner
// but that no scenario exercised ("Warning: ..."), and the rules that cannot apply to it.
std::vector<std::string> coverage_warnings(const CampaignOptions& options, const CampaignResult& result);

// One line for people on an exec planner's process (CampaignResult::planner_process): the name and
// version it gave in `hello` and its stderr logs; empty for an in-process planner.
std::string planner_process_text(const CampaignResult& result);

// Writes report.json, report.md and report.html into `dir` (atomically, each). `liability_reports`
// maps a case path to its liability report (relative to `dir`) when one was written.
void write_campaign_report(const std::string& dir, const CampaignOptions& options, const CampaignResult& result,
                           const std::map<std::string, std::string>& liability_reports);

}  // namespace mg::fuzz
