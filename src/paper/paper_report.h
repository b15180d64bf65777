// `mergeguard reproduce-paper` (spec §11): runs the paper's merge scenario with
// the TriPField-style baseline and both RCPP variants, and writes metrics.json, the figures in
// the manner of the paper's Fig. 4 and Fig. 5, and report.md comparing with the paper.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/scenario.h"
#include "paper/paper_claims.h"
#include "paper/paper_metrics.h"
#include "sim/trace.h"

namespace mg {

// The experiment repeated with the first main-lane vehicle moved by dx_m and its speed (and
// desired speed) changed by dv_mps, to show how much the comparison depends on our choice of
// the scenario, which the paper does not publish.
struct SensitivityCase {
  double dx_m = 0.0, dv_mps = 0.0;
  std::vector<PaperMetrics> metrics;  // in kPaperPlanners order
  int claims_reproduced = 0;          // of the kPaperClaimCount claims, on this variant
};

// The three planners on s, in kPaperPlanners order; with_right_of_way judges each run
// (check/checked_run.h) to fill PaperRun::right_of_way, which only the report shows.
std::vector<PaperRun> run_paper_planners(const Scenario& s, bool with_right_of_way = false);

struct PaperExperiment {
  Scenario scenario;
  std::string scenario_path;
  std::vector<PaperRun> runs;  // in kPaperPlanners order
  std::vector<SensitivityCase> sensitivity;
  // Not the defaults (paper/paper_variant.h): RCPP keeping its lane at the cruise speed after the
  // merge, on the scenario with its first main-lane vehicle only.
  Scenario variant_scenario;
  std::vector<PaperRun> variant_runs;
};

// Runs the three planners on s and, when s has a main-lane vehicle, the sensitivity grid
// dx in {-12, -6, 0, 6, 12} m x dv in {-2, 0, 2} m/s.
PaperExperiment run_paper_experiment(const Scenario& s, const std::string& scenario_path,
                                     bool with_right_of_way = false);

// {"planners": {name: metrics}, "merge_time_saving_pct": {"rcpp": x, "rcpp-coop": y},
//  "path_length_reduction_pct": {...}, "scenario": path, "definitions": {...}}
nlohmann::json paper_metrics_json(const PaperExperiment& e);

// The run of a planner (std::logic_error when the experiment has none).
const PaperRun& paper_run_of(const PaperExperiment& e, const std::string& planner);

// report.md; the figures are paper/paper_figures.h's.
std::string paper_report_markdown(const PaperExperiment& e);

// Every planner merged without collision and both RCPP variants are no worse than the
// baseline in merge time and path length; `why` lists what failed.
bool paper_results_consistent(const PaperExperiment& e, std::vector<std::string>& why);

// Writes metrics.json, fig4_paths.svg, fig5_motion.svg, fig_right_of_way.svg and report.md
// into out_dir, each atomically.
void write_paper_report(const PaperExperiment& e, const std::string& out_dir);

}  // namespace mg
