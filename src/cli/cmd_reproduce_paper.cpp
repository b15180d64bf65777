// `mergeguard reproduce-paper [--out DIR] [--scenario FILE]`: the RCPP paper's experiment
// (spec §11). Exit 0 when every planner merged without collision and RCPP is no
// worse than the baseline, 1 otherwise, 2 on bad input. With --search it searches
// the scenario space around --scenario instead and writes the ranking (docs/paper_search.md)
// and, with --search-scenario, the best candidate as a scenario file.
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/output_path.h"
#include "core/scenario.h"
#include "paper/paper_report.h"
#include "paper/paper_search.h"
#include "planner/planner_params.h"

namespace mg::cli {
namespace {

constexpr int kSearchTableRows = 15;

int run_search(const Scenario& base, const std::string& base_path, const std::string& table_path,
               const std::string& scenario_out) {
  const PaperSearch search = run_paper_search(base);
  write_file_atomic(table_path, paper_search_markdown(search, base_path, kSearchTableRows));
  if (!scenario_out.empty()) write_file_atomic(scenario_out, best_search_scenario_json(base, search).dump(2) + "\n");
  const PaperSearchResult& best = search.results.front();
  std::cout << "searched " << search.results.size() << " candidates; best reproduces " << best.reproduced << " of "
            << kPaperClaimCount << " rows; wrote " << table_path << (scenario_out.empty() ? "" : " and " + scenario_out)
            << "\n";
  return kExitOk;
}

int run(const std::vector<std::string>& args) {
  CLI::App app{"Reproduce the RCPP paper's simulation: metrics.json, figures and report.md"};
  std::string out_dir = "reports/paper/";
  std::string scenario_path = "corpus/scenarios/paper_merge.json";
  bool json = false, search = false;
  std::string search_out = "docs/paper_search.md", search_scenario;
  app.add_option("--out", out_dir, "output directory (default reports/paper/)");
  app.add_option("--scenario", scenario_path, "scenario file (default corpus/scenarios/paper_merge.json)");
  app.add_flag("--json", json, "print metrics.json on stdout");
  app.add_flag("--search", search, "search the scenario space around --scenario instead (a few minutes)");
  app.add_option("--search-out", search_out, "the search's ranking (default docs/paper_search.md)");
  app.add_option("--search-scenario", search_scenario, "also write the best candidate as a scenario file");
  if (!parse_args(app, args)) return kExitOk;

  const Scenario scenario = load_planner_scenario(scenario_path);
  if (search) {
    // Before a minute of search, not after it.
    check_output_file("--search-out", search_out);
    if (!search_scenario.empty()) check_output_file("--search-scenario", search_scenario);
    return run_search(scenario, scenario_path, search_out, search_scenario);
  }
  prepare_output_dir("--out", out_dir);
  const PaperExperiment experiment = run_paper_experiment(scenario, scenario_path, /*with_right_of_way=*/true);
  write_paper_report(experiment, out_dir);
  std::vector<std::string> why;
  const bool consistent = paper_results_consistent(experiment, why);
  if (json) {
    std::cout << paper_metrics_json(experiment).dump(2) << "\n";
  } else {
    for (const PaperRun& r : experiment.runs) {
      const PaperMetrics& m = r.metrics;
      std::cout << r.planner << ": merged " << (m.merged ? "yes" : "no") << ", collision "
                << (m.collision ? "yes" : "no") << ", merge time "
                << (m.merge_time_s ? std::to_string(*m.merge_time_s) + " s" : "n/a") << ", path length "
                << (m.path_length_m ? std::to_string(*m.path_length_m) + " m" : "n/a") << ", lateral reversals "
                << m.lateral_reversals << "\n";
    }
    std::cout << "wrote " << out_dir << " (metrics.json, fig4_paths.svg, fig5_motion.svg, fig_right_of_way.svg, report.md)\n";
  }
  for (const std::string& w : why) std::cerr << "reproduce-paper: " << w << "\n";
  return consistent ? kExitOk : kExitViolation;
}

}  // namespace

Command reproduce_paper_command() {
  return {"reproduce-paper",
          "reproduce-paper [--out DIR] [--scenario FILE] [--json] [--search [--search-out FILE] [--search-scenario FILE]]",
          run};
}

}  // namespace mg::cli
