// `mergeguard corpus merge DIR... --into DIR` (docs/fleet.md): the corpora of a fleet's shards
// (or of several campaigns) become one. An open finding (a case whose recorded verdict still
// fails with its signature) is kept once per signature, the smallest scenario winning (fewer
// vehicles, then a shorter horizon, then the lower campaign seed and run index, then the order
// of the arguments, the target first); a regression case that holds is a test of its own and is
// kept unless the same signature and scenario are already there. Every case is loaded and
// validated before anything is written, and each file is written atomically.
#pragma once

#include <string>
#include <vector>

#include "fuzz/corpus_case.h"

namespace mg::fuzz {

struct CorpusMergeDecision {
  enum class Action { kKept, kAdded, kReplaced, kDropped };
  Action action = Action::kKept;
  std::string source;  // the case file decided on
  std::string target;  // where it is (kKept), is written (kAdded, kReplaced), or what beat it (kDropped)
  Signature signature;
  bool open_finding = true;
  std::string why;     // one line
};
std::string to_string(CorpusMergeDecision::Action a);

// Decides, then writes the added and replaced cases into `into` (created if missing). Throws
// InputError naming the first case that cannot be read, before anything is written.
std::vector<CorpusMergeDecision> merge_corpora(const std::vector<std::string>& sources, const std::string& into);

}  // namespace mg::fuzz
