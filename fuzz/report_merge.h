// `mergeguard report merge REPORT.json... --out DIR` (docs/fleet.md): the report.json summaries
// of a sharded campaign's shards become the report of the whole campaign. Counts, failures by
// property, rule and party, signatures and margin statistics are summed exactly (margin sums are
// kept in integer micro-units, `sum_micro`); each signature keeps its lowest first run and that
// shard's case. The shards must be of one campaign: the same planner, seed, run budget and
// generator, the same shard count N and distinct indices; all N are required unless `partial`.
#pragma once

#include <string>
#include <vector>

#include "fuzz/campaign.h"

namespace mg::fuzz {

struct MergedReport {
  CampaignOptions options;  // shard 0/1 when every shard is there (their union is the campaign)
  CampaignResult result;
  std::vector<int> shards;  // the shard indices merged
  int shard_count = 1;
  bool complete() const { return static_cast<int>(shards.size()) == shard_count; }
};

// Reads and checks every summary (InputError naming the file and JSON path), then merges.
MergedReport merge_reports(const std::vector<std::string>& report_paths, bool partial);

}  // namespace mg::fuzz
