// A league's report (docs/league.md): league.json (one entry per planner under "planners"),
// league.md and league.html with the same table (report/report_table.h), the safety-against-
// efficiency plot (league.svg, inline in the HTML), failures by rule and by liable party, and links
// to each planner's worst runs, saved as corpus cases with their liability reports as `fuzz` saves
// its findings.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "league/league.h"
#include "report/report_table.h"

namespace mg::league {

// Where a worst run was saved, relative to the report directory.
struct SavedCase {
  std::string case_path;         // cases/<signature>.json, a corpus case (fuzz/corpus_case.h)
  std::string liability_report;  // cases/<signature>/report.html; empty when there is no run to report on
};
using SavedCases = std::map<fuzz::Signature, SavedCase>;

// Runs each planner's worst run of every signature again (scenario i of the seed), with its
// decision records, and writes it as a corpus case (not shrunk: the worst run as it happened;
// `mergeguard replay` runs it) and its liability report into DIR/cases/.
SavedCases save_worst_cases(const std::string& dir, const LeagueOptions& options, const LeagueResult& result);

// One row per planner: the columns docs/league.md explains.
ReportTable standings_table(const LeagueResult& result);
// Failing runs by rule (or by liable party class): one row per rule, one column per planner.
ReportTable failures_table(const LeagueResult& result, bool by_party);
// Failing share (with its 95 % Wilson interval) against the median merge time, one point per
// planner that merged at least once.
std::string safety_efficiency_svg(const LeagueResult& result);

// What `league --json` prints and league.json holds. Only "seconds", "jobs" and "date" depend on
// timing and the machine; the rest is a function of the planners, the seed and the runs.
nlohmann::json league_json(const LeagueOptions& options, const LeagueResult& result, const SavedCases& saved);

// Writes league.json, league.md, league.html and league.svg into `dir` (atomically, each).
void write_league_report(const std::string& dir, const LeagueOptions& options, const LeagueResult& result,
                         const SavedCases& saved);

}  // namespace mg::league
