#include "rules/merge_attempts.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rules/check.h"
#include "rules/monitor.h"

namespace mg {

std::string to_string(RowBasis b) {
  switch (b) {
    case RowBasis::kNone: return "none";
    case RowBasis::kDef1: return "Definition 1";
    case RowBasis::kDef2: return "Definition 2";
  }
  return "none";
}

namespace {

std::size_t step_at_or_after(const ObservedTrace& t, double time_s) {
  const auto it = std::lower_bound(t.steps.begin(), t.steps.end(), time_s - kTieS,
                                   [](const ObservedStep& s, double v) { return s.time_s < v; });
  return static_cast<std::size_t>(it - t.steps.begin());
}

// The attempts' spans from the merge phases.
std::vector<MergeAttempt> spans_of(const MergePhases& phases) {
  std::vector<MergeAttempt> out;
  for (const MergePhaseEvent& e : phases.events) {
    if (e.kind == MergePhaseKind::kStart) {
      out.push_back({});
      out.back().start_step = e.step;
      out.back().start_time_s = e.time_s;
      continue;
    }
    if (out.empty()) continue;
    MergeAttempt& a = out.back();
    if (e.kind == MergePhaseKind::kMidpoint) a.midpoint_time_s = e.time_s;
    if (e.kind == MergePhaseKind::kAbort || e.kind == MergePhaseKind::kComplete) a.end_time_s = e.time_s;
    if (e.kind == MergePhaseKind::kComplete) a.completed = true;
  }
  return out;
}

// The first step of [from, to) at which the ego's leftmost corner is past the lane line by more
// than the tolerance the rules give painted lines (road_edge_tolerance_m).
std::optional<std::size_t> entry_step_of(const ObservedTrace& t, const RuleParams& p, std::size_t from,
                                         std::size_t to) {
  const double line_y = -0.5 * t.road.lane_width_m;
  const VehicleSize& size = t.vehicles[0].size;
  for (std::size_t i = from; i < std::min(to, t.steps.size()); ++i) {
    const ObservedState& e = t.steps[i].vehicles[0];
    const double left_y = e.y_m + 0.5 * size.width_m * std::abs(std::cos(e.yaw_rad)) +
                          0.5 * size.length_m * std::abs(std::sin(e.yaw_rad));
    if (left_y > line_y + p.road_edge_tolerance_m) return i;  // on the marking is not in the lane
  }
  return std::nullopt;
}

// When the ego's motion toward the main lane that led into the start at `start_step` began: the
// first step of the unbroken run of steps before it with lateral speed above the hysteresis. An
// ego placed off its lane centre on the far side moves toward the main lane well before its
// offset says "start", and its decision cannot be later than that motion.
double approach_onset_s(const ObservedTrace& t, const RuleParams& p, std::size_t start_step) {
  std::size_t i = start_step;
  while (i > 0 && t.steps[i - 1].vehicles[0].vy_mps > p.lat_speed_hysteresis_mps) --i;
  return t.steps[i].time_s;
}

// The decision window is read every kScanStride steps (0.1 s at 50 Hz): a Definition 1 reading
// costs two bisections, and a gap's feasibility does not come and go within a tenth of a second.
constexpr std::size_t kScanStride = 5;

// Definition 1 at step i for a gap, with rho_m or the observed duration.
Def1Reading read_def1(const ObservedTrace& t, const RuleParams& p, const MergeAttempt& a, const GapIndices& gap,
                      std::size_t i) {
  const double time_s = t.steps[i].time_s;
  std::vector<double> rhos = {p.merge_duration_s};
  // The observed duration when longer than rho_m (never shorter: rho_m is the rule's, and a
  // planner that merges faster is still judged by it): to the midpoint; for an attempt still
  // under way when the trace ends, the shortest duration whose midpoint falls after that end.
  const std::optional<double> mid_s =
      a.midpoint_time_s ? a.midpoint_time_s : a.end_time_s ? std::nullopt : std::optional(t.steps.back().time_s);
  if (mid_s && 2.0 * (*mid_s - time_s) > p.merge_duration_s) rhos.push_back(2.0 * (*mid_s - time_s));
  Def1Reading best;
  bool have = false;
  for (const double rho : rhos) {
    Def1Reading r{gap, i, time_s, rho, def1_interval(t, i, gap, rho)};
    // v_e*: nearest the ego's speed where it crossed the line (or would have, rho/2 on).
    const std::size_t at = a.midpoint_time_s ? step_at_or_after(t, *a.midpoint_time_s)
                                             : std::min(step_at_or_after(t, time_s + 0.5 * rho), t.steps.size() - 1);
    const double v_mid = t.steps[std::min(at, t.steps.size() - 1)].vehicles[0].vx_mps;
    r.observed_mps = v_mid;
    r.ve_star_mps = r.interval.feasible() ? std::clamp(v_mid, r.interval.ve_lo_mps, r.interval.ve_hi_mps)
                                          : def1_best_speed_mps(t, i, gap, rho);
    r.margin_11_m = def1_1_margin_m(t, i, gap.follower, r.ve_star_mps, rho);
    r.margin_12_m = def1_2_margin_m(t, i, gap.leader, r.ve_star_mps, rho);
    if (!have || (r.interval.feasible() && !best.interval.feasible()) ||
        (r.interval.feasible() == best.interval.feasible() && r.min_margin_m() > best.min_margin_m())) {
      best = r;
      have = true;
    }
    if (best.interval.feasible()) break;
  }
  return best;
}

// A Def. 2 exchange with a vehicle of the gap that grants the attempt: accepted, the acceptance
// delivered within rho_c of the request (closed window) and within [from_s, entry]. With
// `timely` false, the same for an acceptance delivered after rho_c.
std::optional<CoopExchange> accepted_exchange(const ObservedTrace& t, const RuleParams& p, const MergeAttempt& a,
                                              double from_s, bool timely) {
  std::optional<CoopExchange> found;
  for (const CoopExchange& x : coop_exchanges(t)) {
    const double d = x.accept_delivered_time_s;
    if (d < 0.0 || d < from_s - kTieS || d > a.entry_time_s.value_or(a.start_time_s) + kTieS) continue;
    const int k = t.index_of(x.request->to_id);
    const GapIndices then = gap_around_ego(t, step_at_or_after(t, d));
    const auto in = [k](const GapIndices& g) { return k >= 1 && (k == g.follower || k == g.leader); };
    if (!in(a.entered_gap) && !in(then)) continue;
    if ((d <= x.request_time_s + p.comm_threshold_s + kTieS) == timely) found = x;
  }
  return found;
}

}  // namespace

// Definition 2 grants the right of way toward the partner; the gap's other vehicle stays
// Definition 1's (spec §8, review point 15). At the request: for 2.1 (ego ahead of o) the vehicle
// ahead of o must satisfy ineq. (1.2) over rho_c + rho_m with the ego at its speed; for 2.2 the
// vehicle behind o must satisfy ineq. (1.1) over 2 rho_c + rho_m with the ego at its speed after
// braking at b_min for rho_c.
bool other_gap_vehicle_clear(const ObservedTrace& t, const RuleParams& p, const CoopExchange& x) {
  const std::size_t i = std::min(step_at_or_after(t, x.request_time_s), t.steps.size() - 1);
  const int k = t.index_of(x.request->to_id);
  const bool ahead = x.request->coop_case == CoopCase::kEgoAhead;
  const double v_e = std::max(0.0, t.steps[i].vehicles[0].vx_mps);
  const double rho_c = p.comm_threshold_s, rho_m = p.merge_duration_s;
  for (const GapIndices& g : lane_gaps(t, i)) {
    if (ahead && g.follower == k) return def1_2_margin_m(t, i, g.leader, v_e, rho_c + rho_m) >= 0.0;
    if (!ahead && g.leader == k) {
      const double v_after = std::max(0.0, v_e - t.vehicles[0].limits.brake_min_mps2 * rho_c);
      return def1_1_margin_m(t, i, g.follower, v_after, 2.0 * rho_c + rho_m) >= 0.0;
    }
  }
  return true;
}

namespace {

std::string gap_text(const ObservedTrace& t, const GapIndices& g) {
  const auto side = [&](int k) { return k < 1 ? std::string("open") : party_name(t.vehicles[static_cast<std::size_t>(k)].id); };
  return "(follower " + side(g.follower) + ", leader " + side(g.leader) + ")";
}

void describe(const ObservedTrace& t, MergeAttempt& a) {
  std::ostringstream os;
  os << "t = " << a.start_time_s << " s: ego starts merging into gap " << gap_text(t, a.gap) << "; ";
  if (a.basis == RowBasis::kDef2) {
    os << party_name(a.exchange->request->to_id) << "'s acceptance of the request of t = " << a.exchange->request_time_s
       << " s was delivered at t = " << a.exchange->accept_delivered_time_s << " s, within rho_c -> ego holds (Def. 2)";
  } else if (a.def1_read) {
    const Def1Reading& r = a.def1;
    os << "at t = " << r.time_s << " s with v_e* = " << r.ve_star_mps << " m/s, rho = " << r.rho_s << " s, ineq. 1.1 "
       << (r.margin_11_m >= 0.0 ? "holds by " : "is violated by ") << std::abs(r.margin_11_m) << " m, ineq. 1.2 "
       << (r.margin_12_m >= 0.0 ? "holds by " : "is violated by ") << std::abs(r.margin_12_m) << " m"
       << (a.basis == RowBasis::kDef1 ? " -> ego holds (Def. 1)" : " (the best instant of the decision window) -> ego has no right of way");
  } else {
    os << "no decision window -> ego has no right of way";
  }
  a.observation = os.str();
}

// `around` and, after it, the lane gaps just behind and just ahead of it at `step`.
std::vector<GapIndices> with_neighbours(const ObservedTrace& t, std::size_t step, const GapIndices& around) {
  const std::vector<GapIndices> lane = lane_gaps(t, step);
  std::vector<GapIndices> out = {around};
  const auto it = std::find(lane.begin(), lane.end(), around);
  if (it == lane.end()) return out;
  if (it != lane.begin()) out.push_back(*(it - 1));
  if (it + 1 != lane.end()) out.push_back(*(it + 1));
  return out;
}

// Whether a vehicle of `gap` broke its declared limits (the declared_limits rule's criterion) at
// a step of [from, to].
bool gap_vehicle_broke_limits(const ObservedTrace& t, const RuleParams& p, const GapIndices& gap, std::size_t from,
                              std::size_t to) {
  for (const int k : {gap.follower, gap.leader}) {
    if (k < 0) continue;
    const Limits& lim = limits_of(t, static_cast<std::size_t>(k));
    for (std::size_t i = from; i <= to && i < t.steps.size(); ++i) {
      const double a = state_of(t.steps[i], static_cast<std::size_t>(k)).accel_mps2;
      if (a > lim.accel_max_mps2 + p.accel_tolerance_mps2 || -a > lim.brake_max_mps2 + p.accel_tolerance_mps2)
        return true;
    }
  }
  return false;
}

// The gaps read at step i. Before the ego's body enters the main lane: the one around it and its
// neighbours (where it is going is not known yet). After: the one around it, and a neighbour only
// if a vehicle of that neighbour broke its declared limits between i and the entry: a vehicle
// the ego was overtaking for the gap ahead of it, which then raced past the ego beyond its
// a_accel^max, changed the ego's gap by its breach, and the gap the ego decided on still counts
// (a campaign finding, docs/rules.md).
std::vector<GapIndices> gaps_at(const ObservedTrace& t, const RuleParams& p, const MergeAttempt& a, std::size_t i) {
  const GapIndices around = gap_around_ego(t, i);
  if (!a.entry_step) return with_neighbours(t, i, around);
  std::vector<GapIndices> out = {around};
  for (const GapIndices& g : with_neighbours(t, i, around))
    if (!(g == around) && gap_vehicle_broke_limits(t, p, g, i, *a.entry_step)) out.push_back(g);
  return out;
}

// From a feasible reading, back while the same gap stays feasible, as far as the end of the
// previous attempt (not only to the window's start): the ego holds the right of way from the
// start of that run (a planner that decided when the gap opened is credited from then, and its
// lateral approach before the visible start is covered; a slow merge, 12.6 s, decided 4.4 s
// before its visible start was otherwise judged by Def. 1.3 for the time between).
// Strides back (kScanStride steps at a time, the last stride step by step).
void extend_back(const ObservedTrace& t, const RuleParams& p, MergeAttempt& a, std::size_t first) {
  std::size_t stride = kScanStride;
  while (a.def1.step > first) {
    const std::size_t i = a.def1.step - std::min(stride, a.def1.step - first);
    const Def1Reading r = read_def1(t, p, a, a.gap, i);
    if (r.interval.feasible()) {
      a.def1 = r;
    } else if (stride > 1) {
      stride = 1;
    } else {
      return;
    }
  }
}

void judge(const ObservedTrace& t, const RuleParams& p, MergeAttempt& a, double window_from_s, double credit_from_s) {
  const std::size_t mid_or_start = a.midpoint_time_s ? step_at_or_after(t, *a.midpoint_time_s) : a.start_step;
  a.entered_gap = gap_around_ego(t, std::min(mid_or_start, t.steps.size() - 1));
  a.gap = a.entered_gap;
  const std::size_t end_step = a.end_time_s ? step_at_or_after(t, *a.end_time_s) : t.steps.size();
  a.entry_step = entry_step_of(t, p, a.start_step, end_step + 1);
  if (a.entry_step) a.entry_time_s = t.steps[*a.entry_step].time_s;
  if (const auto x = accepted_exchange(t, p, a, window_from_s, true); x && other_gap_vehicle_clear(t, p, *x)) {
    a.basis = RowBasis::kDef2;
    a.exchange = x;
    a.decision_time_s = x->accept_delivered_time_s;
    return;
  }
  const std::size_t first = step_at_or_after(t, window_from_s);
  // Latest first, every kScanStride steps; the step of the entry and the window's first step are
  // always read (a gap feasible only at the first instant the ego saw it is still a gap).
  const std::size_t last = std::max(a.entry_step.value_or(a.start_step), a.start_step);
  for (std::size_t i = last + kScanStride; first <= last && i > first;) {
    i = i >= first + kScanStride ? i - kScanStride : first;
    // The gap the ego entered, then the one around it at i (a follower may have raced past it
    // since, changing the gap it entered). Never a gap the ego was neither in nor entered, except
    // for an attempt whose body has not entered the main lane yet (gaps_at): the gap it will enter
    // is not known, and it may be the one behind the vehicle just behind the ego, which it lets
    // pass, or ahead of the vehicle just ahead, which it overtakes (a planner that decided either
    // was otherwise never credited when its visible start came while that vehicle was alongside);
    // or for a gap a vehicle changed by breaking its declared limits.
    // Each inequality must hold under the bounded-rate model too, so "behind a vehicle alongside
    // at v_e* = 0 at once" is not granted (docs/spec.md §8).
    std::vector<GapIndices> gaps = {a.entered_gap};
    const GapIndices around = gap_around_ego(t, i);
    for (const GapIndices& g : gaps_at(t, p, a, i))
      if (std::find(gaps.begin(), gaps.end(), g) == gaps.end()) gaps.push_back(g);
    for (const GapIndices& gap : gaps) {
      const Def1Reading r = read_def1(t, p, a, gap, i);
      // A neighbouring gap is a hypothesis about where the ego is going: it counts only when
      // feasible at a v_e* the ego's observed speed fits (a stop "behind the vehicle alongside"
      // over a duration stretched to the trace's end fits any gap; an ego still at 20 m/s was
      // not doing that).
      const bool neighbour = !(gap == a.entered_gap) && !(gap == around);
      if (neighbour && (!r.interval.feasible() || std::abs(r.ve_star_mps - r.observed_mps) > p.speed_tolerance_mps))
        continue;
      if (!a.def1_read || r.interval.feasible() || r.min_margin_m() > a.def1.min_margin_m()) {
        a.def1 = r;
        a.def1_read = true;
        a.gap = gap;
      }
      if (r.interval.feasible()) {
        a.basis = RowBasis::kDef1;
        extend_back(t, p, a, step_at_or_after(t, credit_from_s));
        a.decision_time_s = a.def1.time_s;
        return;
      }
    }
  }
  a.exchange = accepted_exchange(t, p, a, window_from_s, false);
}

}  // namespace

MergeAttempts observe_merge_attempts(const ObservedTrace& t, const RuleParams& p, const MergePhases& phases) {
  MergeAttempts out;
  out.attempts = spans_of(phases);
  double previous_end_s = t.steps.empty() ? 0.0 : t.steps.front().time_s;
  for (MergeAttempt& a : out.attempts) {
    judge(t, p, a,
          std::max(previous_end_s,
                   std::min(a.start_time_s - p.merge_decision_window_s, approach_onset_s(t, p, a.start_step))),
          previous_end_s);
    describe(t, a);
    previous_end_s = a.end_time_s.value_or(a.start_time_s);
  }
  return out;
}

}  // namespace mg
