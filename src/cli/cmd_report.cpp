// mergeguard report merge REPORT.json... --out DIR [--partial] [--json]: one campaign report from
// the report.json of each shard of a fleet campaign (docs/fleet.md; fuzz/report_merge.h).
// Exit 0 when merged, 2 when a report cannot be read or the reports are not one campaign's.
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/output_path.h"
#include "fuzz/campaign_report.h"
#include "fuzz/report_merge.h"

namespace mg::cli {
namespace {

int run_merge(const std::vector<std::string>& args) {
  CLI::App app("Merge the report.json of a sharded campaign's shards into one report", "mergeguard report merge");
  std::vector<std::string> reports;
  std::string out;
  bool partial = false;
  bool json = false;
  app.add_option("reports", reports, "the shards' report.json files")->required();
  app.add_option("--out", out, "write report.json, report.md, report.html here")->required();
  app.add_flag("--partial", partial, "merge even when some shards are missing");
  app.add_flag("--json", json, "print the merged summary on stdout");
  if (!parse_args(app, args)) return kExitOk;
  prepare_output_dir("--out", out);
  const fuzz::MergedReport m = fuzz::merge_reports(reports, partial);
  fuzz::write_campaign_report(out, m.options, m.result, {});
  if (json) {
    std::cout << fuzz::campaign_summary_json(m.options, m.result).dump(2) << "\n";
  } else {
    std::cout << "merged " << m.shards.size() << " of " << m.shard_count << " shards" << (m.complete() ? "" : " (partial)")
              << ": " << m.result.scenarios << " scenarios, " << m.result.failing_scenarios << " failing, "
              << m.result.signatures.size() << " signatures -> " << out << "/report.{json,md,html}\n";
  }
  return kExitOk;
}

int run_report(const std::vector<std::string>& args) {
  if (args.empty() || args.front() != "merge")
    throw UsageError("expected 'report merge REPORT.json... --out DIR [--partial] [--json]'");
  return run_merge(std::vector<std::string>(args.begin() + 1, args.end()));
}

}  // namespace

Command report_command() {
  return {"report", "report merge REPORT.json... --out DIR [--partial] [--json]", run_report};
}

}  // namespace mg::cli
