// mergeguard corpus merge DIR... --into DIR [--json]: one corpus from several (a fleet's shards,
// docs/fleet.md; the rules: fuzz/corpus_merge.h). Exit 0 when merged, 2 when a case cannot be
// read (nothing is written then).
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/output_path.h"
#include "fuzz/corpus_merge.h"

namespace mg::cli {
namespace {

int run_merge(const std::vector<std::string>& args) {
  CLI::App app("Merge corpora: one case per open signature (the smallest), every regression case once",
               "mergeguard corpus merge");
  std::vector<std::string> sources;
  std::string into;
  bool json = false;
  app.add_option("corpora", sources, "corpus directories (or case files) to merge")->required();
  app.add_option("--into", into, "the corpus to merge into (created if missing; its cases take part)")->required();
  app.add_flag("--json", json, "print one JSON document");
  if (!parse_args(app, args)) return kExitOk;
  prepare_output_dir("--into", into);
  const auto decisions = fuzz::merge_corpora(sources, into);
  nlohmann::json list = nlohmann::json::array();
  std::size_t written = 0;
  for (const auto& d : decisions) {
    const std::string action = fuzz::to_string(d.action);
    if (d.action == fuzz::CorpusMergeDecision::Action::kAdded || d.action == fuzz::CorpusMergeDecision::Action::kReplaced) ++written;
    if (json) {
      list.push_back({{"action", action}, {"case", d.source}, {"target", d.target}, {"signature", d.signature.key()},
                      {"open_finding", d.open_finding}, {"why", d.why}});
    } else {
      std::cout << action << std::string(9 - action.size(), ' ') << d.source;
      if (d.action == fuzz::CorpusMergeDecision::Action::kDropped) std::cout << " (kept: " << d.target << ")";
      else if (d.target != d.source) std::cout << " -> " << d.target;
      std::cout << ": " << d.signature.key() << ", " << d.why << "\n";
    }
  }
  if (json) std::cout << nlohmann::json{{"into", into}, {"written", written}, {"decisions", list}}.dump(2) << "\n";
  else std::cout << written << " case(s) written into " << into << "\n";
  return kExitOk;
}

int run_corpus(const std::vector<std::string>& args) {
  if (args.empty() || args.front() != "merge") throw UsageError("expected 'corpus merge DIR... --into DIR [--json]'");
  return run_merge(std::vector<std::string>(args.begin() + 1, args.end()));
}

}  // namespace

Command corpus_command() {
  return {"corpus", "corpus merge DIR... --into DIR [--json]", run_corpus};
}

}  // namespace mg::cli
