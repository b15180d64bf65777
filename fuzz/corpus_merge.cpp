#include "fuzz/corpus_merge.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>

#include "core/input_error.h"

namespace mg::fuzz {
namespace {

struct Entry {
  std::string path;
  CorpusCase c;
  bool in_target = false;
  std::size_t order = 0;  // argument order, the target first
};

bool is_open(const CorpusCase& c) {
  const auto& f = c.verdict.failed_properties;
  return std::find(f.begin(), f.end(), c.signature) != f.end();
}

// Smaller first: fewer vehicles, a shorter horizon, then where it came from.
auto size_key(const Entry& e) {
  return std::make_tuple(e.c.scenario.vehicles.size(), e.c.scenario.params.sim.horizon_s, e.c.provenance.campaign_seed,
                         e.c.provenance.run_index, e.order, e.path);
}

std::string size_text(const CorpusCase& c) {
  return std::to_string(c.scenario.vehicles.size()) + " vehicles, horizon " +
         std::to_string(c.scenario.params.sim.horizon_s).substr(0, 5) + " s";
}

std::vector<Entry> load_all(const std::vector<std::string>& sources, const std::string& into) {
  std::vector<Entry> all;
  if (std::filesystem::exists(into)) {
    if (!std::filesystem::is_directory(into)) throw InputError(into, "", "--into must be a directory");
    for (const std::string& f : case_files(into)) all.push_back({f, load_case(f), true, 0});
  }
  for (std::size_t i = 0; i < sources.size(); ++i)
    for (const std::string& f : case_files(sources[i])) {
      std::error_code ec;
      if (std::filesystem::equivalent(std::filesystem::path(f).parent_path(), into, ec)) continue;  // the target named as a source too
      all.push_back({f, load_case(f), false, i + 1});
    }
  return all;
}

// One signature's open findings: the smallest stays or comes in, the rest are dropped.
void decide_open(std::vector<const Entry*> group, const std::string& into, std::vector<CorpusMergeDecision>& out) {
  std::sort(group.begin(), group.end(), [](const Entry* a, const Entry* b) { return size_key(*a) < size_key(*b); });
  const Entry& best = *group.front();
  const auto in_target = std::find_if(group.begin(), group.end(), [](const Entry* e) { return e->in_target; });
  std::string target = best.path;
  if (best.in_target) {
    out.push_back({CorpusMergeDecision::Action::kKept, best.path, best.path, best.c.signature, true, "smallest (" + size_text(best.c) + ")"});
  } else if (in_target != group.end()) {
    target = (*in_target)->path;
    out.push_back({CorpusMergeDecision::Action::kReplaced, best.path, target, best.c.signature, true,
                   "smaller (" + size_text(best.c) + ") than " + target + " (" + size_text((*in_target)->c) + ")"});
  } else {
    target = free_case_path(into, best.c.signature.file_stem());
    out.push_back({CorpusMergeDecision::Action::kAdded, best.path, target, best.c.signature, true, "new signature (" + size_text(best.c) + ")"});
  }
  for (auto it = group.begin() + 1; it != group.end(); ++it)
    if (!(*it)->in_target || (*it)->path != target)
      out.push_back({CorpusMergeDecision::Action::kDropped, (*it)->path, target, (*it)->c.signature, true,
                     "same signature, not smaller (" + size_text((*it)->c) + ")"});
}

}  // namespace

std::string to_string(CorpusMergeDecision::Action a) {
  switch (a) {
    case CorpusMergeDecision::Action::kKept: return "kept";
    case CorpusMergeDecision::Action::kAdded: return "added";
    case CorpusMergeDecision::Action::kReplaced: return "replaced";
    case CorpusMergeDecision::Action::kDropped: return "dropped";
  }
  return "unknown";
}

std::vector<CorpusMergeDecision> merge_corpora(const std::vector<std::string>& sources, const std::string& into) {
  const std::vector<Entry> all = load_all(sources, into);
  std::vector<CorpusMergeDecision> out;
  std::map<Signature, std::vector<const Entry*>> open;
  std::vector<const Entry*> holding;  // regression cases, in argument order
  for (const Entry& e : all) (is_open(e.c) ? open[e.c.signature].push_back(&e) : holding.push_back(&e));
  for (const auto& [signature, group] : open) decide_open(group, into, out);
  std::vector<const Entry*> kept;
  for (const Entry* e : holding) {
    const auto same = std::find_if(kept.begin(), kept.end(), [e](const Entry* k) {
      return k->c.signature == e->c.signature && k->c.scenario == e->c.scenario;
    });
    if (same != kept.end()) {
      out.push_back({CorpusMergeDecision::Action::kDropped, e->path, (*same)->path, e->c.signature, false, "the same regression case"});
      continue;
    }
    kept.push_back(e);
    if (e->in_target)
      out.push_back({CorpusMergeDecision::Action::kKept, e->path, e->path, e->c.signature, false, "regression case"});
    else
      out.push_back({CorpusMergeDecision::Action::kAdded, e->path, "", e->c.signature, false, "regression case"});
  }
  // Write only once every case has been read and decided; regression cases get their names last
  // so that a new open finding keeps the signature's plain file name.
  std::filesystem::create_directories(into);
  for (CorpusMergeDecision& d : out) {
    if (d.action != CorpusMergeDecision::Action::kAdded && d.action != CorpusMergeDecision::Action::kReplaced) continue;
    const Entry& e = *std::find_if(all.begin(), all.end(), [&d](const Entry& x) { return x.path == d.source; });
    if (d.target.empty()) d.target = free_case_path(into, e.c.signature.file_stem());
    write_case(e.c, d.target);
  }
  return out;
}

}  // namespace mg::fuzz
