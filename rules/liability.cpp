#include "rules/liability.h"

#include <limits>
#include <optional>
#include <string>

#include "rules/check.h"
#include "rules/merge_phases.h"

namespace mg {

bool RightOfWay::ego_holds_at(double time_s) const {
  for (const auto& [from, to] : ego_holds) {
    if (time_s >= from && time_s < to) return true;
  }
  return false;
}

bool RightOfWay::ego_held_within(double from_s, double to_s) const {
  for (const auto& [from, to] : ego_holds) {
    if (from <= to_s && to > from_s) return true;
  }
  return false;
}

double acceptance_time(const Trace& t, int partner_id, double time_s) {
  double when = -1.0;
  for (const auto& e : t.events) {
    if (e.time_s > time_s + 1e-9) break;
    if (e.kind == EventKind::kMessageDelivered && e.message && e.message->type == MessageType::kAccept &&
        e.message->from_id == partner_id && e.message->to_id == kEgoId) {
      when = e.time_s;
    }
  }
  return when;
}

namespace {

// Whether a decision gives the ego the right of way, keeps the previous state, or revokes it.
enum class RowEffect { kGrant, kKeep, kRevoke, kConflictOver };

RowEffect effect_of(const Trace& t, const Decision& d) {
  switch (d.mode) {
    case DecisionMode::kDef1Merge:
      return d.gap ? RowEffect::kGrant : RowEffect::kRevoke;
    case DecisionMode::kDef2Merge:
      return acceptance_time(t, d.coop_partner_id, d.time_s) >= 0.0 ? RowEffect::kGrant : RowEffect::kRevoke;
    case DecisionMode::kProperResponse:
      return RowEffect::kKeep;
    case DecisionMode::kMerged:
      return RowEffect::kConflictOver;
    case DecisionMode::kKeepLane:
    case DecisionMode::kDef2Request:
    case DecisionMode::kDef1Halt:
    case DecisionMode::kPotentialField:
      return RowEffect::kRevoke;
  }
  return RowEffect::kRevoke;
}

}  // namespace

RightOfWay compute_right_of_way(const Scenario& s, const Trace& t) {
  return compute_right_of_way(s, t, observe_merge_phases(s, t));
}

RightOfWay compute_right_of_way(const Scenario& s, const Trace& t, const MergePhases& phases) {
  RightOfWay row;
  const int traffic = s.vehicles.empty() ? kNobody : kMainLane;
  const double end = std::numeric_limits<double>::infinity();
  const std::optional<MergePhaseEvent> complete = phases.first(MergePhaseKind::kComplete);
  const double merge_complete = complete ? complete->time_s : end;
  int holder = traffic;
  row.timeline.emplace_back(0.0, holder);
  auto change = [&](double time_s, int h) {
    if (h == holder) return;
    if (holder == kEgoId) row.ego_holds.back().second = time_s;
    if (h == kEgoId) row.ego_holds.emplace_back(time_s, end);
    holder = h;
    if (row.timeline.back().first == time_s) {
      row.timeline.back().second = h;  // decided at the same instant: only the outcome counts
    } else {
      row.timeline.emplace_back(time_s, h);
    }
  };
  for (const auto& d : t.decisions) {
    if (d.time_s >= merge_complete) break;
    switch (effect_of(t, d)) {
      case RowEffect::kGrant: change(d.time_s, kEgoId); break;
      case RowEffect::kKeep: break;
      case RowEffect::kRevoke: change(d.time_s, traffic); break;
      case RowEffect::kConflictOver: change(d.time_s, kNobody); break;
    }
  }
  if (merge_complete < end) change(merge_complete, kNobody);
  return row;
}

void assign_liability(CheckResult& r) {
  const RuleResult* first = nullptr;
  const RuleResult* collision = nullptr;
  for (const auto& rule : r.rules) {
    if (rule.holds) continue;
    if (rule.rule_id == "collision") collision = &rule;
    if (rule.liable_id == kNobody) continue;
    if (!first || *rule.first_violation_time_s < *first->first_violation_time_s) first = &rule;
  }
  r.collision = collision != nullptr;
  if (collision) {
    // The obligation broken last at or before the collision: the danger that led to it.
    const RuleResult* cause = nullptr;
    for (const auto& rule : r.rules) {
      if (rule.holds || rule.liable_id == kNobody ||
          *rule.first_violation_time_s > *collision->first_violation_time_s + 1e-9)
        continue;
      if (!cause || *rule.first_violation_time_s > *cause->first_violation_time_s) cause = &rule;
    }
    r.collision_liable_id = cause ? cause->liable_id : kNobody;
    if (!cause) first = nullptr;
  }
  if (first) {
    r.liable_id = first->liable_id;
    r.liability_detail = party_name(first->liable_id) + " broke " + first->rule_id + " (" +
                         first->paper_ref + ") first, at t = " +
                         std::to_string(*first->first_violation_time_s) + " s: " + first->detail;
  } else if (collision) {
    r.liable_id = kNobody;
    r.liability_detail = "collision with nobody liable: the rule set did not explain it (" +
                         collision->detail + ")";
  }
}

}  // namespace mg
