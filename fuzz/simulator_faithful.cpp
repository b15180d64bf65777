#include "fuzz/simulator_faithful.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/fixed_text.h"

namespace mg::fuzz {
namespace {

// Channel times are step times: a message sent at t is delivered at the first step at or after
// t + latency (sim/v2v_channel.h), so no later than one step after it.
constexpr double kTimeTieS = 1e-9;

const MainVehicle* declared(const Scenario& s, int id) {
  const int index = s.index_of(id);
  return index < 0 ? nullptr : &s.vehicles[static_cast<std::size_t>(index)];
}

// A scripted exceed_accel / exceed_brake declares that the vehicle breaks its limits; every other
// vehicle (a reneging one included: it breaks its answer, not its limits) keeps them (spec §7).
bool declares_its_limits(const MainVehicle& v) {
  return v.noncompliance.type != NonComplianceType::kExceedAccel &&
         v.noncompliance.type != NonComplianceType::kExceedBrake;
}

// The first step at which each main-lane vehicle that declares its limits is observed beyond
// them by more than the judge's accel_tolerance_mps2 (the bound declared_limits judges with).
void declared_limits(const Scenario& s, const CheckResult& result, std::vector<SimulatorFinding>& out) {
  const ObservedTrace& trace = result.trace;
  const double tol = result.rule_params.accel_tolerance_mps2;
  for (std::size_t k = 1; k < trace.vehicles.size(); ++k) {
    const MainVehicle* v = declared(s, trace.vehicles[k].id);
    if (v == nullptr || !declares_its_limits(*v)) continue;
    for (const ObservedStep& step : trace.steps) {
      const double a = step.vehicles[k].accel_mps2;
      const double margin = std::min(a + v->limits.brake_max_mps2 + tol, v->limits.accel_max_mps2 + tol - a);
      if (margin >= 0.0) continue;  // a NaN acceleration fails too
      out.push_back({kRuleSimDeclaredLimits, v->id, step.time_s, std::isnan(margin) ? -1.0 : margin,
                     "vehicle " + std::to_string(v->id) + " applied " + fixed_text(a, 3) +
                         " m/s2, outside its declared [-" + fixed_text(v->limits.brake_max_mps2, 2) + ", " +
                         fixed_text(v->limits.accel_max_mps2, 2) + "] m/s2, and the scenario declares no "
                         "non-compliance that allows it"});
      break;
    }
  }
}

// The latest acceptance `id` sent at or before `time_s` (-inf when none).
double last_acceptance_s(const ObservedTrace& trace, int id, double time_s) {
  double at = -std::numeric_limits<double>::infinity();
  for (const ChannelEvent& e : trace.channel)
    if (e.kind == ChannelEventKind::kSent && e.message.type == MessageType::kAccept && e.message.from_id == id &&
        e.time_s <= time_s)
      at = e.time_s;
  return at;
}

// Whether the vehicle directly ahead of trace vehicle k in its lane braked (beyond the judge's
// tolerance) at some step of [from_s, to_s].
bool held_back_by_braking(const ObservedTrace& trace, std::size_t k, double from_s, double to_s, double tol) {
  const double half_lane_m = 0.5 * trace.road.lane_width_m;
  for (const ObservedStep& step : trace.steps) {
    if (step.time_s < from_s || step.time_s > to_s) continue;
    const ObservedState& me = step.vehicles[k];
    const ObservedState* ahead = nullptr;
    for (std::size_t j = 1; j < step.vehicles.size(); ++j) {
      const ObservedState& o = step.vehicles[j];
      if (j == k || std::abs(o.y_m - me.y_m) >= half_lane_m || o.x_m <= me.x_m) continue;
      if (ahead == nullptr || o.x_m < ahead->x_m) ahead = &o;
    }
    if (ahead != nullptr && ahead->accel_mps2 < -tol) return true;
  }
  return false;
}

// A cooperative driver declared compliant keeps the v_o* it accepted (RCPP Def. 2.1 B / 2.2 B):
// it accepts only what its cooperating law reaches behind the vehicle ahead of it as that one
// drives then (sim/behaviour.h), so the checker's responder rules must never blame it, unless
// that vehicle braked after the acceptance: the traffic, not the driver, then held it back.
void accepted_speeds(const Scenario& s, const CheckResult& result, std::vector<SimulatorFinding>& out) {
  const ObservedTrace& trace = result.trace;
  for (const RuleResult& r : result.rules) {
    if (r.holds || !r.liable_id.is_vehicle()) continue;
    if (std::find(kAcceptedSpeedRules.begin(), kAcceptedSpeedRules.end(), r.rule_id) == kAcceptedSpeedRules.end())
      continue;
    const MainVehicle* v = declared(s, r.liable_id.vehicle_id());
    const int k = trace.index_of(r.liable_id.vehicle_id());
    if (v == nullptr || k < 1 || v->noncompliance.type != NonComplianceType::kNone) continue;
    const double failed_s = r.first_violation_time_s.value_or(r.min_margin_time_s);
    const double accepted_s = last_acceptance_s(trace, v->id, failed_s);
    if (held_back_by_braking(trace, static_cast<std::size_t>(k), accepted_s, failed_s,
                             result.rule_params.accel_tolerance_mps2))
      continue;
    out.push_back({r.rule_id, v->id, failed_s, r.min_margin,
                   "vehicle " + std::to_string(v->id) + ", declared compliant, did not keep the speed it accepted " +
                       "(the vehicle ahead of it did not brake): " + r.detail});
  }
}

const V2v* link_of(const Scenario& s, int id) {
  if (id == 0) return &s.ego.v2v;
  const MainVehicle* v = declared(s, id);
  return v == nullptr ? nullptr : &v->v2v;
}

std::string message_text(const V2vMessage& m) {
  return to_string(m.type) + " " + std::to_string(m.from_id) + "->" + std::to_string(m.to_id) + " sent at t = " +
         fixed_text(m.sent_time_s, 3) + " s";
}

bool same_message(const V2vMessage& a, const V2vMessage& b) {
  return a.type == b.type && a.from_id == b.from_id && a.to_id == b.to_id && a.sent_time_s == b.sent_time_s;
}

// A message is delivered or lost: one sent long enough before the trace's end (its latency and a
// step) that is neither has vanished in the channel.
void vanished(const Scenario& s, const CheckResult& result, std::vector<SimulatorFinding>& out) {
  const auto& events = result.trace.channel;
  if (result.trace.steps.empty()) return;
  const double end_s = result.trace.steps.back().time_s;
  for (const ChannelEvent& e : events) {
    if (e.kind != ChannelEventKind::kSent) continue;
    const V2v* from = link_of(s, e.message.from_id);
    const double due_s = e.time_s + (from != nullptr ? from->latency_s : 0.0) + s.params.sim.step_s;
    if (due_s >= end_s) continue;
    const bool answered = std::any_of(events.begin(), events.end(), [&](const ChannelEvent& f) {
      return f.kind != ChannelEventKind::kSent && same_message(f.message, e.message);
    });
    if (!answered)
      out.push_back({kRuleSimV2vLoss, -1, e.time_s, -1.0, message_text(e.message) + " was neither delivered nor lost"});
  }
}

// Each delivery happens at its send time plus the sender's declared latency (at the first step
// then); a message is lost only when a party has no V2V or its sender's link may lose it
// (loss_prob > 0), and never delivered when a party has no V2V.
void channel(const Scenario& s, const CheckResult& result, std::vector<SimulatorFinding>& out) {
  const double step_s = s.params.sim.step_s;
  for (const ChannelEvent& e : result.trace.channel) {
    if (e.kind == ChannelEventKind::kSent) continue;
    const V2vMessage& m = e.message;
    const V2v* from = link_of(s, m.from_id);
    const V2v* to = link_of(s, m.to_id);
    const bool both_capable = from != nullptr && to != nullptr && from->capable && to->capable;
    if (e.kind == ChannelEventKind::kLost) {
      if (both_capable && !(from->loss_prob > 0.0))
        out.push_back({kRuleSimV2vLoss, -1, e.time_s, -1.0,
                       message_text(m) + " was lost, but both parties have V2V and the sender's loss_prob is 0"});
      continue;
    }
    if (!both_capable) {
      out.push_back({kRuleSimV2vLoss, -1, e.time_s, -1.0, message_text(m) + " was delivered to or from a vehicle without V2V"});
      continue;
    }
    const double took_s = e.time_s - m.sent_time_s;
    const double margin = std::min(took_s - (from->latency_s - kTimeTieS), from->latency_s + step_s + kTimeTieS - took_s);
    if (!(margin >= 0.0))
      out.push_back({kRuleSimV2vLatency, -1, e.time_s, std::isnan(margin) ? -1.0 : margin,
                     message_text(m) + " was delivered after " + fixed_text(took_s, 3) +
                         " s; its sender declares a latency of " + fixed_text(from->latency_s, 3) + " s"});
  }
  vanished(s, result, out);
}

}  // namespace

std::vector<SimulatorFinding> simulator_findings(const Scenario& scenario, const CheckResult& result) {
  std::vector<SimulatorFinding> out;
  declared_limits(scenario, result, out);
  accepted_speeds(scenario, result, out);
  channel(scenario, result, out);
  return out;
}

}  // namespace mg::fuzz
