// A corpus case (spec §9): one self-contained JSON file holding a minimal failing scenario,
// the planner, the property and signature it failed, the verdict and violations it produced,
// and how it was found. It replays from the JSON alone. Format: docs/fuzzing.md "Corpus cases".
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/party.h"
#include "core/scenario.h"
#include "fuzz/properties.h"
#include "planner/exec_protocol.h"
#include "rules/check.h"

namespace mg::fuzz {

inline constexpr int kCorpusFormatVersion = 1;

struct CaseViolation {
  std::string rule;
  Party liable_id = Party::nobody();
  std::optional<double> time_s;   // first violation time
  double margin = 0.0;            // minimum robustness margin (< 0)
  std::string unit;
  bool operator==(const CaseViolation&) const = default;
};

// What a check produced, in the form a case records and replay compares.
struct CaseVerdict {
  bool holds = true;
  bool collision = false;
  Party collision_liable_id = Party::nobody();
  std::vector<CaseViolation> violations;          // rules that do not hold, in checker order
  std::vector<Signature> failed_properties;       // every property failure's signature, sorted, unique
  std::uint64_t trace_digest = 0;                 // informative: digests differ between builds
};

struct Provenance {
  std::string found_by = "mergeguard fuzz";
  std::uint64_t campaign_seed = 0;
  std::uint64_t run_index = 0;
  int shrink_steps = 0;
  int shrink_attempts = 0;
  bool shrink_minimal = false;
  std::string date;               // ISO 8601, UTC
};

struct CorpusCase {
  int format_version = kCorpusFormatVersion;
  Signature signature;            // the failure this case keeps (its planner is the case's planner)
  PropertyFailure failure;        // that failure in the final, shrunk scenario
  CaseVerdict verdict;
  Provenance provenance;
  Scenario scenario;
  // What an exec planner said it was in its hello (key "planner_hello"); absent for registered
  // planners. Informative: replay runs the command in "planner" whatever it answers.
  std::optional<PlannerIdentity> planner_hello;
};

CaseVerdict verdict_of(const RunOutcome& outcome);

nlohmann::json case_to_json(const CorpusCase& c);
// Validates everything (unknown keys, types, a future format_version, the scenario itself);
// errors are InputError naming `source` and the JSON path.
CorpusCase case_from_json(const nlohmann::json& j, const std::string& source);
CorpusCase load_case(const std::string& path);
// Atomic (core/atomic_file.h): a reader never sees a half-written case.
void write_case(const CorpusCase& c, const std::string& path);

// The *.json files of a directory (sorted; temporary files of atomic writes are ignored), or
// the path itself when it is a file. Throws InputError when the path does not exist.
std::vector<std::string> case_files(const std::string& path);
// Signatures of the open findings in `dir`: the cases whose recorded verdict still fails with
// their signature (a case updated to hold after a fix is a regression test and does not hide a
// new failure of the same signature). Missing directory: none. Unreadable or invalid cases raise
// InputError: a corpus must stay loadable.
std::set<Signature> corpus_signatures(const std::string& dir);

// DIR/<stem>.json, or DIR/<stem>-2.json, -3, ... when that file already exists.
std::string free_case_path(const std::string& dir, const std::string& stem);

std::string utc_now_iso8601();

}  // namespace mg::fuzz
