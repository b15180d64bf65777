// The fifteen claims of the RCPP paper's §IV (text of Fig. 4 and Fig. 5 and the abstract's
// headline numbers), each judged mechanically on one run of the three planners.
// The report's "Paper vs. ours" table and `reproduce-paper --search` share these criteria, so
// the scenario the search picks is scored exactly as the report judges it.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/party.h"
#include "core/scenario.h"
#include "paper/paper_metrics.h"
#include "sim/trace.h"

namespace mg {

inline const std::vector<std::string> kPaperPlanners{"tripfield", "rcpp", "rcpp-coop"};

struct PaperRun {
  std::string planner;
  Trace trace;
  PaperMetrics metrics;
  // Right-of-way holder at every change (rules/liability.h), when the
  // run was judged (run_paper_planners' with_right_of_way); empty otherwise.
  std::vector<std::pair<double, Party>> right_of_way;
};

struct PaperClaim {
  std::string what;       // e.g. "TriPField merge point"
  std::string paper;      // what the paper reports
  std::string ours;       // what our run measured
  bool reproduced = false;
  std::string criterion;  // the mechanical test
  std::string why_not;    // when not reproduced: what the run shows instead, where it can say
};

inline constexpr int kPaperClaimCount = 15;

// The runs in kPaperPlanners order; the obstacle is the scenario's first main-lane vehicle.
std::vector<PaperClaim> paper_claims(const Scenario& s, const std::vector<PaperRun>& runs);
int reproduced_count(const std::vector<PaperClaim>& claims);

// Time of the largest |sideslip| of the ego and its signed value.
std::pair<double, double> sideslip_peak(const Trace& t);
// First time the obstacle (main-lane vehicle 0) brakes harder than kObstacleBrakingMps2.
inline constexpr double kObstacleBrakingMps2 = 0.5;
std::optional<double> obstacle_first_braking_s(const Trace& t);
// First event of kind k whose actor is vehicle_id.
std::optional<double> first_event_s(const Trace& t, EventKind k, int vehicle_id);
// The first Definition 1 merge decision of a run, in words: on which side of vehicle_id the
// ego merged, at which v_e* and rho (empty when it never took one).
std::string def1_merge_side(const Trace& t, int vehicle_id);
// First delivery to the ego of an acceptance (Def. 2.3) from vehicle_id.
std::optional<double> first_acceptance_s(const Trace& t, int vehicle_id);

}  // namespace mg
