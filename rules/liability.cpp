#include "rules/liability.h"

#include <limits>
#include <optional>
#include <string>

#include "rules/check.h"
#include "rules/merge_attempts.h"

namespace mg {

namespace {

bool holds_at(const RightOfWay::Intervals& v, double time_s) {
  for (const auto& [from, to] : v)
    if (time_s >= from && time_s < to) return true;
  return false;
}

bool held_within(const RightOfWay::Intervals& v, double from_s, double to_s) {
  for (const auto& [from, to] : v)
    if (from <= to_s && to > from_s) return true;
  return false;
}

// The intervals of one attempt toward vehicle k: its cover's, for a vehicle of the gap it
// entered; the attempt's as a whole for any other.
void add_toward(RightOfWay& row, const MergeAttempt& a, double end_s) {
  for (std::size_t k = 1; k < row.toward.size(); ++k) {
    const int v = static_cast<int>(k);
    const PairCover* c = v == a.follower.vehicle ? &a.follower : v == a.leader.vehicle ? &a.leader : nullptr;
    double from_s = a.decision_time_s;
    if (c != nullptr) {
      if (c->by == Cover::kNone) continue;
      from_s = c->from_s;
    } else if (a.basis == RowBasis::kNone) {
      continue;
    }
    if (from_s < end_s) row.toward[k].emplace_back(from_s, end_s);
  }
}

}  // namespace

bool RightOfWay::ego_holds_at(double time_s) const { return holds_at(ego_holds, time_s); }

bool RightOfWay::ego_held_within(double from_s, double to_s) const { return held_within(ego_holds, from_s, to_s); }

bool RightOfWay::ego_holds_toward_at(std::size_t k, double time_s) const {
  return k < toward.size() ? holds_at(toward[k], time_s) : ego_holds_at(time_s);
}

bool RightOfWay::ego_held_toward_within(std::size_t k, double from_s, double to_s) const {
  return k < toward.size() ? held_within(toward[k], from_s, to_s) : ego_held_within(from_s, to_s);
}

RightOfWay compute_right_of_way(const ObservedTrace& t, const MergeAttempts& attempts) {
  RightOfWay row;
  row.toward.resize(t.vehicles.size());
  const Party traffic = t.vehicles.size() <= 1 ? Party::nobody() : Party::main_lane();
  const double end = std::numeric_limits<double>::infinity();
  Party holder = traffic;
  row.timeline.emplace_back(0.0, holder);
  auto change = [&](double time_s, Party h) {
    if (h == holder) return;
    if (holder == Party::ego()) row.ego_holds.back().second = time_s;
    if (h == Party::ego()) row.ego_holds.emplace_back(time_s, end);
    holder = h;
    if (row.timeline.back().first == time_s) {
      row.timeline.back().second = h;  // at the same instant: only the outcome counts
    } else {
      row.timeline.emplace_back(time_s, h);
    }
  };
  for (const MergeAttempt& a : attempts.attempts) {
    add_toward(row, a, a.end_time_s.value_or(end));
    if (a.basis != RowBasis::kNone) change(a.decision_time_s, Party::ego());
    if (!a.end_time_s) break;
    change(*a.end_time_s, a.completed ? Party::nobody() : traffic);
    if (a.completed) break;
  }
  return row;
}

// Obligations of comfort and progress: broken, they are the ego's, but no danger follows from
// them, so they are never a collision's cause (otherwise the ego's path oscillating in the side
// lane would be blamed for two main-lane vehicles colliding 0.08 s later, one of them racing
// beyond its declared limits since t = 1 s: corpus case
// rcpp-coop__no_oscillation__smoothness_oscillation__ego-5; docs/rules.md).
bool can_cause_collision(const RuleResult& rule) {
  return rule.rule_id != "smoothness_oscillation" && rule.rule_id != "progress";
}

void assign_liability(CheckResult& r) {
  const RuleResult* first = nullptr;
  const RuleResult* collision = nullptr;
  for (const auto& rule : r.rules) {
    if (rule.holds) continue;
    if (rule.rule_id == "collision") collision = &rule;
    if (rule.liable_id == Party::nobody()) continue;
    if (!first || *rule.first_violation_time_s < *first->first_violation_time_s) first = &rule;
  }
  r.collision = collision != nullptr;
  if (collision) {
    // The obligation broken last at or before the collision: the danger that led to it.
    const RuleResult* cause = nullptr;
    for (const auto& rule : r.rules) {
      if (rule.holds || rule.liable_id == Party::nobody() || !can_cause_collision(rule) ||
          *rule.first_violation_time_s > *collision->first_violation_time_s + 1e-9)
        continue;
      if (!cause || *rule.first_violation_time_s > *cause->first_violation_time_s) cause = &rule;
    }
    r.collision_liable_id = cause ? cause->liable_id : Party::nobody();
    if (!cause) first = nullptr;
  }
  if (first) {
    r.liable_id = first->liable_id;
    r.liability_detail = party_name(first->liable_id) + " broke " + first->rule_id + " (" +
                         first->paper_ref + ") first, at t = " +
                         std::to_string(*first->first_violation_time_s) + " s: " + first->detail;
  } else if (collision) {
    r.liable_id = Party::nobody();
    r.liability_detail = "collision with nobody liable: the rule set did not explain it (" +
                         collision->detail + ")";
  }
}

}  // namespace mg
