// Right of way and blame (spec §8). The main-lane vehicles hold the right of way until the
// ego has established a Definition 1 gap (a Def. 1 merge decision) or a Definition 2
// acceptance (a Def. 2 merge after the partner's acceptance was delivered); the ego keeps it
// until the merge completes or it aborts. Blame follows RSS: the party whose obligation broke
// first, at the last safe moment (+T) before the danger or collision.
#pragma once

#include <utility>
#include <vector>

#include "core/scenario.h"
#include "sim/trace.h"

namespace mg {

struct CheckResult;

struct RightOfWay {
  std::vector<std::pair<double, int>> timeline;      // (time_s, holder) at every change
  std::vector<std::pair<double, double>> ego_holds;  // [from, to) intervals
  bool ego_holds_at(double time_s) const;
  // Whether the ego held it at some instant of [from_s, to_s].
  bool ego_held_within(double from_s, double to_s) const;
};

struct MergePhases;
RightOfWay compute_right_of_way(const Scenario& s, const Trace& t, const MergePhases& phases);
// The same, observing the merge phases from the trace itself.
RightOfWay compute_right_of_way(const Scenario& s, const Trace& t);

// Time an acceptance from `partner_id` was delivered to the ego at or before `time_s`
// (the latest such), or a negative value when none was.
double acceptance_time(const Trace& t, int partner_id, double time_s);

// Fills r.liable_id, r.liability_detail and r.collision_liable_id from the rule results
// (whose liable parties the monitors already set): the earliest broken obligation wins; a
// collision is blamed on the latest obligation broken at or before it (the danger that led to
// it), and with nobody liable the finding is stated and the check fails.
void assign_liability(CheckResult& r);

}  // namespace mg
