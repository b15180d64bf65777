// What every rule monitor shares (spec §8): a monitor is a pure function of the observable trace
// (core/observed_trace.h: declarations, observed states, the V2V channel), the rule parameters and
// what the checker inferred from them (merge phases and attempts, the right of way), yielding a
// signed robustness margin per trace step (NaN where the rule does not apply) and a RuleResult.
// No monitor reads a planner's annotations.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/observed_trace.h"
#include "core/party.h"
#include "rules/check.h"
#include "rules/coop_exchange.h"
#include "rules/liability.h"
#include "rules/merge_attempts.h"
#include "rules/merge_phases.h"
#include "rules/pair_geometry.h"
#include "rules/rule_catalog.h"

namespace mg {

struct MonitorContext {
  const ObservedTrace& trace;
  const RightOfWay& row;
  const RuleParams& params;      // the rules' own (trace.params.rules, or --params)
  const MergePhases& phases;     // the ego's observed merge (rules/merge_phases.h)
  const MergeAttempts& attempts; // each attempt's right of way (rules/merge_attempts.h)
  const std::vector<CoopExchange>& exchanges;  // the V2V exchanges (rules/coop_exchange.h)
};

struct MonitorOutput {
  RuleResult result;
  // One value per trace step; NaN = not applicable. Pair monitors (RSS longitudinal, collision)
  // leave out the pairs too far apart to lower the rule's minimum (MarginAccumulator::min_margin).
  std::vector<double> margin;
};

// Folds per-step margins into a RuleResult: minimum margin and its time, first violation time
// and the party liable for it, required/actual values at the worst moment.
class MarginAccumulator {
 public:
  MarginAccumulator(std::string_view rule_id, std::size_t steps);
  // Records a margin at a step. Returns true when this is the rule's first violation (the
  // caller may then set the detail line).
  // A NaN margin (a number the rule needs is missing or not finite) fails the rule: it is
  // never read as "not applicable" (monitors leave such steps out instead of recording them).
  bool record(std::size_t step, double time_s, double margin, Party party, double required,
              double actual) {
    if (std::isnan(margin)) return record_non_finite(time_s, party);
    if (step < out_.margin.size()) {
      double& m = out_.margin[step];
      m = std::isnan(m) ? margin : std::min(m, margin);
    }
    RuleResult& r = out_.result;
    if (margin < r.min_margin) {
      r.min_margin = margin;
      r.min_margin_time_s = time_s;
      r.required_value = required;
      r.actual_value = actual;
    }
    if (margin < 0.0 && !r.first_violation_time_s) {
      r.first_violation_time_s = time_s;
      r.liable_id = party;
      r.holds = false;
      return true;
    }
    return false;
  }
  void set_detail(std::string detail) { out_.result.detail = std::move(detail); }
  // Adds a sentence to the detail line ("; " between).
  void append_detail(const std::string& more) {
    std::string& d = out_.result.detail;
    d += (d.empty() ? "" : "; ") + more;
  }
  void add_measure(std::string name, double value) { out_.result.measures.emplace_back(std::move(name), value); }
  bool violated() const { return out_.result.first_violation_time_s.has_value(); }
  // The smallest margin recorded so far (+inf before the first). A record of a margin at least
  // this large, and not negative, changes nothing in the RuleResult: monitors skip computing
  // such margins for pairs too far apart to interact (docs/performance.md), so their
  // per-step margins leave out records that could not lower the rule's minimum.
  double min_margin() const { return out_.result.min_margin; }
  MonitorOutput finish();

 private:
  bool record_non_finite(double time_s, Party party);

  MonitorOutput out_;
};

// Vehicle k of a trace: 0 = ego, k >= 1 = the others, in ObservedTrace::vehicles order.
inline const ObservedState& state_of(const ObservedStep& s, std::size_t k) { return s.vehicles[k]; }
inline const ObservedState& ego_of(const ObservedStep& s) { return s.vehicles[0]; }
inline Party party_of(const ObservedTrace& t, std::size_t k) { return Party::from_vehicle_id(t.vehicles[k].id); }
inline const VehicleSize& size_of(const ObservedTrace& t, std::size_t k) { return t.vehicles[k].size; }
inline const Limits& limits_of(const ObservedTrace& t, std::size_t k) { return t.vehicles[k].limits; }
// Index k of a party (0 for the ego), or -1 for one that is no vehicle of the trace.
inline int index_of_party(const ObservedTrace& t, Party party) {
  if (party.is_nobody() || party.is_main_lane()) return -1;
  return t.index_of(party.is_ego() ? 0 : party.vehicle_id());  // the ego is vehicle id 0
}
// Index of the trace step nearest to time_s.
std::size_t step_at(const ObservedTrace& t, double time_s);
// Index of the first step at or after time_s (within kTieS); steps.size() when there is none.
std::size_t step_at_or_after(const ObservedTrace& t, double time_s);
inline double speed_of(const ObservedState& v) { return v.vx_mps; }  // road-frame longitudinal speed
// The trace's sampling interval (its first step; 0 for fewer than two steps).
double step_interval_s(const ObservedTrace& t);
// Whether the ego is the rear vehicle of an RSS-dangerous pair (both distances unsafe) at step i:
// its RSS proper response then governs its speed.
bool ego_rear_in_rss_danger(const MonitorContext& ctx, std::size_t step);

inline constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

// Trace times are sums of steps and deadlines are computed another way: the same instant may
// differ by rounding (~1e-15 s). Closed windows and deadlines include such ties (spec §8, "Ties at
// deadlines").
inline constexpr double kTieS = 1e-9;

}  // namespace mg

namespace mg {

using MonitorFn = MonitorOutput (*)(const MonitorContext&);
// Every monitor. Each judges one rule of rules/catalog.json and names it in its RuleResult (the
// monitor is the one place in code that writes the rule's id); together they judge every rule
// of the catalogue exactly once.
std::span<const MonitorFn> rule_monitors();
// Runs every monitor; the results (and margins, kept only when `margins` is not null) come in
// catalogue order (= report order). A rule judged twice or not at all is a std::logic_error.
std::vector<RuleResult> run_monitors(const MonitorContext& ctx, std::vector<std::vector<double>>* margins);

}  // namespace mg
