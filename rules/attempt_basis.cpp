#include "rules/attempt_basis.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "core/demand.h"
#include "rules/acceptance_cover.h"
#include "rules/def1_reading.h"
#include "rules/definition2_inequalities.h"
#include "rules/monitor.h"

namespace mg {
namespace {

// The decision window is read every kScanStride steps (0.1 s at 50 Hz) first: a Definition 1
// reading costs two bisections, and most gaps stay feasible for longer (try_def1 reads the steps
// between when no stride finds one).
constexpr std::size_t kScanStride = 5;

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
// (spec §8, "Definition 1 basis").
std::vector<GapIndices> gaps_at(const AttemptInputs& in, const MergeAttempt& a, std::size_t i) {
  const GapIndices around = in.around[i];
  if (!a.entry_step) return with_neighbours(in.t, i, around);
  std::vector<GapIndices> out = {around};
  for (const GapIndices& g : with_neighbours(in.t, i, around))
    if (!(g == around) && gap_vehicle_broke_limits(in.t, in.p, g, i, *a.entry_step)) out.push_back(g);
  return out;
}

class AttemptJudge {
 public:
  AttemptJudge(const AttemptInputs& in, MergeAttempt& a, double window_from_s, double credit_from_s)
      : in_(in), a_(a), window_from_s_(window_from_s), credit_from_s_(credit_from_s) {}

  void run();

 private:
  bool known_gap() const { return a_.midpoint_time_s.has_value(); }
  ReadingSpan span() const { return {a_.midpoint_time_s, a_.end_time_s.has_value()}; }
  PairCover* side_for(const CoopExchange& x, bool responder_broke);
  bool try_def2();
  bool try_def2_unknown_gap();
  bool bounds_a_gap_seen(const CoopExchange& x) const;
  bool covers_rest(const Def1Reading& r) const;
  void cover_by_reading(const Def1Reading& r);
  bool try_def1();
  // Step i of the decision window whose first step is `first`: whether a good Definition 1 reading
  // was found there (and kept).
  bool read_window_step(std::size_t i, std::size_t first, bool keep_worse = true);
  void keep_if_best(const Def1Reading& r, bool covers);
  void extend_back(std::size_t first);
  void earliest_run(std::size_t first);
  void granted();
  void no_basis();
  void settle_decision_time();

