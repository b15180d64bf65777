// `mergeguard reproduce-paper [--out DIR] [--scenario FILE]`: the RCPP paper's experiment
// (spec §11, issue #4). Exit 0 when every planner merged without collision and RCPP is no
// worse than the baseline, 1 otherwise, 2 on bad input.
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "core/output_path.h"
#include "core/scenario.h"
#include "sim/paper_report.h"

namespace mg::cli {
namespace {

int run(const std::vector<std::string>& args) {
  CLI::App app{"Reproduce the RCPP paper's simulation: metrics.json, figures and report.md"};
  std::string out_dir = "reports/paper/";
  std::string scenario_path = "corpus/scenarios/paper_merge.json";
  bool json = false;
  app.add_option("--out", out_dir, "output directory (default reports/paper/)");
  app.add_option("--scenario", scenario_path, "scenario file (default corpus/scenarios/paper_merge.json)");
  app.add_flag("--json", json, "print metrics.json on stdout");
  if (!parse_args(app, args)) return kExitOk;

  const Scenario scenario = load_scenario(scenario_path);
  prepare_output_dir("--out", out_dir);
  const PaperExperiment experiment = run_paper_experiment(scenario, scenario_path);
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
    std::cout << "wrote " << out_dir << " (metrics.json, fig4_paths.svg, fig5_motion.svg, report.md)\n";
  }
  for (const std::string& w : why) std::cerr << "reproduce-paper: " << w << "\n";
  return consistent ? kExitOk : kExitViolation;
}

const CommandRegistration registration("reproduce-paper", "reproduce-paper [--out DIR] [--scenario FILE] [--json]",
                                       run);

}  // namespace
}  // namespace mg::cli
