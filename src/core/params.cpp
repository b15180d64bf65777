#include "core/params.h"

#include "core/json_reader.h"

namespace mg {
namespace {

RuleParams read_rules(const ObjectReader& r) {
  r.only_keys({"merge_duration_s", "comm_threshold_s", "merge_start_offset_m", "merge_abort_offset_m", "merge_abort_reversal_m",
               "merge_complete_offset_m", "merge_complete_yaw_rad", "merge_decision_window_s",
               "accel_tolerance_mps2", "speed_tolerance_mps", "yield_speed_tolerance_mps", "halted_speed_mps",
               "road_edge_tolerance_m", "lat_speed_hysteresis_mps", "max_lat_speed_sign_changes_per_merge",
               "sideslip_max_rad", "sideslip_min_speed_mps", "progress_grace_s", "progress_gap_margin_m",
               "progress_leader_braking_mps2", "progress_min_merge_speed_mps", "progress_lateral_margin_m"});
  RuleParams p;
  p.merge_duration_s = r.number_or("merge_duration_s", p.merge_duration_s, 0.5, 20.0);
  p.comm_threshold_s = r.number_or("comm_threshold_s", p.comm_threshold_s, 0.05, 10.0);
  p.merge_start_offset_m = r.number_or("merge_start_offset_m", p.merge_start_offset_m, 0.01, 0.5);
  p.merge_abort_offset_m = r.number_or("merge_abort_offset_m", p.merge_abort_offset_m, 0.0, p.merge_start_offset_m);
  if (p.merge_abort_offset_m >= p.merge_start_offset_m)
    r.fail("merge_abort_offset_m", "must be below merge_start_offset_m (the hysteresis)");
  p.merge_abort_reversal_m = r.number_or("merge_abort_reversal_m", p.merge_abort_reversal_m, 0.0, 0.3);
  p.merge_complete_offset_m = r.positive_or("merge_complete_offset_m", p.merge_complete_offset_m, 0.5);
  p.merge_complete_yaw_rad = r.positive_or("merge_complete_yaw_rad", p.merge_complete_yaw_rad, 0.1);
  p.merge_decision_window_s = r.number_or("merge_decision_window_s", p.merge_decision_window_s, 0.0, 8.0);
  p.accel_tolerance_mps2 = r.number_or("accel_tolerance_mps2", p.accel_tolerance_mps2, 0.0, 0.2);
  p.speed_tolerance_mps = r.number_or("speed_tolerance_mps", p.speed_tolerance_mps, 0.0, 0.5);
  p.yield_speed_tolerance_mps = r.number_or("yield_speed_tolerance_mps", p.yield_speed_tolerance_mps, 0.0, 1.0);
  p.halted_speed_mps = r.number_or("halted_speed_mps", p.halted_speed_mps, 0.0, 0.2);
  p.road_edge_tolerance_m = r.number_or("road_edge_tolerance_m", p.road_edge_tolerance_m, 0.0, 0.2);
  p.lat_speed_hysteresis_mps = r.number_or("lat_speed_hysteresis_mps", p.lat_speed_hysteresis_mps, 0.0, 0.3);
  p.max_lat_speed_sign_changes_per_merge = static_cast<int>(
      r.integer_or("max_lat_speed_sign_changes_per_merge", p.max_lat_speed_sign_changes_per_merge, 0, 4));
  p.sideslip_max_rad = r.positive_or("sideslip_max_rad", p.sideslip_max_rad, 0.2);
  p.sideslip_min_speed_mps = r.number_or("sideslip_min_speed_mps", p.sideslip_min_speed_mps, 0.0, 5.0);
  p.progress_grace_s = r.number_or("progress_grace_s", p.progress_grace_s, 0.0, 10.0);
  p.progress_gap_margin_m = r.number_or("progress_gap_margin_m", p.progress_gap_margin_m, 0.0, 20.0);
  p.progress_leader_braking_mps2 =
      r.number_or("progress_leader_braking_mps2", p.progress_leader_braking_mps2, 0.0, 15.0);
  p.progress_min_merge_speed_mps =
      r.number_or("progress_min_merge_speed_mps", p.progress_min_merge_speed_mps, 0.0, 10.0);
  p.progress_lateral_margin_m = r.number_or("progress_lateral_margin_m", p.progress_lateral_margin_m, 0.0, 1.5);
  return p;
}

RssParams read_rss(const ObjectReader& r) {
  r.only_keys({"response_time_s", "fluctuation_margin_m"});
  RssParams p;
  p.response_time_s = r.number_or("response_time_s", p.response_time_s, 0.0, 5.0);
  p.fluctuation_margin_m = r.number_or("fluctuation_margin_m", p.fluctuation_margin_m, 0.0, 5.0);
  return p;
}

PlannerParams read_planner(const ObjectReader& r) {
  r.only_keys({"merge_duration_s", "comm_threshold_s", "halt_margin_m", "lat_accel_comfort_mps2",
               "kappa_min_per_m", "kappa_max_per_m", "pc_candidates", "kappa_candidates",
               "pf_road_beta", "pf_obstacle_gamma", "pf_obstacle_u", "pf_lane_xi",
               "pf_search_distance_m", "cost_time_weight", "cost_speed_change_weight",
               "cost_traffic_speed_weight"});
  PlannerParams p;
  p.merge_duration_s = r.number_or("merge_duration_s", p.merge_duration_s, 0.5, 20.0);
  p.comm_threshold_s = r.number_or("comm_threshold_s", p.comm_threshold_s, 0.05, 10.0);
  p.halt_margin_m = r.number_or("halt_margin_m", p.halt_margin_m, 0.0, 100.0);
  p.lat_accel_comfort_mps2 = r.positive_or("lat_accel_comfort_mps2", p.lat_accel_comfort_mps2, 10.0);
  p.kappa_min_per_m = r.positive_or("kappa_min_per_m", p.kappa_min_per_m, 10.0);
  p.kappa_max_per_m = r.number_or("kappa_max_per_m", p.kappa_max_per_m, p.kappa_min_per_m, 10.0);
  p.pc_candidates = static_cast<int>(r.integer_or("pc_candidates", p.pc_candidates, 1, 200));
  p.kappa_candidates = static_cast<int>(r.integer_or("kappa_candidates", p.kappa_candidates, 1, 200));
  p.pf_road_beta = r.number_or("pf_road_beta", p.pf_road_beta, 0.0, 1e6);
  p.pf_obstacle_gamma = r.number_or("pf_obstacle_gamma", p.pf_obstacle_gamma, 0.0, 1e6);
  p.pf_obstacle_u = r.number_or("pf_obstacle_u", p.pf_obstacle_u, 0.0, 1.0);
  p.pf_lane_xi = r.number_or("pf_lane_xi", p.pf_lane_xi, 0.0, 1e6);
  p.pf_search_distance_m = r.positive_or("pf_search_distance_m", p.pf_search_distance_m, 1000.0);
  p.cost_time_weight = r.number_or("cost_time_weight", p.cost_time_weight, 0.0, 1e3);
  p.cost_speed_change_weight = r.number_or("cost_speed_change_weight", p.cost_speed_change_weight, 0.0, 1e3);
  p.cost_traffic_speed_weight = r.number_or("cost_traffic_speed_weight", p.cost_traffic_speed_weight, 0.0, 1e3);
  return p;
}

SimParams read_sim(const ObjectReader& r) {
  r.only_keys({"step_s", "planner_cycle_s", "horizon_s"});
  SimParams p;
  p.step_s = r.number_or("step_s", p.step_s, 1e-3, 0.5);
  p.planner_cycle_s = r.number_or("planner_cycle_s", p.planner_cycle_s, p.step_s, 5.0);
  p.horizon_s = r.positive_or("horizon_s", p.horizon_s, 3600.0);
  // Bound the work of one simulation (hostile input guard, documented in docs/scenario_format.md).
  if (p.horizon_s / p.step_s > 1e6) r.fail("horizon_s", "horizon_s / step_s must be <= 1e6 steps");
  return p;
}

}  // namespace

Params params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path) {
  ObjectReader r(j, source, path);
  r.only_keys({"rss", "planner", "sim", "rules"});
  Params p;
  if (r.has("rules")) p.rules = read_rules(r.object("rules"));
  if (r.has("rss")) p.rss = read_rss(r.object("rss"));
  if (r.has("planner")) p.planner = read_planner(r.object("planner"));
  if (r.has("sim")) p.sim = read_sim(r.object("sim"));
  return p;
}

