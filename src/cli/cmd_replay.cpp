// mergeguard replay [CASE.json | DIR]... [--json]: re-run corpus cases from their JSON alone and
// compare verdict, violations and failed properties (spec §9, §10). Exit 1 naming every case
// that does not reproduce; 2 when a case cannot be read (future format_version included).
// --update records the replayed verdict in the cases that do not reproduce (after a planner fix
// the minimal case stays in the corpus as a regression test that now holds; docs/fuzzing.md).
// --planner P replays every case against P instead of the planner it names (to check a fix),
// comparing with the recorded verdict as it stands.
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "check/checked_run.h"
#include "cli/command.h"
#include "cli/planner_option.h"
#include "core/input_error.h"
#include "core/output_path.h"
#include "fuzz/corpus_case.h"
#include "fuzz/replay.h"
#include "planner/exec_planner.h"
#include "planner/planner.h"
#include "rules/check.h"

namespace mg::cli {
namespace {

int run_replay(const std::vector<std::string>& args) {
  CLI::App app("Replay corpus cases and compare their recorded verdicts", "mergeguard replay");
  std::vector<std::string> paths;
  bool json = false;
  bool update = false;
  PlannerChoice choice;
  app.add_option("cases", paths, "case files or directories of cases (default corpus/cases)");
  add_planner_options(app, choice, "replay against this planner (registered or 'exec:COMMAND ARGS') instead of each case's own");
  app.add_flag("--json", json, "print one JSON document");
  app.add_flag("--update", update, "rewrite the recorded verdict of cases that do not reproduce");
  if (!parse_args(app, args)) return kExitOk;
  if (paths.empty()) paths.push_back("corpus/cases");
  if (update && !choice.name.empty())
    throw UsageError("--update records what each case's own planner does now: not with --planner");

  // Load (and so validate) every case before running any.
  std::vector<std::pair<std::string, fuzz::CorpusCase>> cases;
  for (const std::string& p : paths)
    for (const std::string& file : fuzz::case_files(p)) {
      fuzz::CorpusCase c = fuzz::load_case(file);
      if (choice.name.empty() && !is_exec_planner(c.signature.planner) && !make_planner(c.signature.planner))
        throw InputError(file, "/planner", "unknown planner '" + c.signature.planner + "'");
      if (update) check_output_file("--update", file);
      cases.emplace_back(file, std::move(c));
    }
  // Every exec planner starts once before any case runs: one that cannot is a usage error.
  std::set<std::string> planners;
  for (const auto& [file, c] : cases) planners.insert(choice.name.empty() ? c.signature.planner : choice.name);
  for (const std::string& name : planners) start_planner(name, choice);

  nlohmann::json report = nlohmann::json::array();
  int failed = 0;
  int updated_count = 0;
  for (const auto& [file, c] : cases) {
    const std::string planner = choice.name.empty() ? c.signature.planner : choice.name;
    const fuzz::ReplayResult r =
        fuzz::replay_case(c, [&planner](const Scenario& s) { return check_scenario(s, planner); });
    if (!r.reproduces && update) {
      fuzz::CorpusCase updated = c;
      updated.verdict = r.actual;
      fuzz::write_case(updated, file);
      ++updated_count;
    } else if (!r.reproduces) {
      ++failed;
    }
    if (json) {
      report.push_back({{"case", file}, {"signature", c.signature.key()}, {"reproduces", r.reproduces}, {"updated", !r.reproduces && update},
                        {"differences", r.differences}});
    } else {
      std::cout << (r.reproduces ? "reproduces         " : update ? "updated            " : "DOES NOT REPRODUCE ")
                << file << "\n";
      for (const std::string& d : r.differences) std::cout << "    " << d << "\n";
    }
  }
  if (json) {
    std::cout << nlohmann::json{{"cases", cases.size()}, {"not_reproduced", failed}, {"updated", updated_count}, {"results", report}}.dump(2) << "\n";
  } else {
    std::cout << cases.size() - static_cast<std::size_t>(failed + updated_count) << " of " << cases.size()
              << " cases reproduce" << (update ? ", " + std::to_string(updated_count) + " updated" : "") << "\n";
  }
  return failed > 0 ? kExitViolation : kExitOk;
}

}  // namespace

Command replay_command() {
  return {"replay", "replay [CASE.json | DIR]... [--planner P|exec:CMD] [--planner-timeout S] [--planner-start-timeout S] [--json] [--update]", run_replay};
}

}  // namespace mg::cli
