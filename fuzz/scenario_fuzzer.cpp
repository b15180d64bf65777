// libFuzzer entry point (issue #6 item 6; docs/fuzzing.md "Coverage-guided fuzzing"): bytes ->
// scenario -> check -> abort on a property failure. Inputs that start with '{' are JSON and go
// through the strict loaders instead (a scenario, a corpus case when it has a "scenario" key, an
// observable trace when it has a "format" key), and inputs that start with '<' are CommonRoad XML
// recordings for the audit's loader, road reconstruction and audit (issue #17):
// rejected input is fine, a crash or sanitizer report is not (issue #7 item 4).
// Environment: MG_FUZZ_PLANNER (default rcpp); MG_FUZZ_CASE_DIR: write each failure there as a
// corpus case (found_by "libFuzzer", not shrunk) before aborting; MG_FUZZ_LOADERS_ONLY=1: every
// input is JSON or XML text for the loaders (no simulation), for fuzzing the input boundary alone.
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

#include "audit/recording_audit.h"
#include "core/input_error.h"
#include "core/json_reader.h"
#include "core/observed_trace_json.h"
#include "fuzz/byte_scenario.h"
#include "fuzz/corpus_case.h"
#include "fuzz/properties.h"
#include "planner/planner.h"
#include "planner/planner_params.h"
#include "recording/commonroad_reader.h"
#include "recording/road_layout.h"
#include "rules/check.h"
#include "sim/checked_run.h"

namespace {

const std::string& planner_name() {
  static const std::string name = [] {
    const char* env = std::getenv("MG_FUZZ_PLANNER");
    const std::string n = env != nullptr ? env : "rcpp";
    if (!mg::make_planner(n)) {
      std::cerr << "MG_FUZZ_PLANNER: unknown planner '" << n << "'\n";
      std::abort();
    }
    return n;
  }();
  return name;
}

// Loader fuzzing: only InputError is an acceptable outcome for hostile JSON.
void load_json(const std::uint8_t* data, std::size_t size) {
  try {
    const nlohmann::json j = mg::parse_json_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz input");
    if (j.is_object() && j.contains("scenario")) mg::fuzz::case_from_json(j, "fuzz input");
    else if (j.is_object() && j.contains("format")) mg::observed_trace_from_json(j, "fuzz input");
    else mg::planner_scenario_from_json(j, "fuzz input");
  } catch (const mg::InputError&) {
  }
}

// Recording fuzzing: a recording the loader accepts is audited; only InputError may come out.
void load_xml(const std::uint8_t* data, std::size_t size) {
  try {
    const mg::Recording r = mg::parse_recording(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz input");
    const mg::RoadLayout road = mg::build_road_layout(r);
    mg::audit_recording(r, road, mg::default_audit_profile());
  } catch (const mg::InputError&) {
  }
}

[[noreturn]] void report_and_abort(const mg::Scenario& s, const mg::fuzz::RunOutcome& outcome) {
  const mg::fuzz::PropertyFailure& f = outcome.failures.front();
  const mg::fuzz::Signature sig = mg::fuzz::signature_of(outcome.planner, f);
  std::cerr << "property failure: " << sig.key() << ": " << f.detail << "\nscenario: " << mg::scenario_to_json(s).dump()
            << "\n";
  if (const char* dir = std::getenv("MG_FUZZ_CASE_DIR")) {
    mg::fuzz::CorpusCase c;
    c.signature = sig;
    c.failure = f;
    c.scenario = s;
    c.scenario.name = sig.file_stem();
    c.verdict = mg::fuzz::verdict_of(outcome);
    c.provenance.found_by = "libFuzzer";
    c.provenance.date = mg::fuzz::utc_now_iso8601();
    const std::string path = std::string(dir) + "/" + sig.file_stem() + ".json";
    mg::fuzz::write_case(c, path);
    std::cerr << "case written: " << path << "\n";
  }
  std::abort();
}

bool loaders_only() {
  static const bool only = [] {
    const char* env = std::getenv("MG_FUZZ_LOADERS_ONLY");
    return env != nullptr && std::string(env) == "1";
  }();
  return only;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 0 && data[0] == '<') {
    load_xml(data, size);
    return 0;
  }
  if (loaders_only() || (size > 0 && data[0] == '{')) {
    load_json(data, size);
    return 0;
  }
  const mg::Scenario s = mg::fuzz::scenario_from_bytes(data, size);
  const std::string& planner = planner_name();
  const auto outcome = mg::fuzz::run_properties(
      s, [&planner](const mg::Scenario& x) { return mg::check_scenario(x, planner); }, planner, true);
  if (!outcome.failures.empty()) report_and_abort(s, outcome);
  return 0;
}
