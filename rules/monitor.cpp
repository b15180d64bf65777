#include "rules/monitor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mg {

MarginAccumulator::MarginAccumulator(std::string_view rule_id, std::size_t steps) {
  const RuleSpec& spec = rule_spec(rule_id);
  out_.result.rule_id = spec.id;
  out_.result.paper_ref = spec.paper_ref;
  out_.result.unit = spec.unit;
  out_.result.min_margin = std::numeric_limits<double>::infinity();
  out_.margin.assign(steps, kNotApplicable);
}

bool MarginAccumulator::record_non_finite(double time_s, Party party) {
  RuleResult& r = out_.result;
  r.min_margin = std::numeric_limits<double>::lowest();  // the worst margin there is, and finite
  r.min_margin_time_s = time_s;
  r.required_value = r.actual_value = std::numeric_limits<double>::quiet_NaN();
  if (r.first_violation_time_s) return false;
  r.first_violation_time_s = time_s;
  r.liable_id = party;
  r.holds = false;
  r.detail = "a number this rule needs is missing or not finite at t = " + std::to_string(time_s) + " s";
  return false;  // the detail says why; the caller's detail would quote the non-finite margin
}

MonitorOutput MarginAccumulator::finish() {
  if (std::isinf(out_.result.min_margin) && out_.result.detail.empty()) {
    out_.result.detail = "not applicable in this trace";
  }
  return std::move(out_);
}

std::size_t step_at(const ObservedTrace& t, double time_s) {
  if (t.steps.empty()) return 0;
  auto it = std::lower_bound(t.steps.begin(), t.steps.end(), time_s,
                             [](const ObservedStep& s, double v) { return s.time_s < v; });
  if (it == t.steps.end()) return t.steps.size() - 1;
  std::size_t i = static_cast<std::size_t>(it - t.steps.begin());
  if (i > 0 && time_s - t.steps[i - 1].time_s < it->time_s - time_s) --i;
  return i;
}

std::size_t step_at_or_after(const ObservedTrace& t, double time_s) {
  const auto it = std::lower_bound(t.steps.begin(), t.steps.end(), time_s - kTieS,
                                   [](const ObservedStep& s, double v) { return s.time_s < v; });
  return static_cast<std::size_t>(it - t.steps.begin());
}

double step_interval_s(const ObservedTrace& t) {
  return t.steps.size() < 2 ? 0.0 : t.steps[1].time_s - t.steps[0].time_s;
}

bool ego_rear_in_rss_danger(const MonitorContext& ctx, std::size_t step) {
  for (std::size_t j = 1; j < ctx.trace.vehicles.size(); ++j) {
    const PairGeometry g = pair_geometry(ctx.trace, ctx.trace.steps[step], 0, j);
    if (g.rear == 0 && g.lat_unsafe() && g.lon_unsafe()) return true;
  }
  return false;
}

}  // namespace mg
