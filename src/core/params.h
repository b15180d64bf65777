// The parameters every module shares, one structure per owner: the RSS model, the planners'
// common ones, the simulator and the rule monitors. Each structure's member initialisers are its
// defaults; its table (core/param_table.h, in params.cpp) gives each parameter's JSON key, unit,
// valid range and description, from which the reader, the writer and docs/scenario_format.md's
// table and the schemas are made. A planner's own tunables are its own (planner/rcpp_params.h for
// RCPP's): core keeps them as PlannerParams::tunables without knowing them.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/param_table.h"

namespace mg {

// RSS model parameters shared by planner, monitors and liability (RCPP eq. 1, 2).
struct RssParams {
  double response_time_s = 0.5;       // T_lag: response time + communication delay
  double fluctuation_margin_m = 0.1;  // mu of eq. 2
  bool operator==(const RssParams&) const = default;
};

// What every planner is told about the merge it is to make (spec §4-§6), the JSON object
// params.planner. The object also carries the tunables a planner owns, under keys of its own
// table: core keeps them as given (a JSON object, only the keys the input set), and the owner
// checks them at the input boundary (planner/planner_params.h) and reads them
// (planner/rcpp_params.h). Core cannot check them itself: it does not depend on any planner.
struct PlannerParams {
  double merge_duration_s = 4.0;  // rho_m: decision to completion of the merge
  double comm_threshold_s = 1.0;  // rho_c: time allowed for the V2V exchange
  double halt_margin_m = 5.0;     // Definition 1.3: stop this far before the side lane end
  nlohmann::json tunables = nlohmann::json::object();
  bool operator==(const PlannerParams&) const = default;
};

// The rule monitors' own parameters: the durations Definitions 1 and 2 are judged with, how a
// merge is recognised in the observed motion, and the tolerances. A planner may use other values
// (PlannerParams) and is still judged by these (docs/scenario_format.md, docs/spec.md).
struct RuleParams {
  double merge_duration_s = 4.0;  // rho_m of Def. 1
  double comm_threshold_s = 1.0;  // rho_c of Def. 2
  // A merge starts when the ego's centre leaves its side-lane centre toward the main lane by more
  // than merge_start_offset_m; back within merge_abort_offset_m (before the lane line) it has been
  // aborted; within merge_complete_offset_m of the main-lane centre, heading within
  // merge_complete_yaw_rad, it is complete (the simulator's merge events use the same values).
  double merge_start_offset_m = 0.1;
  double merge_abort_offset_m = 0.05;
  // ... or, before the line, once it has turned back toward the side lane by more than this from
  // the furthest Y of the attempt (smaller reversals are path-tracking ripple).
  double merge_abort_reversal_m = 0.05;
  double merge_complete_offset_m = 0.2;
  double merge_complete_yaw_rad = 0.02;
  // How long before the observed start of a merge its decision may have been taken: the right of
  // way is read at the latest instant of [start - window, entry] at which it held, the window
  // reaching back further to the onset of an unbroken approach (rules/merge_attempts.h).
  double merge_decision_window_s = 4.0;
  double accel_tolerance_mps2 = 0.05;
  double speed_tolerance_mps = 0.2;
  double yield_speed_tolerance_mps = 0.5;
  double halted_speed_mps = 0.05;
  double road_edge_tolerance_m = 0.05;
  double lat_speed_hysteresis_mps = 0.1;
  int max_lat_speed_sign_changes_per_merge = 2;
  double sideslip_max_rad = 0.05;
  double sideslip_min_speed_mps = 2.0;
  double progress_grace_s = 3.0;
  double progress_gap_margin_m = 5.0;
  double progress_leader_braking_mps2 = 0.5;
  double progress_min_merge_speed_mps = 5.0;
  double progress_lateral_margin_m = 0.75;
  double progress_lat_accel_max_mps2 = 1.5;
  double progress_sideslip_fraction = 0.7;
  bool operator==(const RuleParams&) const = default;
};

// Simulation parameters (spec §7).
struct SimParams {
  double step_s = 0.02;          // fixed integration step
  double planner_cycle_s = 0.1;  // planner period, a multiple of step_s
  double horizon_s = 30.0;       // simulated duration
  bool operator==(const SimParams&) const = default;
};

struct Params {
  RssParams rss;
  PlannerParams planner;
  SimParams sim;
  RuleParams rules;
  bool operator==(const Params&) const = default;
};

// The tables (params.cpp). The planner table holds the keys common to every planner only.
const ParamTable<RssParams>& rss_param_table();
const ParamTable<PlannerParams>& planner_param_table();
const ParamTable<SimParams>& sim_param_table();
const ParamTable<RuleParams>& rule_param_table();

// The sections of a scenario's params object, in the order docs/scenario_format.md lists them:
// rss, planner (the common keys; planner/planner_params.h adds the planners' tunables), sim,
// rules. For the generated documentation (core/param_docs.h).
std::vector<ParamSection> core_param_sections();
// Those a trace's params object holds: rss and rules (core/observed_trace_json.h).
std::vector<ParamSection> trace_param_sections();

// Reads the "params" object (every key optional, defaults above); raises InputError naming
// `source` and the JSON path on unknown keys, wrong types or out-of-range values. The keys of
// params.planner that planner_param_table() does not declare go to PlannerParams::tunables as
// they are.
Params params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path);
nlohmann::json params_to_json(const Params& p);
// The "rules" object alone (every key optional), for traces and `--params`.
RuleParams rule_params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path);
nlohmann::json rule_params_to_json(const RuleParams& p);
RssParams rss_params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path);
nlohmann::json rss_params_to_json(const RssParams& p);

}  // namespace mg
