#include "audit/censoring.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/demand.h"
#include "rules/merge_attempts.h"
#include "rules/monitor.h"
#include "rules/pair_geometry.h"
#include "rules/situation.h"

namespace mg {
namespace {

std::string at(double t_s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", t_s);
  return buf;
}

// "vehicle 375" (or "the ego, vehicle 389") for trace vehicle index k.
std::string who(const MergeTrace& m, std::size_t k) {
  return "vehicle " + std::to_string(m.recording_ids[k]) + (k == 0 ? " (the ego)" : "");
}

std::size_t track_of(const RecordingView& v, int vehicle_id) {
  for (std::size_t i = 0; i < v.tracks.size(); ++i) {
    if (v.tracks[i].vehicle_id == vehicle_id) return i;
  }
  return v.tracks.size();
}

int lane_at_step(const RecordingView& v, std::size_t i, int step) {
  const FrenetTrack& t = v.tracks[i];
  if (t.at_step(step) == nullptr) return kRampLane - 1;  // not recorded then
  return v.lanes[i][static_cast<std::size_t>(step - t.states.front().time_step)];
}

// Whether the left-out vehicle was, at some recorded step of [from, to], the ego's nearest
// neighbour ahead or behind in the lane it entered (no participant between them), within 80 m.
bool next_to_ego(const RecordingView& v, const MergeTrace& m, const PartialRecord& p, int from, int to) {
  const std::size_t ego = track_of(v, m.change.vehicle_id), other = track_of(v, p.vehicle_id);
  if (ego == v.tracks.size() || other == v.tracks.size()) return false;
  for (int step = std::max(from, p.first_step); step <= std::min(to, p.last_step); ++step) {
    const TrackState* e = v.tracks[ego].at_step(step);
    const TrackState* o = v.tracks[other].at_step(step);
    if (e == nullptr || o == nullptr || lane_at_step(v, other, step) != m.change.to_lane || std::abs(o->s_m - e->s_m) > 80.0) continue;
    bool between = false;
    for (std::size_t k = 1; k < m.recording_ids.size() && !between; ++k) {
      const std::size_t i = track_of(v, m.recording_ids[k]);
      const TrackState* x = v.tracks[i].at_step(step);
      between = x != nullptr && lane_at_step(v, i, step) == m.change.to_lane && (x->s_m - e->s_m) * (o->s_m - x->s_m) > 0.0;
    }
    if (!between) return true;
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
  const Situation s = observe_situation(t, p);
  const MergeAttempt* chosen = nullptr;
  for (const MergeAttempt& a : s.attempts.attempts) {
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
  w.right_of_way = chosen->basis != RowBasis::kNone;
  return w;
}

std::optional<std::string> decision_censoring(const RecordingView& v, const MergeTrace& m, const DecisionWindow& w,
                                              const CheckResult& r, std::vector<std::string>& missing) {
  const double dt = v.recording->time_step_s;
  const double t0 = m.first_step * dt;
  std::optional<std::string> reason;
  if (!r.holds && !w.right_of_way && m.window_start.recording_limit) {
    if (w.under_way_at_first) {
      reason = "the merge was already under way at the first judged instant (t = " + at(t0) + ", " + m.window_start.why +
               ") and the rules found no right of way in what was recorded: its decision was not observed";
      missing.push_back("the ego's decision and the gap it chose, before t = " + at(t0));
    } else if (w.from_s < t0 - kTieS) {
      reason = "the decision window (t = " + at(w.from_s) + " to " + at(w.to_s) + ") begins before " + m.window_start.why +
               ", and the rules found no right of way in what was recorded: the decision was not observed in full";
      missing.push_back("t = " + at(w.from_s) + " to " + at(t0) + " of the decision window");
    }
  }
  if (!r.holds) return reason;
  const int from = static_cast<int>(std::floor(w.from_s / dt + 1e-9)), to = static_cast<int>(std::ceil(w.to_s / dt - 1e-9));
  // Every vehicle of the recording but the ego, in or out of the trace: one whose record begins
  // or ends inside the decision window was not seen over all of it.
  for (const FrenetTrack& t : v.tracks) {
    const PartialRecord p{t.vehicle_id, t.states.front().time_step, t.states.back().time_step};
    if (p.vehicle_id == m.change.vehicle_id || (p.first_step <= std::max(from, 0) && p.last_step >= to)) continue;
    if (!next_to_ego(v, m, p, from, to)) continue;
    missing.push_back("vehicle " + std::to_string(p.vehicle_id) + ", next to the ego in the lane entered, recorded only from " + at(p.first_step * dt) +
                      " to " + at(p.last_step * dt));
    if (!reason) {
      reason = "a vehicle next to the ego in the lane it entered was not observed over the decision window (t = " + at(w.from_s) + " to " +
               at(w.to_s) + "): whether the gap was enough is not known";
    }
  }
  return reason;
}

const RuleResult* deciding_rule(const CheckResult& r) {
  const RuleResult* best = nullptr;
  for (const RuleResult& x : r.rules) {
    if (x.holds || !x.first_violation_time_s) continue;
    if (!r.liable_id.is_nobody() && x.liable_id != r.liable_id) continue;
    if (best == nullptr || *x.first_violation_time_s < *best->first_violation_time_s) best = &x;
  }
  return best;
}

std::optional<CensoredBlame> censored_blame(const ObservedTrace& whole, const CheckResult& r, const MergeTrace& m) {
  const RuleResult* rule = deciding_rule(r);
  if (!m.window_start.recording_limit || rule == nullptr || (rule->rule_id != "rss_longitudinal" && rule->rule_id != "rss_lateral")) return std::nullopt;
  const int liable = index_of_party(whole, rule->liable_id);
  if (liable < 0) return std::nullopt;
  const std::size_t l = static_cast<std::size_t>(liable);
  const auto dangerous = [&](std::size_t x, const ObservedStep& st) {
    const PairGeometry g = pair_geometry(whole, st, std::min(l, x), std::max(l, x));
    return g.lon_unsafe() && g.lat_unsafe();
  };
  const std::vector<ObservedStep>& steps = whole.steps;
  for (std::size_t x = 0; x < whole.vehicles.size(); ++x) {
    if (x == l) continue;
    std::size_t k = 0;
    while (k < steps.size() && dangerous(x, steps[k])) ++k;
    if (k == 0 || (k < steps.size() && steps[k].time_s <= *rule->first_violation_time_s + kTieS)) continue;
    CensoredBlame b;
    b.pair = who(m, l) + " and " + who(m, x);
    b.reason = "the danger between " + b.pair + " for which " + who(m, l) + " is blamed (" + rule->rule_id + " at t = " +
               at(*rule->first_violation_time_s) + ") was already under way at the first judged instant (t = " + at(steps.front().time_s) + ", " +
               m.window_start.why + ")" + (k < steps.size() ? " until t = " + at(steps[k].time_s) : std::string(" and lasted to the window's end")) +
               ": when it began, and who made it, was not recorded";
    if (k < steps.size()) b.end_step = k;
    return b;
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
    const int k = index_of_party(r.trace, x.liable_id);
    out.push_back(id + " violated" + (k >= 0 ? " by " + who(m, static_cast<std::size_t>(k)) : std::string()) + " at t = " +
                  at(x.first_violation_time_s.value_or(0.0)) + ": " + x.detail);
  }
  return out;
}

}  // namespace mg
