// Every tunable of mergeguard in one structure. Defaults and valid ranges are documented in
// docs/scenario_format.md and enforced by params_from_json (the only place they are checked).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace mg {

// RSS model parameters shared by planner, monitors and liability (RCPP eq. 1, 2).
struct RssParams {
  double response_time_s = 0.5;       // T_lag: response time + communication delay, [0, 5]
  double fluctuation_margin_m = 0.1;  // mu of eq. 2, [0, 5]
  bool operator==(const RssParams&) const = default;
};

// RCPP planner parameters (spec §4-§6).
struct PlannerParams {
  double merge_duration_s = 4.0;       // rho_m: decision to completion of the merge, [0.5, 20]
  double comm_threshold_s = 1.0;       // rho_c: time allowed for the V2V exchange, [0.05, 10]
  double halt_margin_m = 5.0;          // Definition 1.3: stop this far before the side lane end, [0, 100]
  double lat_accel_comfort_mps2 = 1.5; // bound on the sigmoid's peak lateral acceleration, (0, 10]
  double kappa_min_per_m = 0.05;       // smallest sigmoid slope considered, (0, kappa_max]
  double kappa_max_per_m = 1.0;        // largest sigmoid slope considered, [kappa_min, 10]
  int pc_candidates = 15;              // v_e* (hence P_c) samples scored by the field, [1, 200]
  int kappa_candidates = 8;            // kappa samples scored by the potential field, [1, 200]
  // Potential field coefficients (RCPP eq. 3-5).
  double pf_road_beta = 0.5;           // beta, road-mark repulsion, [0, 1e6]
  double pf_obstacle_gamma = 10.0;     // gamma, obstacle repulsion, [0, 1e6]
  double pf_obstacle_u = 0.01;         // U, small positive offset, [0, 1]
  double pf_lane_xi = 0.2;             // xi, lane-centre attraction, [0, 1e6]
  double pf_search_distance_m = 20.0;  // D*, search target distance of the merging mode, (0, 1000]
  // Cost weights for choosing gap and v_e* (documented in docs/planner.md).
  double cost_time_weight = 1.0;         // per second until the merge midpoint, [0, 1e3]
  double cost_speed_change_weight = 0.5; // per m/s of |v_e* - v_e|, [0, 1e3]
  double cost_traffic_speed_weight = 0.2;// per m/s of |v_e* - gap traffic speed|, [0, 1e3]
  bool operator==(const PlannerParams&) const = default;
};

// The rule monitors' own parameters: the durations Definitions 1 and 2 are judged
// with, how a merge is recognised in the observed motion, and the tolerances. A planner may use
// other values (PlannerParams) and is still judged by these (docs/scenario_format.md, docs/spec.md).
struct RuleParams {
  double merge_duration_s = 4.0;        // rho_m of Def. 1, [0.5, 20]
  double comm_threshold_s = 1.0;        // rho_c of Def. 2, [0.05, 10]
  // A merge starts when the ego's centre leaves its side-lane centre toward the main lane by more
  // than merge_start_offset_m; back within merge_abort_offset_m (before the lane line) it has been
  // aborted; within merge_complete_offset_m of the main-lane centre, heading within
  // merge_complete_yaw_rad, it is complete (the simulator's merge events use the same values).
  double merge_start_offset_m = 0.1;    // [0.01, 0.5]
  double merge_abort_offset_m = 0.05;   // [0, merge_start_offset_m)
  // ... or, before the line, once it has turned back toward the side lane by more than this from
  // the furthest Y of the attempt (smaller reversals are path-tracking ripple), [0, 0.3]
  double merge_abort_reversal_m = 0.05;
  double merge_complete_offset_m = 0.2; // (0, 0.5]
  double merge_complete_yaw_rad = 0.02; // (0, 0.1]
  // How long before the observed start of a merge its decision may have been taken: the right of
  // way is read at the latest instant of [start - window, entry] at which it held, the window
  // reaching back further to the onset of an unbroken approach (rules/merge_attempts.h).
  double merge_decision_window_s = 4.0; // [0, 8]
  double accel_tolerance_mps2 = 0.05;   // measured accelerations beyond a declared limit by less are within it, [0, 0.2]
  double speed_tolerance_mps = 0.2;     // speed comparisons, [0, 0.5]
  double yield_speed_tolerance_mps = 0.5;  // a responder "at v_o*" within this, [0, 1]
  double halted_speed_mps = 0.05;       // below this a vehicle is at rest, [0, 0.2]
  double road_edge_tolerance_m = 0.05;  // road-edge containment, [0, 0.2]
  double lat_speed_hysteresis_mps = 0.1;// lateral motion below this has no direction, [0, 0.3]
  int max_lat_speed_sign_changes_per_merge = 2;  // smoothness, [0, 4]
  double sideslip_max_rad = 0.05;       // (0, 0.2]
  double sideslip_min_speed_mps = 2.0;  // sideslip judged above this speed, [0, 5]
  // progress (rules/progress_monitor.h): how long a merge offered to the ego in the side lane (a
  // feasible Def. 1 gap, an accepted Def. 2 request) may go unused, [0, 10]
  double progress_grace_s = 3.0;
  double progress_gap_margin_m = 5.0;   // progress: slack a gap must have to count as feasible, [0, 20]
  double progress_leader_braking_mps2 = 0.5;  // progress: leader braking that excuses waiting, [0, 15]
  double progress_min_merge_speed_mps = 5.0;  // progress: the slowest v_e* that counts as a drivable merge, [0, 10]
  double progress_lateral_margin_m = 0.75;  // progress: lateral slack of a feasible merge beyond D_lat, [0, 1.5]
  bool operator==(const RuleParams&) const = default;
};

// Simulation parameters (spec §7).
struct SimParams {
  double step_s = 0.02;           // fixed integration step, [1e-3, 0.5]
  double planner_cycle_s = 0.1;   // planner period, a multiple of step_s, [step_s, 5]
  double horizon_s = 30.0;        // simulated duration, (0, 3600]
  bool operator==(const SimParams&) const = default;
};

struct Params {
  RssParams rss;
  PlannerParams planner;
  SimParams sim;
  RuleParams rules;
  bool operator==(const Params&) const = default;
};

// Reads the "params" object (every key optional, defaults above); raises InputError naming
// `source` and the JSON path on unknown keys, wrong types or out-of-range values.
Params params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path);
nlohmann::json params_to_json(const Params& p);
// The "rules" object alone (every key optional), for traces and `--params`.
RuleParams rule_params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path);
nlohmann::json rule_params_to_json(const RuleParams& p);
RssParams rss_params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path);
nlohmann::json rss_params_to_json(const RssParams& p);

}  // namespace mg
