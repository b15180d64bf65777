#include "rules/def1_reading.h"

#include <algorithm>

#include "rules/monitor.h"

namespace mg {
namespace {

// The merge durations a Definition 1 reading at `time_s` is tried with, in order.
//   - An attempt that reached its midpoint: rho_m, or, when longer, twice the time to the midpoint
//     less the response time T. Definition 1.1 lets the follower accelerate until the ego merges;
//     rho_m alone for a merge whose midpoint came much later would predict it at a_accel^max for
//     rho_m/2 only and move onto a follower that accelerated legally the duty the ego's late
//     merge created (spec §8, point 23). T: RSS's time to turn a decision into
//     motion; a midpoint within T of the one decided is that merge, tracked with a lag.
//   - One still under way when the trace ends: rho_m, then, when longer, the shortest duration
//     whose midpoint falls after that end. Nothing has crossed the follower's path yet (an ego
//     stalled with a corner in the lane is not merging on: the RSS rules judge it there), so
//     rho_m stands where it admits a v_e*.
//   - One aborted before its midpoint: rho_m.
std::vector<double> reading_rhos_s(const ObservedTrace& t, const RuleParams& p, const ReadingSpan& a, double time_s) {
  if (a.midpoint_time_s)
    return {std::max(p.merge_duration_s, 2.0 * (*a.midpoint_time_s - time_s - t.params.rss.response_time_s))};
  std::vector<double> out = {p.merge_duration_s};
  if (!a.ended && 2.0 * (t.steps.back().time_s - time_s) > p.merge_duration_s)
    out.push_back(2.0 * (t.steps.back().time_s - time_s));
  return out;
}

// Definition 1 at step i for a gap, with a duration.
Def1Reading read_def1_at(const ObservedTrace& t, const ReadingSpan& a, const GapIndices& gap, std::size_t i,
                         double rho) {
  const double time_s = t.steps[i].time_s;
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
  return r;
}

}  // namespace

Def1Reading read_def1(const ObservedTrace& t, const RuleParams& p, const ReadingSpan& a, const GapIndices& gap,
                      std::size_t i) {
  std::optional<Def1Reading> best;
  for (const double rho : reading_rhos_s(t, p, a, t.steps[i].time_s)) {
    const Def1Reading r = read_def1_at(t, a, gap, i, rho);
    if (!best || (r.interval.feasible() && !best->interval.feasible()) ||
        (r.interval.feasible() == best->interval.feasible() && r.min_margin_m() > best->min_margin_m()))
      best = r;
    if (best->interval.feasible()) break;
  }
  return *best;
}

double pair_margin_m(const ObservedTrace& t, const Def1Reading& r, int vehicle, bool follower) {
  return follower ? def1_1_margin_m(t, r.step, vehicle, r.ve_star_mps, r.rho_s)
                  : def1_2_margin_m(t, r.step, vehicle, r.ve_star_mps, r.rho_s);
}

}  // namespace mg
