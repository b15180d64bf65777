// `mergeguard reproduce-paper --search`: the paper publishes no scenario numbers,
// so we look for the scenario in which the three planners, with their default parameters,
// behave as §IV describes. A bounded, deterministic staged grid over the scenario alone (the
// initial gap, both speeds, the obstacle's limits and IDM headway, the V2V latency and the
// on-ramp length); every candidate is scored by the report's own claims (paper/paper_claims.h).
#pragma once

#include <string>
#include <vector>

#include "core/scenario.h"
#include "paper/paper_claims.h"

namespace mg {

// One point of the search space. The ego starts at X = 0 on the on-ramp; the obstacle (the
// base scenario's first main-lane vehicle) gap_m ahead of it (negative: behind) and drives at
// obstacle_speed_mps, which is also its IDM desired speed.
struct PaperSearchCandidate {
  double gap_m = 0.0;
  double ego_speed_mps = 20.0;
  double obstacle_speed_mps = 18.0;
  double obstacle_accel_max_mps2 = 2.0;
  double obstacle_brake_min_mps2 = 4.0;
  double obstacle_headway_s = 1.5;
  double latency_s = 0.1;        // both directions of the V2V exchange
  double ramp_end_x_m = 300.0;   // side_lane_end_x_m
  double obstacle_comfort_brake_mps2 = 2.0;  // IDM b: how gently it yields
  // A second main-lane vehicle (IDM, no V2V) lead_gap_m ahead of the ego at lead_speed_mps, or
  // none when lead_gap_m <= 0: what the ego follows after merging ahead of the obstacle (the
  // paper's non-coop ego "slows to 20 m/s post-merging"; without one RCPP keeps the lane at the
  // speed limit).
  double lead_gap_m = 0.0;
  double lead_speed_mps = 20.0;
};

struct PaperSearchResult {
  PaperSearchCandidate candidate;
  int stage = 1;
  bool consistent = false;       // every planner merged without collision (paper_results_consistent's first half)
  int reproduced = 0;            // claims reproduced, of kPaperClaimCount
  double headline_miss = 0.0;    // tie-break: distance of the headline numbers from 72.3 % / 53.4 %, in 10-point units
  std::vector<int> failed_rows;  // 1-based rows of the report's table that do not reproduce
};

// The base scenario with the candidate applied (names it after the candidate).
Scenario apply_search_candidate(const Scenario& base, const PaperSearchCandidate& c);

PaperSearchResult evaluate_search_candidate(const Scenario& base, const PaperSearchCandidate& c, int stage);

// Better first: consistent, then more rows reproduced, then the smaller headline miss; a
// strict weak order, ties kept in evaluation order by the caller's stable sort.
bool search_result_better(const PaperSearchResult& a, const PaperSearchResult& b);

struct PaperSearch {
  std::vector<PaperSearchResult> results;  // every evaluated candidate, best first
  std::vector<int> stage_sizes;            // candidates evaluated per stage
};

// Stage 1: gap x ego speed x obstacle speed x ramp length x lead vehicle, the obstacle's
// behaviour at the base scenario's. Stage 2: the obstacle's accel_max, brake_min, IDM headway
// and comfortable braking and the V2V latency around the best kStage2Seeds of stage 1. Stage 3: gap and speeds refined around the
// best so far. About 9,000 candidates x 3 simulations (about 1.5 minutes on one core).
inline constexpr int kStage2Seeds = 5;
inline constexpr int kRefineSeeds = 5;
inline constexpr int kRefineRounds = 3;
PaperSearch run_paper_search(const Scenario& base);

// docs/paper_search.md: the space, the stage sizes, and the best `top` candidates' scores.
std::string paper_search_markdown(const PaperSearch& search, const std::string& base_path, int top);

// The best candidate's scenario as JSON (the scenario file format).
nlohmann::json best_search_scenario_json(const Scenario& base, const PaperSearch& search);

}  // namespace mg
