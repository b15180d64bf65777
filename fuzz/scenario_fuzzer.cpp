// libFuzzer target for scenario bytes (docs/fuzzing.md "Coverage-guided fuzzing"): every input
// decodes to a scenario inside the generator's ranges (fuzz/byte_scenario.h), which is simulated
// and checked with every property, determinism included; a property failure prints its signature
// and the scenario JSON and aborts. The input formats have their own targets
// (json_loader_fuzzer, commonroad_fuzzer), so that each mutates one kind of input with its own
// seeds and dictionary.
// Environment: MG_FUZZ_PLANNER (default rcpp) names the planner under test; MG_FUZZ_CASE_DIR:
// write each failure there as a corpus case (found_by "libFuzzer", not shrunk) before aborting;
// MG_FUZZ_KNOWN_CASES: a corpus directory whose open findings are known, so that a failure of
// the same planner, rule and party class is not reported (whichever property it fails: an open
// progress finding also fails ego_never_liable): the run aborts on crashes, sanitizer reports
// and failures the corpus has no open finding of.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <set>
#include <string>

#include "fuzz/byte_scenario.h"
#include "fuzz/corpus_case.h"
#include "fuzz/properties.h"
#include "planner/planner.h"
#include "rules/check.h"
#include "check/checked_run.h"

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

const std::set<mg::fuzz::Signature>& known_signatures() {
  static const std::set<mg::fuzz::Signature> known = [] {
    const char* dir = std::getenv("MG_FUZZ_KNOWN_CASES");
    return dir != nullptr ? mg::fuzz::corpus_signatures(dir) : std::set<mg::fuzz::Signature>{};
  }();
  return known;
}

[[noreturn]] void report_and_abort(const mg::Scenario& s, const mg::fuzz::RunOutcome& outcome,
                                   const mg::fuzz::PropertyFailure& f) {
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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const mg::Scenario s = mg::fuzz::scenario_from_bytes(data, size);
  const std::string& planner = planner_name();
  const auto outcome = mg::fuzz::run_properties(
      s, [&planner](const mg::Scenario& x) { return mg::check_scenario(x, planner); }, planner, true);
  const auto known = [&](const mg::fuzz::PropertyFailure& f) {
    const mg::fuzz::Signature sig = mg::fuzz::signature_of(outcome.planner, f);
    return std::any_of(known_signatures().begin(), known_signatures().end(), [&](const mg::fuzz::Signature& k) {
      return k.planner == sig.planner && k.rule == sig.rule && k.party == sig.party;
    });
  };
  const auto unknown = std::find_if(outcome.failures.begin(), outcome.failures.end(),
                                    [&](const mg::fuzz::PropertyFailure& f) { return !known(f); });
  if (unknown != outcome.failures.end()) report_and_abort(s, outcome, *unknown);
  return 0;
}
