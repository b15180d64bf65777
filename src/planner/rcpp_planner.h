// The RCPP planner (RCPP §II, spec §4-§6) as its stages, each cycle: the Definition 1 search
// (planner/definition1_search.h) picks a gap, v_e* and the sigmoid; with cooperation enabled
// ("rcpp-coop") the Definition 2 search (planner/definition2_search.h) asks a V2V neighbour for
// v_o* when no Definition 1 gap exists; with neither, Definition 1.3 halts before the side lane's
// end. A merge once decided is committed, re-checked and possibly aborted
// (planner/committed_merge.h), or replaced by a better one (planner/merge_revision.h); in the side
// lane the return stage draws the path (planner/side_lane_path.h); the RSS proper response
// overrides last (planner/rss_override.h).
// RcppDecision rules and cost: docs/planner.md.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <variant>

#include "planner/braking_memory.h"
#include "planner/committed_merge.h"
#include "planner/definition2_search.h"
#include "planner/merge_revision.h"
#include "planner/planner.h"
#include "planner/reversal_ledger.h"
#include "planner/side_lane_path.h"

namespace mg {

// A Definition 2 request sent, awaiting its answer until deadline_s (Def. 2.3).
struct PendingRequest {
  Def2Plan plan;
  double deadline_s = 0.0;
};

// RCPP's state: one of three phases. In the side lane (from the start, and after an abort), with
// what the side lane remembers; merging along a committed sigmoid; in the main lane (merged, or
// started there), for good.
struct InSideLane {
  SideLaneLateral lateral;
  std::optional<PendingRequest> pending;
  double no_merge_before_s = -1.0;    // after an abort: earliest time of a new merge
  double next_longer_merge_s = -1.0;  // next time the longer merge durations are searched
};
struct InMainLane {};
using RcppPhase = std::variant<InSideLane, Merging, InMainLane>;

class RcppPlanner : public Planner {
 public:
  explicit RcppPlanner(bool cooperative) : cooperative_(cooperative) {}
  std::string name() const override { return cooperative_ ? "rcpp-coop" : "rcpp"; }
  PlanOutput plan(const WorldSnapshot& w) override;
  const RcppPhase& phase() const { return phase_; }

 private:
  // A side-lane cycle's command, or the merge it starts.
  struct SideLaneStep {
    RcppCycle out;
    std::optional<CommittedMerge> merge;
  };
  std::string advance_phase(const WorldSnapshot& w);  // completion, abort, a start in the main lane
  SideLaneStep decide_in_side_lane(InSideLane& side, const WorldSnapshot& w);
  bool defers_merge(const InSideLane& side, const WorldSnapshot& w, bool turns_away) const;
  void forget_broken_acceptance(const CommittedMerge& aborted, const WorldSnapshot& w);
  std::optional<CommittedMerge> read_reply(InSideLane& side, const WorldSnapshot& w, std::string& note);
  void send_request(InSideLane& side, const WorldSnapshot& w, RcppCycle& out, std::string& note);

  bool cooperative_;
  RcppPhase phase_;
  std::map<int, double> retry_after_s_;  // partner id -> earliest time of a new request, kept across merges
  // Until when the latest Def. 2.2 request binds the ego to braking at most b_min (Def. 2.2A:
  // rho_c after it, whether or not the ego still waits for its answer); -1 once refused.
  double ego_behind_request_until_s_ = -1.0;
  // The latest acceptance read, kept while it binds its sender: a merge made on it and aborted
  // may be made again on it (plan_accepted_definition2).
  std::optional<HeldAcceptance> held_;
  BrakingMemory braking_;
  ReversalLedger reversals_;  // starts a merge only while an abort of it stays within the smoothness rule
};

}  // namespace mg