RuleParams rule_params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path) {
  return read_rules(ObjectReader(j, source, path));
}

RssParams rss_params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path) {
  return read_rss(ObjectReader(j, source, path));
}

nlohmann::json rss_params_to_json(const RssParams& p) {
  return {{"response_time_s", p.response_time_s}, {"fluctuation_margin_m", p.fluctuation_margin_m}};
}

nlohmann::json rule_params_to_json(const RuleParams& p) {
  return {{"merge_duration_s", p.merge_duration_s},
          {"comm_threshold_s", p.comm_threshold_s},
          {"merge_start_offset_m", p.merge_start_offset_m},
          {"merge_abort_offset_m", p.merge_abort_offset_m},
          {"merge_abort_reversal_m", p.merge_abort_reversal_m},
          {"merge_complete_offset_m", p.merge_complete_offset_m},
          {"merge_complete_yaw_rad", p.merge_complete_yaw_rad},
          {"merge_decision_window_s", p.merge_decision_window_s},
          {"accel_tolerance_mps2", p.accel_tolerance_mps2},
          {"speed_tolerance_mps", p.speed_tolerance_mps},
          {"yield_speed_tolerance_mps", p.yield_speed_tolerance_mps},
          {"halted_speed_mps", p.halted_speed_mps},
          {"road_edge_tolerance_m", p.road_edge_tolerance_m},
          {"lat_speed_hysteresis_mps", p.lat_speed_hysteresis_mps},
          {"max_lat_speed_sign_changes_per_merge", p.max_lat_speed_sign_changes_per_merge},
          {"sideslip_max_rad", p.sideslip_max_rad},
          {"sideslip_min_speed_mps", p.sideslip_min_speed_mps},
          {"progress_grace_s", p.progress_grace_s},
          {"progress_gap_margin_m", p.progress_gap_margin_m},
          {"progress_leader_braking_mps2", p.progress_leader_braking_mps2},
          {"progress_min_merge_speed_mps", p.progress_min_merge_speed_mps},
          {"progress_lateral_margin_m", p.progress_lateral_margin_m}};
}