  const AttemptInputs& in_;
  MergeAttempt& a_;
  double window_from_s_;
  double credit_from_s_;
  std::vector<PcCheck> checks_;             // of the acceptances the attempt was made on
  std::optional<std::size_t> untruthful_;   // an acceptance that would have covered, from a lying request ...
  const PairCover* untruthful_side_ = nullptr;  // ... the vehicle it would have covered (null: gap not known)
  bool best_good_ = false;                  // of the reading kept in a_.def1
  double best_score_ = 0.0;
};

// The cover an acceptance of `x` speaks for: its sender bounding the gap entered on the side its
// case names (ego ahead: the follower; ego behind: the leader), or none. On the other side too
// when the sender got there by breaking what it accepted (beyond def2_positions' bound before
// the midpoint: a 2.1 responder that did not yield and passed the ego): its breach changed the
// ego's gap, and the acceptance still counts, as a gap changed by a vehicle breaking its
// declared limits does for Definition 1.
PairCover* AttemptJudge::side_for(const CoopExchange& x, bool responder_broke) {
  const int k = in_.t.index_of(x.request->to_id);
  if (k < 1) return nullptr;
  const bool ahead = x.request->coop_case == CoopCase::kEgoAhead;
  PairCover* named = ahead ? &a_.follower : &a_.leader;
  PairCover* other = ahead ? &a_.leader : &a_.follower;
  if (k == named->vehicle) return named;
  if (k == other->vehicle && responder_broke) return other;
  return nullptr;
}

// Definition 2 for an attempt that reached its midpoint: each vehicle of the gap entered by its
// own timely acceptance of a truthful request; the other, if none, by Definition 1 for the pair
// at the request. Covers found stay for try_def1 when the other vehicle is not covered.
bool AttemptJudge::try_def2() {
  std::optional<std::size_t> first;
  for (std::size_t i = 0; i < in_.exchanges.size(); ++i) {
    const CoopExchange& x = in_.exchanges[i];
    // An acceptance of a request that lacks a number accepted nothing the rules can hold anyone
    // to: it is no acceptance (def2_request_sound fails the request).
    if (!x.complete() || !x.accepted_in_time(in_.p.comm_threshold_s) || !delivered_in_window(x, a_, window_from_s_, in_.p))
      continue;
    const int k = in_.t.index_of(x.request->to_id);
    const bool broke =
        k >= 1 && responder_broke_acceptance(in_.t, in_.p, x, static_cast<std::size_t>(k), *a_.midpoint_time_s);
    PairCover* c = side_for(x, broke);
    if (c == nullptr) continue;
    // A responder that broke what it accepted left the ego to answer its breach: where the ego
    // then crossed says nothing of the P_c it asked on.
    const std::optional<PcCheck> pc = broke ? std::nullopt : std::optional(pc_check_of(in_.t, x, i, a_));
    if (pc) checks_.push_back(*pc);
    if (x.order_margin_m < 0.0 || (pc && pc->margin_m < 0.0)) {
      if (!untruthful_) untruthful_side_ = c;
      untruthful_ = untruthful_.value_or(i);
      continue;
    }
    if (c->by == Cover::kDef2) continue;  // an earlier acceptance covers it already
    *c = PairCover{c->vehicle, Cover::kDef2, x.accept_delivered_time_s, std::numeric_limits<double>::infinity(), i};
    if (!first) first = i;
  }
  if (!first) return false;
  for (PairCover* c : {&a_.follower, &a_.leader}) {
    if (c->vehicle < 1 || c->by == Cover::kDef2) continue;
    const std::size_t i = a_.follower.by == Cover::kDef2 ? *a_.follower.exchange : *a_.leader.exchange;
    c->margin_m = other_vehicle_margin_m(in_.t, in_.p, in_.exchanges[i], c->vehicle, c == &a_.follower);
    if (c->margin_m >= 0.0) *c = PairCover{c->vehicle, Cover::kDef2Pair, in_.exchanges[i].accept_delivered_time_s, c->margin_m, i};
  }
  const auto covered = [](const PairCover& c) { return c.vehicle < 1 || c.by != Cover::kNone; };
  if (!covered(a_.follower) || !covered(a_.leader)) return false;
  a_.basis = RowBasis::kDef2;
  a_.exchange = in_.exchanges[*first];
  return true;
}

// Whether the sender of x's acceptance bounds a gap the ego was seen in during an attempt whose
// gap entered is not known: the one around it at its start, at the acceptance's delivery, or at
// its entry, once its body reached into the main lane. A 2.1 merge behind a vehicle that passes
// the ego after the delivery, ahead of the vehicle that accepted, enters the gap that vehicle
// bounds; read only at the start and the delivery, with the trace ending before the midpoint,
// its acceptance covered nothing (a campaign finding).
bool AttemptJudge::bounds_a_gap_seen(const CoopExchange& x) const {
  const int k = in_.t.index_of(x.request->to_id);
  const auto in = [k](const GapIndices& g) { return k >= 1 && (k == g.follower || k == g.leader); };
  const std::size_t last = in_.t.steps.size() - 1;
  if (in(a_.entered_gap) || in(in_.around[std::min(step_at_or_after(in_.t, x.accept_delivered_time_s), last)])) return true;
  return a_.entry_step && in(in_.around[*a_.entry_step]);
}

// Definition 2 for an attempt whose gap entered is not known (aborted, or cut by the trace's end,
// before its midpoint): an acceptance from a vehicle of a gap the ego was seen in
// (bounds_a_gap_seen), the other vehicle of the gap the request asked for clear by Definition 1.
bool AttemptJudge::try_def2_unknown_gap() {
  for (std::size_t i = 0; i < in_.exchanges.size(); ++i) {
    const CoopExchange& x = in_.exchanges[i];
    if (!x.complete() || !x.accepted_in_time(in_.p.comm_threshold_s) || !delivered_in_window(x, a_, window_from_s_, in_.p))
      continue;
    if (!bounds_a_gap_seen(x)) continue;
    if (x.order_margin_m < 0.0) {
      untruthful_ = untruthful_.value_or(i);
      continue;
    }
    const bool other_is_follower = x.request->coop_case == CoopCase::kEgoBehind;
    if (other_vehicle_margin_m(in_.t, in_.p, x, requested_gap_other(in_.t, x), other_is_follower) < 0.0) continue;
    a_.basis = RowBasis::kDef2;
    a_.exchange = x;
    a_.decision_time_s = x.accept_delivered_time_s;
    return true;
  }
  return false;
}

// Whether a reading covers every vehicle of the gap entered that no acceptance covers: a vehicle
// of the gap it was read for, or by Definition 1 for the pair at it.
bool AttemptJudge::covers_rest(const Def1Reading& r) const {
  if (!known_gap()) return true;
  for (const PairCover* c : {&a_.follower, &a_.leader}) {
    if (c->vehicle < 1 || c->by == Cover::kDef2) continue;
    if (c->vehicle == r.gap.follower || c->vehicle == r.gap.leader) continue;
    if (pair_margin_m(in_.t, r, c->vehicle, c == &a_.follower) < 0.0) return false;
  }
  return true;
}

// The covers of a reading that is the attempt's basis (or, with no basis, its best reading's
// margins toward the vehicles left uncovered).
void AttemptJudge::cover_by_reading(const Def1Reading& r) {
  if (!known_gap()) return;
  const bool feasible = r.interval.feasible();
  for (PairCover* c : {&a_.follower, &a_.leader}) {
    if (c->vehicle < 1 || c->by == Cover::kDef2) continue;
    const bool member = c->vehicle == r.gap.follower || c->vehicle == r.gap.leader;
    c->margin_m = member ? (c->vehicle == r.gap.follower ? r.margin_11_m : r.margin_12_m)
                         : pair_margin_m(in_.t, r, c->vehicle, c == &a_.follower);
    c->exchange.reset();
    // A vehicle of a feasible reading's gap is covered by the reading (its margin at v_e* is the
    // bisection's, >= 0 to within its tolerance); another one by its pair's margin.
    c->by = !feasible ? Cover::kNone : member ? Cover::kDef1 : c->margin_m < 0.0 ? Cover::kNone : Cover::kDef1Pair;
    c->from_s = r.time_s;
  }
}

// From a good reading (feasible, covering the rest of the gap entered), back while the same gap
// stays good, as far as the end of the previous attempt (not only to the window's start): the ego
// holds the right of way from the start of that run (a planner that decided when the gap opened
// is credited from then, and its lateral approach before the visible start is covered; a slow
// merge, 12.6 s, decided 4.4 s before its visible start was otherwise judged by Def. 1.3 for the
// time between). Strides back (kScanStride steps at a time, the last stride step by step).
void AttemptJudge::extend_back(std::size_t first) {
  std::size_t stride = kScanStride;
  while (a_.def1.step > first) {
    const std::size_t i = a_.def1.step - std::min(stride, a_.def1.step - first);
    const Def1Reading r = read_def1(in_.t, in_.p, span(), a_.gap, i);
    if (r.interval.feasible() && covers_rest(r)) {
      a_.def1 = r;
    } else if (stride > 1) {
      stride = 1;
    } else {
      return;
    }
  }
}

// An earlier run of good readings of the same gap within the window, before a stretch in which
// its readings were not good, moves T_dec back to that run's start: Definition 1 decides at
// T_dec, and a vehicle that then uses what it is allowed (a follower accelerating within its
// a_accel^max) makes later readings of the gap fail while the decision stands. Judged from the
// latest good run alone, an ego that decided when it first saw the gap was without the right of
// way in between and failed Def. 1.3 near a short side lane's end (a campaign finding). Strides
// back every kScanStride steps to the window's first step, which is always read.
void AttemptJudge::earliest_run(std::size_t first) {
  const std::size_t credit_first = step_at_or_after(in_.t, credit_from_s_);
  for (std::size_t i = a_.def1.step; i > first;) {
    i = i >= first + kScanStride ? i - kScanStride : first;
    const Def1Reading r = read_def1(in_.t, in_.p, span(), a_.def1.gap, i);
    if (!r.interval.feasible() || !covers_rest(r)) continue;
    a_.def1 = r;
    extend_back(credit_first);
    i = a_.def1.step;
  }
}

// The reading kept when none is good: feasible before not, then the largest smaller margin
// (toward the vehicles of the gap entered the reading would have to cover, too).
void AttemptJudge::keep_if_best(const Def1Reading& r, bool covers) {
  double score = r.min_margin_m();
  if (known_gap() && !covers)
    for (const PairCover* c : {&a_.follower, &a_.leader})
      if (c->vehicle >= 1 && c->by != Cover::kDef2 && c->vehicle != r.gap.follower && c->vehicle != r.gap.leader)
        score = std::min(score, pair_margin_m(in_.t, r, c->vehicle, c == &a_.follower));
  const bool good = r.interval.feasible() && covers;
  if (a_.def1_read && (good != best_good_ ? !good : score <= best_score_)) return;
  a_.def1 = r;
  a_.def1_read = true;
  a_.gap = r.gap;
  best_good_ = good;
  best_score_ = score;
}

bool AttemptJudge::try_def1() {
  const ObservedTrace& t = in_.t;
  const std::size_t first = step_at_or_after(t, window_from_s_);
  const std::size_t last = std::max(a_.entry_step.value_or(a_.start_step), a_.start_step);
  if (first > last) return false;
  // Latest first, every kScanStride steps; the step of the entry and the window's first step are
  // always read (a gap feasible only at the first instant the ego saw it is still a gap). When no
  // stride finds a good reading, the steps between are read too: a gap can be feasible at one
  // step alone (a follower at rest that starts to move the next step), and a planner may decide
  // at exactly that step (a campaign finding: the strides missed it by 0.04 s).
  const auto strided = [&](std::size_t i) { return i == first || (last - i) % kScanStride == 0; };
  for (std::size_t i = last + kScanStride; i > first;) {
    i = i >= first + kScanStride ? i - kScanStride : first;
    if (read_window_step(i, first)) return true;
  }
  // Those steps only grant what they find; the best reading that is not good stays the strides'.
  for (std::size_t i = last + 1; i > first;)
    if (!strided(--i) && read_window_step(i, first, false)) return true;
  return false;
}

bool AttemptJudge::read_window_step(std::size_t i, std::size_t first, bool keep_worse) {
  const ObservedTrace& t = in_.t;
  // The gap the ego entered, then the one around it at i (a follower may have raced past it
  // since, changing the gap it entered). Never a gap the ego was neither in nor entered, except
  // for an attempt whose body has not entered the main lane yet (gaps_at): the gap it will enter
  // is not known, and it may be the one behind the vehicle just behind the ego, which it lets
  // pass, or ahead of the vehicle just ahead, which it overtakes (a planner that decided either
  // was otherwise never credited when its visible start came while that vehicle was alongside);
  // or for a gap a vehicle changed by breaking its declared limits.
  // Each inequality must hold under the bounded-rate model too, so "behind a vehicle alongside
  // at v_e* = 0 at once" is not granted (docs/spec.md §8).
  std::vector<GapIndices> gaps = {a_.entered_gap};
  const GapIndices around = in_.around[i];
  for (const GapIndices& g : gaps_at(in_, a_, i))
    if (std::find(gaps.begin(), gaps.end(), g) == gaps.end()) gaps.push_back(g);
  for (const GapIndices& gap : gaps) {
    const Def1Reading r = read_def1(t, in_.p, span(), gap, i);
    // A neighbouring gap is a hypothesis about where the ego is going: it counts only when
    // feasible at a v_e* the ego's observed speed fits (a stop "behind the vehicle alongside"
    // over a duration stretched to the trace's end fits any gap; an ego still at 20 m/s was
    // not doing that).
    const bool neighbour = !(gap == a_.entered_gap) && !(gap == around);
    if (neighbour && (!r.interval.feasible() || std::abs(r.ve_star_mps - r.observed_mps) > in_.p.speed_tolerance_mps))
      continue;
    const bool covers = covers_rest(r);
    const bool good = r.interval.feasible() && covers;
    if (keep_worse || good) keep_if_best(r, covers);
    if (good) {
      a_.basis = RowBasis::kDef1;
      extend_back(step_at_or_after(t, credit_from_s_));
      earliest_run(first);
      cover_by_reading(a_.def1);
      return true;
    }
  }
  return false;
}

// No basis: the best reading's margins toward the vehicles left uncovered, and the acceptance the
// attempt was made on, if any (late: def2_3_fallback's; from a lying request:
// def2_request_truthful's).
void AttemptJudge::no_basis() {
  a_.basis = RowBasis::kNone;
  if (a_.def1_read) cover_by_reading(a_.def1);
  // A lie about a vehicle a truthful acceptance of its own covers is not what the attempt was
  // made on (an earlier request to it, replaced).
  if (untruthful_side_ != nullptr && untruthful_side_->by == Cover::kDef2) {
    untruthful_.reset();
    std::erase_if(checks_, [](const PcCheck& c) { return c.margin_m < 0.0; });
  }
  a_.pc_checks = checks_;
  if (untruthful_) {
    a_.exchange = in_.exchanges[*untruthful_];
    a_.fault = AcceptanceFault::kUntruthful;
    return;
  }
  for (const CoopExchange& x : in_.exchanges) {
    const double d = x.accept_delivered_time_s;
    if (d < 0.0 || x.accepted_in_time(in_.p.comm_threshold_s) || !delivered_in_window(x, a_, window_from_s_, in_.p)) continue;
    if (!bounds_a_gap_seen(x)) continue;
    a_.exchange = x;
    a_.fault = AcceptanceFault::kLate;
  }
}

// A basis found: the attempt rests on it and on the truthful acceptances that cover its
// vehicles, not on a lying one it could have been made on (an earlier acceptance of the same
// vehicle, say, whose P_c a later request replaced): that one's check is dropped.
void AttemptJudge::granted() {
  untruthful_.reset();
  std::erase_if(checks_, [](const PcCheck& c) { return c.margin_m < 0.0; });
  a_.pc_checks = checks_;
}

// The ego holds the right of way as a whole once it holds it toward every vehicle of the gap
// entered; toward each vehicle, from its cover's instant.
void AttemptJudge::settle_decision_time() {
  if (a_.basis == RowBasis::kDef1) a_.decision_time_s = a_.def1.time_s;
  if (a_.basis == RowBasis::kDef2 && known_gap()) a_.decision_time_s = a_.exchange->accept_delivered_time_s;
  for (const PairCover* c : {&a_.follower, &a_.leader})
    if (c->vehicle >= 1 && c->by != Cover::kNone) a_.decision_time_s = std::max(a_.decision_time_s, c->from_s);
}

void AttemptJudge::run() {
  if (known_gap() ? try_def2() : try_def2_unknown_gap()) {
    granted();
  } else if (try_def1()) {
    granted();
  } else {
    no_basis();
  }
  settle_decision_time();
  // The right of way as a whole means toward every vehicle of the gap entered: a basis with an
  // uncovered vehicle would let the ego cut in next to it unjudged.
  for (const PairCover* c : {&a_.follower, &a_.leader})
    MG_DEMAND(a_.basis == RowBasis::kNone || c->vehicle < 1 || c->by != Cover::kNone);
}

}  // namespace

void judge_attempt_basis(const AttemptInputs& in, MergeAttempt& a, double window_from_s, double credit_from_s) {
  AttemptJudge(in, a, window_from_s, credit_from_s).run();
}

}  // namespace mg
