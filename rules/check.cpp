#include "rules/check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

#include "rules/collision_monitor.h"
#include "rules/declared_limits_monitor.h"
#include "rules/definition1_monitor.h"
#include "rules/definition2_inequalities.h"
#include "rules/definition2_monitor.h"
#include "rules/liability.h"
#include "rules/merge_phases.h"
#include "rules/monitor.h"
#include "rules/progress_monitor.h"
#include "rules/road_monitor.h"
#include "rules/rule_catalog.h"
#include "rules/rss_distance_monitor.h"
#include "rules/sigmoid_bounds_monitor.h"
#include "rules/situation.h"
#include "rules/smoothness_monitor.h"

namespace mg {

std::span<const MonitorFn> rule_monitors() {
  static constexpr MonitorFn kMonitors[] = {
      monitor_rss_longitudinal,
      monitor_rss_lateral,
      monitor_def1_1_gap,
      monitor_def1_1_follower,
      monitor_def1_2_gap,
      monitor_def1_2_leader,
      monitor_def1_3_halt,
      monitor_def2_1a_request,
      monitor_def2_1b_responder,
      monitor_def2_2a_ego_brake,
      monitor_def2_2b_responder,
      monitor_def2_3_fallback,
      monitor_def2_request_sound,
      monitor_def2_positions,
      monitor_def2_request_truthful,
      monitor_sigmoid_pc_bounds,
      monitor_collision,
      monitor_on_road,
      monitor_side_lane_end,
      monitor_smoothness_oscillation,
      monitor_sideslip,
      monitor_progress,
      monitor_declared_limits,
  };
  return kMonitors;
}

std::vector<RuleResult> run_monitors(const MonitorContext& ctx, std::vector<std::vector<double>>* margins) {
  const std::size_t rules = rule_catalog().size();
  std::vector<RuleResult> results(rules);
  std::vector<bool> judged(rules, false);
  if (margins) margins->assign(rules, {});
  for (const MonitorFn run : rule_monitors()) {
    MonitorOutput out = run(ctx);
    const std::size_t i = rule_index(out.result.rule_id);
    if (judged[i]) throw std::logic_error("two monitors judge rule " + out.result.rule_id);
    judged[i] = true;
    results[i] = std::move(out.result);
    if (margins) (*margins)[i] = std::move(out.margin);
  }
  for (std::size_t i = 0; i < rules; ++i)
    if (!judged[i]) throw std::logic_error("no monitor judges rule " + rule_catalog()[i].id);
  return results;
}

namespace {

void set_aside_liveness(std::vector<RuleResult>& results) {
  for (RuleResult& r : results) {
    if (!rule_spec(r.rule_id).liveness) continue;
    RuleResult set_aside;
    set_aside.rule_id = r.rule_id, set_aside.paper_ref = r.paper_ref, set_aside.unit = r.unit;
    r = std::move(set_aside);
    r.min_margin = std::numeric_limits<double>::infinity();
    r.detail = "not judged: a liveness rule, and this judgement applies the safety rules only";
  }
}

}  // namespace

CheckResult check_observed(ObservedTrace&& trace, const std::optional<RuleParams>& rules, RuleSet applied) {
  CheckResult r;
  if (trace.planner_annotations.is_object() && trace.planner_annotations.contains("planner") &&
      trace.planner_annotations["planner"].is_string())
    r.planner = trace.planner_annotations["planner"].get<std::string>();  // shown, never judged
  const RuleParams params = rules.value_or(trace.params.rules);
  // Stages: what happened (once), each rule over it, then liability and the report.
  const Situation s = observe_situation(trace, params);
  r.rule_params = params;
  for (const MergePhaseEvent& e : s.phases.events) r.merge_phase_times_s.push_back(e.time_s);
  r.right_of_way = s.row.timeline;
  for (const MergeAttempt& a : s.attempts.attempts) r.right_of_way_observations.push_back(a.observation);
  r.rules = run_monitors(MonitorContext{trace, s.row, params, s.phases, s.attempts, s.exchanges}, nullptr);
  if (applied == RuleSet::kSafety) set_aside_liveness(r.rules);
  for (const RuleResult& rule : r.rules) r.holds = r.holds && rule.holds;
  assign_liability(r);
  r.trace_digest = trace_digest(trace);
  r.trace = std::move(trace);
  return r;
}

CheckResult check_observed(const ObservedTrace& trace, const std::optional<RuleParams>& rules, RuleSet applied) {
  return check_observed(ObservedTrace(trace), rules, applied);
}

namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

nlohmann::json measures_to_json(const RuleResult& r) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [name, value] : r.measures) out[name] = number_or_null(value);
  return out;
}

