// What every rule monitor shares (spec §8): a monitor is a pure function of the scenario and
// the trace (plus the right-of-way timeline derived from them) that yields a signed robustness
// margin per trace step (NaN where the rule does not apply) and a RuleResult.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/scenario.h"
#include "rules/check.h"
#include "rules/liability.h"
#include "rules/merge_phases.h"
#include "rules/pair_geometry.h"
#include "rules/rule_catalog.h"
#include "sim/trace.h"

namespace mg {

struct MonitorContext {
  const Scenario& scenario;
  const Trace& trace;
  const RightOfWay& row;
  const CatalogParams& params;
  const MergePhases& phases;  // the ego's observed merge (rules/merge_phases.h)
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
  bool record(std::size_t step, double time_s, double margin, int party, double required,
              double actual) {
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
  bool violated() const { return out_.result.first_violation_time_s.has_value(); }
  // The smallest margin recorded so far (+inf before the first). A record of a margin at least
  // this large, and not negative, changes nothing in the RuleResult: monitors skip computing
  // such margins for pairs too far apart to interact (issue 20, docs/performance.md), so their
  // per-step margins leave out records that could not lower the rule's minimum.
  double min_margin() const { return out_.result.min_margin; }
  MonitorOutput finish();

 private:
  MonitorOutput out_;
};

// Vehicle k of a trace step: 0 = ego, k >= 1 = scenario.vehicles[k - 1].
inline const VehicleState& state_of(const TraceStep& s, std::size_t k) {
  return k == 0 ? s.ego : s.others[k - 1];
}
int party_of(const Scenario& s, std::size_t k);
inline const VehicleSize& size_of(const Scenario& s, std::size_t k) {
  return k == 0 ? s.ego.size : s.vehicles[k - 1].size;
}
inline const Limits& limits_of(const Scenario& s, std::size_t k) {
  return k == 0 ? s.ego.limits : s.vehicles[k - 1].limits;
}
// Index k of a party id (0 for the ego), or -1.
int index_of_party(const Scenario& s, int party_id);
// Index of the trace step nearest to time_s.
std::size_t step_at(const Trace& t, double time_s);
double speed_of(const VehicleState& v);  // road-frame longitudinal speed
// Whether the ego is the rear vehicle of an RSS-dangerous pair (both distances unsafe) at step i:
// its RSS proper response then governs its speed.
bool ego_rear_in_rss_danger(const MonitorContext& ctx, std::size_t step);

inline constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

}  // namespace mg

namespace mg {

using MonitorFn = MonitorOutput (*)(const MonitorContext&);
struct MonitorEntry {
  std::string_view rule_id;
  MonitorFn run;
};
// Every monitor, in catalogue order (rules/catalog.json lists exactly these ids).
const std::vector<MonitorEntry>& rule_monitors();
// Runs every monitor; margins are kept only when `margins` is not null (reports).
std::vector<RuleResult> run_monitors(const Scenario& s, const Trace& t, const RightOfWay& row,
                                     const MergePhases& phases, std::vector<std::vector<double>>* margins);

}  // namespace mg
