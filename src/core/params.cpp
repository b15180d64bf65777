#include "core/params.h"

#include "core/json_reader.h"

namespace mg {
namespace {

using R = RuleParams;

constexpr Param<RssParams> kRssRows[] = {
    param("response_time_s", &RssParams::response_time_s, "s", at_least(0.0), at_most(5.0),
          "T_lag: response time plus communication delay (RCPP eq. 1, 2)"),
    param("fluctuation_margin_m", &RssParams::fluctuation_margin_m, "m", at_least(0.0), at_most(5.0),
          "μ of eq. 2: lateral fluctuation margin"),
};
static_assert(well_formed<RssParams>(kRssRows));

constexpr Param<PlannerParams> kPlannerRows[] = {
    param("merge_duration_s", &PlannerParams::merge_duration_s, "s", at_least(0.5), at_most(20.0),
          "ρ_m the planner plans with: decision to completion of the merge"),
    param("comm_threshold_s", &PlannerParams::comm_threshold_s, "s", at_least(0.05), at_most(10.0),
          "ρ_c the planner plans with: time allowed for the V2V exchange"),
    param("halt_margin_m", &PlannerParams::halt_margin_m, "m", at_least(0.0), at_most(100.0),
          "Definition 1.3: stop this far before the side lane's end"),
};
static_assert(well_formed<PlannerParams>(kPlannerRows));

constexpr Param<SimParams> kSimRows[] = {
    param("step_s", &SimParams::step_s, "s", at_least(1e-3), at_most(0.5), "fixed integration step"),
    param("planner_cycle_s", &SimParams::planner_cycle_s, "s", at_least_param("step_s"), at_most(5.0),
          "planner period, a multiple of step_s"),
    param("horizon_s", &SimParams::horizon_s, "s", above(0.0), at_most(3600.0), "simulated duration"),
};
static_assert(well_formed<SimParams>(kSimRows));

// Bounds the work of one simulation (a hostile-input guard, docs/scenario_format.md).
constexpr ParamCheck<SimParams> kSimChecks[] = {
    {"horizon_s", "horizon_s / step_s ≤ 1e6", "horizon_s / step_s must be <= 1e6 steps",
     [](const SimParams& p) { return p.horizon_s / p.step_s <= 1e6; }},
};

constexpr Param<RuleParams> kRuleRows[] = {
    param("merge_duration_s", &R::merge_duration_s, "s", at_least(0.5), at_most(20.0),
          "ρ_m the rules judge Definition 1 with"),
    param("comm_threshold_s", &R::comm_threshold_s, "s", at_least(0.05), at_most(10.0),
          "ρ_c the rules judge Definition 2 with"),
    param("merge_start_offset_m", &R::merge_start_offset_m, "m", at_least(0.01), at_most(0.5),
          "a merge starts when the ego's centre is this far left of the side-lane centre (moving left)"),
    param("merge_abort_offset_m", &R::merge_abort_offset_m, "m", at_least(0.0), below_param("merge_start_offset_m"),
          "back within this of the side-lane centre before the lane line: aborted (below the start: hysteresis)"),
    param("merge_abort_reversal_m", &R::merge_abort_reversal_m, "m", at_least(0.0), at_most(0.3),
          "turned back toward the side lane by more than this from the attempt's furthest Y, before the line: "
          "aborted"),
    param("merge_complete_offset_m", &R::merge_complete_offset_m, "m", above(0.0), at_most(0.5),
          "within this of the main-lane centre (and the yaw below): complete"),
    param("merge_complete_yaw_rad", &R::merge_complete_yaw_rad, "rad", above(0.0), at_most(0.1),
          "heading bound for completion"),
    param("merge_decision_window_s", &R::merge_decision_window_s, "s", at_least(0.0), at_most(8.0),
          "how long before a merge's observed start its decision may lie"),
    param("accel_tolerance_mps2", &R::accel_tolerance_mps2, "m/s²", at_least(0.0), at_most(0.2),
          "accelerations beyond a declared limit by less are within it"),
    param("speed_tolerance_mps", &R::speed_tolerance_mps, "m/s", at_least(0.0), at_most(0.5), "speed comparisons"),
    param("yield_speed_tolerance_mps", &R::yield_speed_tolerance_mps, "m/s", at_least(0.0), at_most(1.0),
          "a Definition 2 responder counts as at v_o* within this; per second since its acceptance, the travel "
          "allowance of `def2_positions`"),
    param("halted_speed_mps", &R::halted_speed_mps, "m/s", at_least(0.0), at_most(0.2),
          "below this a vehicle is at rest"),
    param("road_edge_tolerance_m", &R::road_edge_tolerance_m, "m", at_least(0.0), at_most(0.2),
          "road-edge containment (`on_road`)"),
    param("lat_speed_hysteresis_mps", &R::lat_speed_hysteresis_mps, "m/s", at_least(0.0), at_most(0.3),
          "lateral motion below this has no direction"),
    param("max_lat_speed_sign_changes_per_merge", &R::max_lat_speed_sign_changes_per_merge, "", at_least(0.0),
          at_most(4.0), "`smoothness_oscillation` allowance per merge attempt"),
    param("sideslip_max_rad", &R::sideslip_max_rad, "rad", above(0.0), at_most(0.2), "`sideslip` bound"),
    param("sideslip_min_speed_mps", &R::sideslip_min_speed_mps, "m/s", at_least(0.0), at_most(5.0),
          "`sideslip` judged above this speed"),
    param("progress_grace_s", &R::progress_grace_s, "s", at_least(0.0), at_most(10.0),
          "`progress`: how long a merge offered to the ego in the side lane (a feasible Def. 1 gap, an accepted Def. 2 request) may go unused"),
    param("progress_gap_margin_m", &R::progress_gap_margin_m, "m", at_least(0.0), at_most(20.0),
          "`progress`: slack a gap must have to count as feasible"),
    param("progress_leader_braking_mps2", &R::progress_leader_braking_mps2, "m/s²", at_least(0.0), at_most(15.0),
          "`progress`: a leader braking harder excuses waiting"),
    param("progress_min_merge_speed_mps", &R::progress_min_merge_speed_mps, "m/s", at_least(0.0), at_most(10.0),
          "`progress`: the slowest v_e* that counts as a drivable merge"),
    param("progress_lateral_margin_m", &R::progress_lateral_margin_m, "m", at_least(0.0), at_most(1.5),
          "`progress`: lateral slack of a feasible merge beyond D_lat"),
    param("progress_lat_accel_max_mps2", &R::progress_lat_accel_max_mps2, "m/s²", at_least(0.5), at_most(5.0),
          "`progress`: peak lateral acceleration of a merge the rule offers (a comfortable lane change)"),
    param("progress_sideslip_fraction", &R::progress_sideslip_fraction, "", at_least(0.1), at_most(1.0),
          "`progress`: share of the `sideslip` bound within which a merge the rule offers turns in and out"),
};
static_assert(well_formed<RuleParams>(kRuleRows));

// params.planner: the common keys by the table, every other key kept for the planner that owns it.
PlannerParams read_planner(const ObjectReader& r) {
  PlannerParams p;
  read_param_values(planner_param_table(), r, p);
  for (const auto& item : r.value().items())
    if (!declares(planner_param_table(), item.key())) p.tunables[item.key()] = item.value();
  return p;
}

}  // namespace

const ParamTable<RssParams>& rss_param_table() {
  static constexpr ParamTable<RssParams> table{kRssRows};
  return table;
}

const ParamTable<PlannerParams>& planner_param_table() {
  static constexpr ParamTable<PlannerParams> table{kPlannerRows};
  return table;
}

const ParamTable<SimParams>& sim_param_table() {
  static constexpr ParamTable<SimParams> table{kSimRows, kSimChecks};
  return table;
}

const ParamTable<RuleParams>& rule_param_table() {
  static constexpr ParamTable<RuleParams> table{kRuleRows};
  return table;
}

std::vector<ParamSection> core_param_sections() {
  return {
      {"rss", "RSS model parameters shared by planners, monitors and liability (RCPP eq. 1, 2); every key optional.",
       param_infos(rss_param_table())},
      {"planner", "What every planner is told about the merge (PlannerParams, src/core/params.h); every key optional.",
       param_infos(planner_param_table())},
      {"sim", "Simulation parameters (spec §7); every key optional.", param_infos(sim_param_table())},
      {"rules", "The rule monitors' own parameters (RuleParams, src/core/params.h); every key optional.",
       param_infos(rule_param_table())},
  };
}

std::vector<ParamSection> trace_param_sections() {
  std::vector<ParamSection> sections;
  for (ParamSection& s : core_param_sections())
    if (s.name == "rss" || s.name == "rules") sections.push_back(std::move(s));
  return sections;
}

Params params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path) {
  ObjectReader r(j, source, path);
  r.only_keys({"rss", "planner", "sim", "rules"});
  Params p;
  if (r.has("rules")) p.rules = read_params(rule_param_table(), r.object("rules"));
  if (r.has("rss")) p.rss = read_params(rss_param_table(), r.object("rss"));
  if (r.has("planner")) p.planner = read_planner(r.object("planner"));
  if (r.has("sim")) p.sim = read_params(sim_param_table(), r.object("sim"));
  return p;
}

RuleParams rule_params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path) {
  return read_params(rule_param_table(), ObjectReader(j, source, path));
}

RssParams rss_params_from_json(const nlohmann::json& j, const std::string& source, const std::string& path) {
  return read_params(rss_param_table(), ObjectReader(j, source, path));
}

nlohmann::json rss_params_to_json(const RssParams& p) { return params_to_json(rss_param_table(), p); }

nlohmann::json rule_params_to_json(const RuleParams& p) { return params_to_json(rule_param_table(), p); }

nlohmann::json params_to_json(const Params& p) {
  nlohmann::json planner = params_to_json(planner_param_table(), p.planner);
  for (const auto& item : p.planner.tunables.items()) planner[item.key()] = item.value();
  return {
      {"rss", rss_params_to_json(p.rss)},
      {"rules", rule_params_to_json(p.rules)},
      {"planner", planner},
      {"sim", params_to_json(sim_param_table(), p.sim)},
  };
}

}  // namespace mg
