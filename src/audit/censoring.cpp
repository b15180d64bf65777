#include "audit/censoring.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rules/merge_attempts.h"
#include "rules/merge_phases.h"
#include "rules/pair_geometry.h"

namespace mg {
namespace {

constexpr double kTieS = 1e-9;

std::string at(double t_s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", t_s);
  return buf;
}

// "vehicle 375" (or "the ego, vehicle 389") for trace vehicle index k.
std::string who(const MergeTrace& m, std::size_t k) {
  return (k == 0 ? "the ego, vehicle " : "vehicle ") + std::to_string(m.recording_ids[k]);
}

// Whether the left-out vehicle was, at some recorded step of [from, to], in the lane left or
// entered within neighbour range of the ego: a member of the gap the decision was made for.
bool near_gap(const RecordingView& v, const MergeTrace& m, const PartialRecord& p, int from, int to, double range_m) {
  const FrenetTrack* ego = nullptr;
  const FrenetTrack* other = nullptr;
  std::size_t other_index = 0;
  for (std::size_t i = 0; i < v.tracks.size(); ++i) {
    if (v.tracks[i].vehicle_id == m.change.vehicle_id) ego = &v.tracks[i];
    if (v.tracks[i].vehicle_id == p.vehicle_id) other = &v.tracks[i], other_index = i;
  }
  if (ego == nullptr || other == nullptr) return false;
  for (int step = std::max(from, p.first_step); step <= std::min(to, p.last_step); ++step) {
    const TrackState* e = ego->at_step(step);
    const TrackState* o = other->at_step(step);
    if (e == nullptr || o == nullptr) continue;
    const int lane = v.lanes[other_index][static_cast<std::size_t>(step - other->states.front().time_step)];
    if ((lane == m.change.to_lane || lane == m.change.from_lane) && std::abs(o->s_m - e->s_m) <= range_m) return true;
  }
  return false;
}

}  // namespace

std::optional<DecisionWindow> decision_window(const ObservedTrace& t, double change_time_s) {
  if (t.steps.empty()) return std::nullopt;
  const RuleParams& p = t.params.rules;
  const double t0 = t.steps.front().time_s;
  DecisionWindow w;
  // An ego already across the lane line at the first step: the rules see no merge at all, yet
  // one was under way.
  if (!(t.steps.front().vehicles[0].y_m < -0.5 * t.road.lane_width_m)) {
    w.under_way_at_first = true;
    w.start_s = w.to_s = t0;
    w.from_s = t0 - p.merge_decision_window_s;
    return w;
  }
  const MergePhases phases = observe_merge_phases(t, p);
  const MergeAttempts attempts = observe_merge_attempts(t, p, phases);
  const MergeAttempt* chosen = nullptr;
  for (const MergeAttempt& a : attempts.attempts) {
    // The attempt that is this lane change: the one that crossed the line nearest to it.
    if (!chosen || (a.midpoint_time_s && (!chosen->midpoint_time_s ||
                                          std::abs(*a.midpoint_time_s - change_time_s) < std::abs(*chosen->midpoint_time_s - change_time_s)))) {
      chosen = &a;
    }
  }
  if (chosen == nullptr) return std::nullopt;
  w.under_way_at_first = chosen->start_step == 0;
  w.start_s = chosen->start_time_s;
  w.from_s = chosen->start_time_s - p.merge_decision_window_s;
  w.to_s = chosen->entry_time_s.value_or(chosen->start_time_s);
  return w;
}

std::optional<std::string> decision_censoring(const RecordingView& v, const MergeTrace& m, const DecisionWindow& w,
                                              std::vector<std::string>& missing) {
  const double dt = v.recording->time_step_s;
  const double t0 = m.first_step * dt;
  std::optional<std::string> reason;
  if (w.under_way_at_first && m.window_start.recording_limit) {
    reason = "the merge was already under way at the first judged instant (t = " + at(t0) + ", " + m.window_start.why +
             "): its decision was not observed";
    missing.push_back("the ego's decision and the gap it chose, before t = " + at(t0));
  } else if (w.from_s < t0 - kTieS && m.window_start.recording_limit) {
    reason = "the decision window (t = " + at(w.from_s) + " to " + at(w.to_s) + ") begins before " + m.window_start.why +
             ": the decision was not observed in full";
    missing.push_back("t = " + at(std::max(0.0, w.from_s)) + " to " + at(t0) + " of the decision window");
  }
  const int from = static_cast<int>(std::floor(w.from_s / dt + 1e-9)), to = static_cast<int>(std::ceil(w.to_s / dt - 1e-9));
  for (const PartialRecord& p : m.partial) {
    if (p.first_step <= std::max(from, 0) && p.last_step >= to) continue;  // observed over the whole window
    if (!near_gap(v, m, p, from, to, 80.0)) continue;
    missing.push_back("vehicle " + std::to_string(p.vehicle_id) + " near the gap, recorded only from " + at(p.first_step * dt) + " to " +
                      at(p.last_step * dt));
    if (!reason) reason = "the gap's vehicles were not observed over the decision window (t = " + at(w.from_s) + " to " + at(w.to_s) + ")";
  }
  return reason;
}

const RuleResult* deciding_rule(const CheckResult& r) {
  const RuleResult* best = nullptr;
  for (const RuleResult& x : r.rules) {
    if (x.holds || !x.first_violation_time_s) continue;
    if (r.liable_id != kNobody && x.liable_id != r.liable_id) continue;
    if (best == nullptr || *x.first_violation_time_s < *best->first_violation_time_s) best = &x;
  }
  return best;
}

std::optional<std::string> censored_blame(const ObservedTrace& t, const CheckResult& r, const MergeTrace& m) {
  const RuleResult* rule = deciding_rule(r);
  if (rule == nullptr || (rule->rule_id != "rss_longitudinal" && rule->rule_id != "rss_lateral")) return std::nullopt;
  const int liable = t.index_of(rule->liable_id);
  if (liable < 0) return std::nullopt;
  const std::size_t l = static_cast<std::size_t>(liable);
  for (std::size_t x = 0; x < t.vehicles.size(); ++x) {
    if (x == l) continue;
    bool throughout = true;
    for (const ObservedStep& st : t.steps) {
      if (st.time_s > *rule->first_violation_time_s + kTieS) break;
      const PairGeometry g = pair_geometry(t, st, std::min(l, x), std::max(l, x));
      if (!(g.lon_unsafe() && g.lat_unsafe())) {
        throughout = false;
        break;
      }
    }
    if (!throughout) continue;
    return "the danger between " + who(m, l) + " and " + who(m, x) + " for which " + who(m, l) + " is blamed (" + rule->rule_id + " at t = " +
           at(*rule->first_violation_time_s) + ") was already under way at the first judged instant (t = " + at(t.steps.front().time_s) + ", " +
           m.window_start.why + "): when it began, and who made it, was not recorded";
  }
  return std::nullopt;
}

std::vector<std::string> judged_on_record(const CheckResult& r, const MergeTrace& m) {
  std::vector<std::string> out;
  for (const RuleResult& x : r.rules) {
    const std::string& id = x.rule_id;
    if (id != "on_road" && id != "side_lane_end" && id != "smoothness_oscillation" && id != "sideslip" && id != "declared_limits") continue;
    if (x.holds) {
      out.push_back(id + " holds");
      continue;
    }
    const int k = r.trace.index_of(x.liable_id);
    out.push_back(id + " violated" + (k >= 0 ? " by " + who(m, static_cast<std::size_t>(k)) : std::string()) + " at t = " +
                  at(x.first_violation_time_s.value_or(0.0)) + ": " + x.detail);
  }
  return out;
}

}  // namespace mg