nlohmann::json params_to_json(const Params& p) {
  const auto& pl = p.planner;
  return {
      {"rss", rss_params_to_json(p.rss)},
      {"rules", rule_params_to_json(p.rules)},
      {"planner",
       {{"merge_duration_s", pl.merge_duration_s},
        {"comm_threshold_s", pl.comm_threshold_s},
        {"halt_margin_m", pl.halt_margin_m},
        {"lat_accel_comfort_mps2", pl.lat_accel_comfort_mps2},
        {"kappa_min_per_m", pl.kappa_min_per_m},
        {"kappa_max_per_m", pl.kappa_max_per_m},
        {"pc_candidates", pl.pc_candidates},
        {"kappa_candidates", pl.kappa_candidates},
        {"pf_road_beta", pl.pf_road_beta},
        {"pf_obstacle_gamma", pl.pf_obstacle_gamma},
        {"pf_obstacle_u", pl.pf_obstacle_u},
        {"pf_lane_xi", pl.pf_lane_xi},
        {"pf_search_distance_m", pl.pf_search_distance_m},
        {"cost_time_weight", pl.cost_time_weight},
        {"cost_speed_change_weight", pl.cost_speed_change_weight},
        {"cost_traffic_speed_weight", pl.cost_traffic_speed_weight}}},
      {"sim", {{"step_s", p.sim.step_s}, {"planner_cycle_s", p.sim.planner_cycle_s}, {"horizon_s", p.sim.horizon_s}}},
  };
}

}  // namespace mg
