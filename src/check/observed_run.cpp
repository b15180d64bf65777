#include "check/observed_run.h"

#include <optional>
#include <string>

namespace mg {
namespace {

std::optional<ChannelEventKind> channel_kind_of(EventKind k) {
  switch (k) {
    case EventKind::kMessageSent: return ChannelEventKind::kSent;
    case EventKind::kMessageDelivered: return ChannelEventKind::kDelivered;
    case EventKind::kMessageLost: return ChannelEventKind::kLost;
    default: return std::nullopt;
  }
}

std::vector<VehicleDeclaration> declarations_of(const Scenario& s) {
  std::vector<VehicleDeclaration> out;
  out.reserve(s.vehicles.size() + 1);
  out.push_back({0, s.ego.size, s.ego.limits, s.ego.v2v.capable});
  for (const MainVehicle& v : s.vehicles) out.push_back({v.id, v.size, v.limits, v.v2v.capable});
  return out;
}

nlohmann::json annotations_of(const Trace& t, PlannerAccount account) {
  if (account == PlannerAccount::kNameOnly) return {{"planner", t.planner}};
  nlohmann::json decisions = nlohmann::json::array();
  for (const PlanRecord& d : t.decisions) decisions.push_back(plan_record_to_json(d));
  return {{"planner", t.planner}, {"decisions", std::move(decisions)}};
}

}  // namespace

ObservedState observed_state_of(const VehicleState& v) {
  return {v.x_m, v.y_m, v.yaw_rad, v.road_vx_mps(), v.road_vy_mps(), v.accel_mps2};
}

ObservedTrace observed_trace_of(const Scenario& scenario, const Trace& trace, PlannerAccount account) {
  ObservedTrace o;
  o.name = scenario.name;
  o.source = "mergeguard simulate (planner " + trace.planner + ")";
  o.road = scenario.road;
  o.vehicles = declarations_of(scenario);
  o.params.rss = scenario.params.rss;
  o.params.rules = scenario.params.rules;
  o.steps.reserve(trace.steps.size());
  for (const TraceStep& step : trace.steps) {
    ObservedStep& out = o.steps.emplace_back();
    out.time_s = step.time_s;
    out.vehicles.reserve(step.others.size() + 1);
    out.vehicles.push_back(observed_state_of(step.ego));
    for (const VehicleState& v : step.others) out.vehicles.push_back(observed_state_of(v));
  }
  for (const TraceEvent& e : trace.events) {
    const std::optional<ChannelEventKind> kind = channel_kind_of(e.kind);
    if (kind && e.message) o.channel.push_back({e.time_s, *kind, *e.message});
  }
  o.planner_annotations = annotations_of(trace, account);
  return o;
}

}  // namespace mg
