// Each merge attempt the ego was observed to make, and whether it held the right of way for it
// (docs/spec_rules.md, "Right of way from observation"). Read from the observable trace alone:
//
//   - an attempt runs from an observed merge start to its abort or its completion
//     (rules/merge_phases.h);
//   - the gap it entered is the follower and leader around the ego in the target lane where the
//     attempt crossed the lane line (its midpoint), or, for an aborted attempt, at its start;
//   - the right of way is per vehicle of the gap entered (for an attempt that reached its
//     midpoint): each is covered by its own acceptance of a request (Definition 2), or by a
//     Definition 1 reading, or it is not; the attempt holds the right of way when every one is;
//   - Definition 2: an acceptance of the ego's request delivered to the ego within rho_c of t_r
//     (rules/coop_exchange.h), in the decision window [start - W, entry], entry being when the
//     ego's body first reached into the main lane (its start, if it never did), covers its sender
//     when the sender bounds the gap entered on the side its case names (ego ahead: the
//     follower; ego behind: the leader) and the request told the truth (coop_exchange.h's order,
//     and P_c against the observed crossing); the gap's other vehicle is then judged by
//     Definition 1 for that pair at the request;
//   - Definition 1: otherwise, the latest step T of that window at which some v_e* in [0, speed
//     limit] satisfies ineq. (1.1) and (1.2) (definition1_gap.h) for the gap it entered or for the
//     gap around the ego at T (a follower may have raced past it since), with rho = max(rho_m,
//     2 (T_mid - T - T_resp)) for an attempt that reached its midpoint: the follower is predicted
//     to accelerate until the merge's observed midpoint (reading_rhos_s).
//     A vehicle of the gap entered that is not one of that gap's is judged by Definition 1 for
//     that pair at the same reading. The ego then holds from the earliest step of the run of
//     steps ending at T at which the same reading stayed good: a planner that decided when the gap
//     opened is credited from then. v_e* is not the ego's realised speed (that would count a
//     braking ego's proper response against it) but the feasible value nearest to it at the
//     midpoint; the ego's execution is judged at the midpoint by sigmoid_pc_bounds and throughout
//     by the RSS rules;
//   - none: the ego merged without the right of way toward some vehicle; the best Definition 1
//     reading of the window is kept for the def1 gap rules' margins.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/observed_trace.h"
#include "rules/coop_exchange.h"
#include "rules/def1_reading.h"
#include "rules/definition1_gap.h"
#include "rules/merge_phases.h"

namespace mg {

enum class RowBasis { kNone, kDef1, kDef2 };
std::string to_string(RowBasis b);

// What gives the ego the right of way toward one vehicle of the gap it entered.
enum class Cover {
  kNone,      // nothing: the ego merged next to it without the right of way
  kDef2,      // that vehicle's own acceptance of a truthful request
  kDef2Pair,  // Definition 1 for that pair at the request of the other vehicle's acceptance
  kDef1,      // the Definition 1 reading (a vehicle of the gap it was read for)
  kDef1Pair,  // Definition 1 for that pair at the reading
};
std::string to_string(Cover c);

struct PairCover {
  int vehicle = -1;  // index into ObservedTrace::vehicles; -1: open side
  Cover by = Cover::kNone;
  double from_s = 0.0;  // the ego holds the right of way toward it from then (covered)
  // Definition 1 toward it for the pair alone, in metres (ineq. (1.1) for the follower, (1.2)
  // for the leader): the check that covered it (kDef2Pair, kDef1Pair), or, uncovered, at the
  // best reading of the window. +inf where no such check was made.
  double margin_m = std::numeric_limits<double>::infinity();
  std::optional<std::size_t> exchange;  // kDef2: the acceptance; kDef2Pair: the other vehicle's
};

// A request's P_c against where the ego's centre crossed the lane line: ego ahead (2.1), the
// crossing no nearer the responder than P_c - tol; ego behind (2.2), no nearer than P_c + tol.
// tol = max(v_cross T, l_e/2): the ground the ego covers in the response time at its crossing
// speed (RSS gives every vehicle T to turn a decision into the motion that carries it out, and a
// crossing within that lag of the one announced is the merge announced), and at least half the
// ego's length (P_c then lies under the ego's body as its centre crosses: the request placed the
// merge to within the vehicle itself) (docs/spec.md §5).
struct PcCheck {
  std::size_t exchange = 0;  // index into the exchanges
  double pc_m = 0.0;
  double crossing_x_m = 0.0;
  double crossing_time_s = 0.0;
  double tolerance_m = 0.0;
  double margin_m = 0.0;  // >= 0: on the responder's safe side within tol
};

// Why an acceptance the attempt was made on gave it nothing.
enum class AcceptanceFault {
  kNone,
  kLate,        // delivered after t_r + rho_c (def2_3_fallback's)
  kUntruthful,  // its request misstated the case or P_c, or lacks a number (def2_request_truthful's)
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
  std::optional<double> crossing_x_m;  // where its centre crossed the line (interpolated) ...
  std::optional<double> crossing_time_s;  // ... when ...
  double crossing_speed_mps = 0.0;        // ... and at what longitudinal speed
  // The entered gap's follower and leader, for an attempt that reached its midpoint (the gap
  // entered is known); unset (-1) otherwise.
  PairCover follower;
  PairCover leader;
  GapIndices gap;                      // the gap the Definition 1 reading was read for
  RowBasis basis = RowBasis::kNone;
  double decision_time_s = 0.0;        // from when the ego held it toward every vehicle (basis != kNone)
  Def1Reading def1;                    // kDef1: the reading that held; kNone: the best one
  bool def1_read = false;              // whether def1 holds a reading (a window with steps)
  // kDef2: the acceptance that granted it (the first); kNone: one the attempt was made on that
  // could not grant (fault says why).
  std::optional<CoopExchange> exchange;
  AcceptanceFault fault = AcceptanceFault::kNone;
  std::vector<PcCheck> pc_checks;      // every acceptance the attempt was made on, against its crossing
  std::string observation;             // one line for the report: what decided the basis
};

struct MergeAttempts {
  std::vector<MergeAttempt> attempts;
};

// `exchanges` as coop_exchanges gives them; `around` the gap around the ego at every step.
MergeAttempts observe_merge_attempts(const ObservedTrace& t, const RuleParams& p, const MergePhases& phases,
                                     const std::vector<CoopExchange>& exchanges,
                                     const std::vector<GapIndices>& around);

}  // namespace mg
