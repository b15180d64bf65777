#include "rules/merge_attempts.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rules/attempt_basis.h"
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

std::string to_string(Cover c) {
  switch (c) {
    case Cover::kNone: return "nothing";
    case Cover::kDef2: return "its acceptance (Def. 2)";
    case Cover::kDef2Pair: return "Def. 1 for the pair at the request";
    case Cover::kDef1: return "the Def. 1 reading";
    case Cover::kDef1Pair: return "Def. 1 for the pair at the reading";
  }
  return "nothing";
}

namespace {

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

// Where and when the ego's centre crossed the lane line, between the midpoint's step and the one
// before it (linear in Y: a 50 Hz trace at 20 m/s moves 0.4 m a step).
void read_crossing(const ObservedTrace& t, MergeAttempt& a, std::size_t mid) {
  const ObservedState& e = t.steps[mid].vehicles[0];
  a.crossing_x_m = e.x_m;
  a.crossing_time_s = t.steps[mid].time_s;
  a.crossing_speed_mps = std::max(0.0, e.vx_mps);
  if (mid == 0) return;
  const ObservedState& b = t.steps[mid - 1].vehicles[0];
  const double line_y = -0.5 * t.road.lane_width_m;
  if (!(e.y_m > b.y_m) || !(b.y_m < line_y)) return;
  const double f = (line_y - b.y_m) / (e.y_m - b.y_m);
  a.crossing_speed_mps = std::max(0.0, b.vx_mps + f * (e.vx_mps - b.vx_mps));
  a.crossing_x_m = b.x_m + f * (e.x_m - b.x_m);
  a.crossing_time_s = t.steps[mid - 1].time_s + f * (t.steps[mid].time_s - t.steps[mid - 1].time_s);
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

std::string gap_text(const ObservedTrace& t, const GapIndices& g) {
  const auto side = [&](int k) { return k < 1 ? std::string("open") : party_name(Party::from_vehicle_id(t.vehicles[static_cast<std::size_t>(k)].id)); };
  return "(follower " + side(g.follower) + ", leader " + side(g.leader) + ")";
}

void describe_cover(const ObservedTrace& t, const PairCover& c, const char* role, std::ostringstream& os) {
  if (c.vehicle < 1) return;
  os << "; toward " << role << " " << party_name(party_of(t, static_cast<std::size_t>(c.vehicle))) << ": "
     << to_string(c.by);
  if (std::isfinite(c.margin_m))
    os << " (" << (c.by == Cover::kNone ? "Def. 1 for the pair fails by " : "by ") << std::abs(c.margin_m) << " m)";
}

void describe(const ObservedTrace& t, MergeAttempt& a) {
  std::ostringstream os;
  os << "t = " << a.start_time_s << " s: ego starts merging into gap " << gap_text(t, a.entered_gap) << "; ";
  if (a.basis == RowBasis::kDef2) {
    os << party_name(Party::from_vehicle_id(a.exchange->request->to_id)) << "'s acceptance of the request of t = " << a.exchange->request_time_s
       << " s was delivered at t = " << a.exchange->accept_delivered_time_s << " s, within rho_c -> ego holds (Def. 2)";
  } else if (a.def1_read) {
    const Def1Reading& r = a.def1;
    os << "gap " << gap_text(t, a.gap) << " at t = " << r.time_s << " s with v_e* = " << r.ve_star_mps
       << " m/s, rho = " << r.rho_s << " s, ineq. 1.1 " << (r.margin_11_m >= 0.0 ? "holds by " : "is violated by ")
       << std::abs(r.margin_11_m) << " m, ineq. 1.2 " << (r.margin_12_m >= 0.0 ? "holds by " : "is violated by ")
       << std::abs(r.margin_12_m) << " m"
       << (a.basis == RowBasis::kDef1 ? " -> ego holds (Def. 1)"
                                      : " (the best instant of the decision window) -> ego has no right of way");
  } else {
    os << "no decision window -> ego has no right of way";
  }
  describe_cover(t, a.follower, "follower", os);
  describe_cover(t, a.leader, "leader", os);
  if (a.fault == AcceptanceFault::kUntruthful)
    os << "; the acceptance of " << party_name(Party::from_vehicle_id(a.exchange->request->to_id)) << " grants nothing: its request misstated "
       << (a.exchange->order_margin_m < 0.0 ? "the order of the ego and its responder" : "P_c");
  a.observation = os.str();
}

// What the attempt's observed motion says before any right of way is judged: the gap around the
// ego at its midpoint (at its start, when it reached none), its entry into the main lane, and,
// for an attempt that reached its midpoint, where it crossed the line and the gap's vehicles.
void read_geometry(const ObservedTrace& t, const RuleParams& p, const std::vector<GapIndices>& around, MergeAttempt& a) {
  const std::size_t mid_or_start = a.midpoint_time_s ? step_at_or_after(t, *a.midpoint_time_s) : a.start_step;
  const std::size_t mid = std::min(mid_or_start, t.steps.size() - 1);
  a.entered_gap = around[mid];
  a.gap = a.entered_gap;
  const std::size_t end_step = a.end_time_s ? step_at_or_after(t, *a.end_time_s) : t.steps.size();
  a.entry_step = entry_step_of(t, p, a.start_step, end_step + 1);
  if (a.entry_step) a.entry_time_s = t.steps[*a.entry_step].time_s;
  if (a.midpoint_time_s) {
    read_crossing(t, a, mid);
    a.follower.vehicle = a.entered_gap.follower;
    a.leader.vehicle = a.entered_gap.leader;
  }
}

}  // namespace

MergeAttempts observe_merge_attempts(const ObservedTrace& t, const RuleParams& p, const MergePhases& phases,
                                     const std::vector<CoopExchange>& exchanges,
                                     const std::vector<GapIndices>& around) {
  MergeAttempts out;
  out.attempts = spans_of(phases);
  const AttemptInputs in{t, p, exchanges, around};
  double previous_end_s = t.steps.empty() ? 0.0 : t.steps.front().time_s;
  for (MergeAttempt& a : out.attempts) {
    const double window_from_s =
        std::max(previous_end_s, std::min(a.start_time_s - p.merge_decision_window_s, approach_onset_s(t, p, a.start_step)));
    read_geometry(t, p, around, a);
    judge_attempt_basis(in, a, window_from_s, previous_end_s);
    describe(t, a);
    previous_end_s = a.end_time_s.value_or(a.start_time_s);
  }
  return out;
}

}  // namespace mg