nlohmann::json rule_to_json(const RuleResult& r) {
  return {{"rule_id", r.rule_id},
          {"paper_ref", r.paper_ref},
          {"unit", r.unit},
          {"holds", r.holds},
          {"applicable", std::isfinite(r.min_margin)},
          {"min_margin", number_or_null(r.min_margin)},
          {"min_margin_time_s", std::isfinite(r.min_margin) ? nlohmann::json(r.min_margin_time_s) : nlohmann::json()},
          {"first_violation_time_s", r.first_violation_time_s ? nlohmann::json(*r.first_violation_time_s) : nlohmann::json()},
          {"liable", party_name(r.holds ? Party::nobody() : r.liable_id)},
          {"required_value", number_or_null(r.required_value)},
          {"actual_value", number_or_null(r.actual_value)},
          {"detail", r.detail},
          {"measures", measures_to_json(r)}};
}

}  // namespace

nlohmann::json judged_with_json(const CheckResult& r) {
  return {{"rules", rule_params_to_json(r.rule_params)}, {"rss", rss_params_to_json(r.trace.params.rss)}};
}

nlohmann::json check_result_to_json(const CheckResult& r) {
  nlohmann::json rules = nlohmann::json::array();
  nlohmann::json violated = nlohmann::json::array();
  nlohmann::json timeline = nlohmann::json::array();
  for (const RuleResult& rule : r.rules) {
    rules.push_back(rule_to_json(rule));
    if (!rule.holds) violated.push_back(rule.rule_id);
  }
  for (const ChannelEvent& e : r.trace.channel) {
    const V2vMessage& m = e.message;
    timeline.push_back({{"time_s", e.time_s}, {"kind", "message_" + to_string(e.kind)},
                        {"actor", party_name(Party::from_vehicle_id(m.from_id))},
                        {"detail", to_string(m.type) + " to " + party_name(Party::from_vehicle_id(m.to_id))}});
  }
  for (const RuleResult& rule : r.rules) {
    if (rule.holds) continue;
    timeline.push_back({{"time_s", *rule.first_violation_time_s}, {"kind", "violation"},
                        {"actor", party_name(rule.liable_id)}, {"detail", rule.rule_id + ": " + rule.detail}});
  }
  std::stable_sort(timeline.begin(), timeline.end(), [](const nlohmann::json& a, const nlohmann::json& b) {
    return a.at("time_s").get<double>() < b.at("time_s").get<double>();
  });
  nlohmann::json row = nlohmann::json::array();
  for (const auto& [t, holder] : r.right_of_way) row.push_back({{"time_s", t}, {"holder", party_name(holder)}});
  char digest[17];
  std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(r.trace_digest));
  return {{"report_format_version", 1},
          {"planner", r.planner},
          {"verdict", r.holds ? "holds" : "violated"},
          {"liable", party_name(r.liable_id)},
          {"liability_detail", r.liability_detail},
          {"collision", r.collision},
          {"collision_liable", party_name(r.collision ? r.collision_liable_id : Party::nobody())},
          {"rules_violated", violated},
          {"judged_with", judged_with_json(r)},
          {"rules", rules},
          {"right_of_way", row},
          {"right_of_way_observations", r.right_of_way_observations},
          {"timeline", timeline},
          {"trace_digest", digest}};
}

}  // namespace mg
