// Right of way and blame (spec §8, docs/spec_rules.md "Right of way from observation"). The main-lane
// vehicles hold the right of way until an observed merge attempt of the ego had it by Definition 1
// or 2 (rules/merge_attempts.h); the ego keeps it from that attempt's decision instant until the
// merge completes or it aborts. Toward each vehicle of the gap an attempt entered the ego holds it
// only as that vehicle's cover gives it (its own acceptance, or Definition 1), from the cover's
// instant; toward any other vehicle, as a whole. Blame follows RSS: the party whose obligation
// broke first, at the last safe moment (+T) before the danger or collision.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "core/observed_trace.h"
#include "core/party.h"

namespace mg {

struct CheckResult;

struct RightOfWay {
  using Intervals = std::vector<std::pair<double, double>>;  // [from, to)
  std::vector<std::pair<double, Party>> timeline;  // (time_s, holder) at every change
  Intervals ego_holds;                           // toward every vehicle
  std::vector<Intervals> toward;                 // per vehicle index (0, the ego itself, unused)
  bool ego_holds_at(double time_s) const;
  // Whether the ego held it at some instant of [from_s, to_s].
  bool ego_held_within(double from_s, double to_s) const;
  // The same toward vehicle k (an index into ObservedTrace::vehicles, >= 1).
  bool ego_holds_toward_at(std::size_t k, double time_s) const;
  bool ego_held_toward_within(std::size_t k, double from_s, double to_s) const;
};

struct MergeAttempts;
RightOfWay compute_right_of_way(const ObservedTrace& t, const MergeAttempts& attempts);

// Fills r.liable_id, r.liability_detail and r.collision_liable_id from the rule results
// (whose liable parties the monitors already set): the earliest broken obligation wins; a
// collision is blamed on the latest obligation broken at or before it (the danger that led to
// it), and with nobody liable the finding is stated and the check fails.
void assign_liability(CheckResult& r);

}  // namespace mg
