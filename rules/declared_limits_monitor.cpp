#include "rules/declared_limits_monitor.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace mg {

double declared_limits_margin_mps2(const ObservedTrace& t, const RuleParams& p, std::size_t i, std::size_t k) {
  const Limits& lim = limits_of(t, k);
  const double a = state_of(t.steps[i], k).accel_mps2;
  return std::min(lim.accel_max_mps2 + p.accel_tolerance_mps2 - a, lim.brake_max_mps2 + p.accel_tolerance_mps2 + a);
}

bool beyond_declared_limits(const ObservedTrace& t, const RuleParams& p, std::size_t i, std::size_t k) {
  return declared_limits_margin_mps2(t, p, i, k) < 0.0;
}

MonitorOutput monitor_declared_limits(const MonitorContext& ctx) {
  const ObservedTrace& t = ctx.trace;
  const auto& steps = t.steps;
  MarginAccumulator acc("declared_limits", steps.size());
  if (t.vehicles.empty()) return acc.finish();
  for (std::size_t i = 0; i < steps.size(); ++i) {
    // The earliest breach is the one that counts; at one step the vehicle furthest beyond its
    // limit (the smallest margin) is named.
    double worst = std::numeric_limits<double>::infinity();
    std::size_t who = 0;
    for (std::size_t k = 0; k < t.vehicles.size(); ++k) {
      const double m = declared_limits_margin_mps2(t, ctx.params, i, k);
      if (m < worst) {
        worst = m;
        who = k;
      }
    }
    const Limits& lim = limits_of(t, who);
    const double a = state_of(steps[i], who).accel_mps2;
    const bool braking = a < 0.0;
    if (acc.record(i, steps[i].time_s, worst, party_of(t, who), braking ? -lim.brake_max_mps2 : lim.accel_max_mps2,
                   a)) {
      std::ostringstream os;
      os << party_name(party_of(t, who)) << (braking ? " braked at " : " accelerated at ") << (braking ? -a : a)
         << " m/s2 at t = " << steps[i].time_s << " s, beyond its declared "
         << (braking ? "a_brake^max = " : "a_accel^max = ") << (braking ? lim.brake_max_mps2 : lim.accel_max_mps2)
         << " m/s2";
      acc.set_detail(os.str());
    }
  }
  return acc.finish();
}

}  // namespace mg
