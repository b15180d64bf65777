// Each merge attempt the ego was observed to make, and whether it held the right of way for it
// (docs/spec.md, "Right of way from observation"). Read from the observable trace alone:
//
//   - an attempt runs from an observed merge start to its abort or its completion
//     (rules/merge_phases.h);
//   - the gap it entered is the follower and leader around the ego in the target lane where the
//     attempt crossed the lane line (its midpoint), or, for an aborted attempt, at its start;
//   - Definition 2: the right of way comes from an acceptance of the ego's request delivered to
//     the ego within rho_c of the request, in the decision window [start - W, entry], entry being
//     when the ego's body first reached into the main lane (its start, if it never did);
//   - Definition 1: otherwise, the latest step T of that window at which some v_e* in [0, speed
//     limit] satisfies ineq. (1.1) and (1.2) (definition1_gap.h) for the gap it entered or for the
//     gap around the ego at T (a follower may have raced past it since), with rho = the
//     rule's rho_m or, when longer, the duration the merge observably took (2 (T_mid - T)).
//     The ego then holds from the earliest step of the run of steps ending at T at which the same
//     gap stayed feasible: a planner that decided when the gap opened is credited from then.
//     v_e* is not the ego's realised speed (that would count a braking ego's proper response
//     against it) but the feasible value nearest to it at the midpoint; the ego's execution is
//     judged at the midpoint by sigmoid_pc_bounds and throughout by the RSS rules;
//   - none: the ego merged without the right of way; the best Definition 1 reading of the
//     window is kept for the def1 gap rules' margins.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/observed_trace.h"
#include "rules/coop_exchange.h"
#include "rules/definition1_gap.h"
#include "rules/merge_phases.h"

namespace mg {

enum class RowBasis { kNone, kDef1, kDef2 };
std::string to_string(RowBasis b);

struct Def1Reading {
  GapIndices gap;
  std::size_t step = 0;
  double time_s = 0.0;
  double rho_s = 0.0;
  Def1Interval interval;
  double ve_star_mps = 0.0;   // the v_e* the margins are stated at
  double observed_mps = 0.0;  // the ego's observed speed it was chosen nearest to
  double margin_11_m = std::numeric_limits<double>::infinity();
  double margin_12_m = std::numeric_limits<double>::infinity();
  double min_margin_m() const { return margin_11_m < margin_12_m ? margin_11_m : margin_12_m; }
};

struct MergeAttempt {
  std::size_t start_step = 0;
  double start_time_s = 0.0;
  std::optional<double> midpoint_time_s;
  // The first step at which the ego's body reached into the main lane (its leftmost corner past
  // the lane line): Definition 1's gap rules judge only attempts that entered it.
  std::optional<std::size_t> entry_step;
  std::optional<double> entry_time_s;
  std::optional<double> end_time_s;    // abort or completion
  bool completed = false;
  GapIndices entered_gap;              // around the ego where it crossed the line (or at its start)
  GapIndices gap;                      // the gap the basis was read for
  RowBasis basis = RowBasis::kNone;
  double decision_time_s = 0.0;        // from when the ego held it (basis != kNone)
  Def1Reading def1;                    // kDef1: the reading that held; kNone: the best one
  bool def1_read = false;              // whether def1 holds a reading (a window with steps)
  std::optional<CoopExchange> exchange;  // kDef2: the accepted one; kNone: a late one, if any
  std::string observation;             // one line for the report: what decided the basis
};

struct MergeAttempts {
  std::vector<MergeAttempt> attempts;
};

// Whether the gap's vehicle other than the partner of an accepted request leaves room for the
// Definition 2 merge, judged at the request (the vehicle ahead of the partner for 2.1, behind it for
// 2.2, by Definition 1's inequalities).
bool other_gap_vehicle_clear(const ObservedTrace& t, const RuleParams& p, const CoopExchange& x);

MergeAttempts observe_merge_attempts(const ObservedTrace& t, const RuleParams& p, const MergePhases& phases);

}  // namespace mg
