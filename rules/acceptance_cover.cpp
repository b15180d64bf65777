#include "rules/acceptance_cover.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "rules/definition1_gap.h"
#include "rules/monitor.h"

namespace mg {

bool delivered_in_window(const CoopExchange& x, const MergeAttempt& a, double from_s, const RuleParams& p) {
  const double d = x.accept_delivered_time_s;
  if (d < 0.0 || d > a.entry_time_s.value_or(a.start_time_s) + kTieS) return false;
  return d >= from_s - kTieS || a.start_time_s <= x.request_time_s + p.comm_threshold_s + p.merge_duration_s + kTieS;
}

PcCheck pc_check_of(const ObservedTrace& t, const CoopExchange& x, std::size_t i, const MergeAttempt& a) {
  PcCheck c{i, x.request->pc_m, *a.crossing_x_m, *a.crossing_time_s};
  c.tolerance_m = std::max(a.crossing_speed_mps * t.params.rss.response_time_s, 0.5 * t.vehicles[0].size.length_m);
  c.margin_m = x.request->coop_case == CoopCase::kEgoAhead ? c.crossing_x_m - (c.pc_m - c.tolerance_m)
                                                            : (c.pc_m + c.tolerance_m) - c.crossing_x_m;
  return c;
}

double other_vehicle_margin_m(const ObservedTrace& t, const RuleParams& p, const CoopExchange& x, int other,
                              bool other_is_follower) {
  if (other < 1) return std::numeric_limits<double>::infinity();
  const std::size_t i = std::min(step_at_or_after(t, x.sent_time_s), t.steps.size() - 1);
  const double v_e = std::max(0.0, t.steps[i].vehicles[0].vx_mps);
  const double rho_c = p.comm_threshold_s, rho_m = p.merge_duration_s;
  const double v_after = x.request->coop_case == CoopCase::kEgoAhead
                             ? v_e
                             : std::max(0.0, v_e - t.vehicles[0].limits.brake_min_mps2 * rho_c);
  return other_is_follower ? def1_1_margin_m(t, i, other, v_after, 2.0 * rho_c + rho_m)
                           : def1_2_margin_m(t, i, other, v_after, rho_c + rho_m);
}

int requested_gap_other(const ObservedTrace& t, const CoopExchange& x) {
  const std::size_t i = std::min(step_at_or_after(t, x.sent_time_s), t.steps.size() - 1);
  const int k = t.index_of(x.request->to_id);
  const bool ahead = x.request->coop_case == CoopCase::kEgoAhead;
  for (const GapIndices& g : lane_gaps(t, i)) {
    if (ahead && g.follower == k) return g.leader;
    if (!ahead && g.leader == k) return g.follower;
  }
  return -1;
}

bool other_gap_vehicle_clear(const ObservedTrace& t, const RuleParams& p, const CoopExchange& x) {
  const bool other_is_follower = x.request->coop_case == CoopCase::kEgoBehind;
  return other_vehicle_margin_m(t, p, x, requested_gap_other(t, x), other_is_follower) >= 0.0;
}

}  // namespace mg
