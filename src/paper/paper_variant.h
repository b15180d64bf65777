// A clearly labelled, report-only variant of the RCPP planners, never a default:
// after the merge the ego keeps its lane at its initial (cruise) speed instead of the speed
// limit, as the TriPField-style baseline does and as the paper's Fig. 5(d) suggests ("briefly
// accelerates to 30 m/s then slows to 20 m/s post-merging"; the cooperative ego "maintains a
// steady speed"). It wraps the registered planner and changes nothing else: the fuzzer and
// every other command use the planners unwrapped.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/scenario.h"
#include "paper/paper_claims.h"
#include "planner/planner.h"

namespace mg {

class CruiseAfterMergePlanner final : public Planner {
 public:
  explicit CruiseAfterMergePlanner(std::unique_ptr<Planner> inner) : inner_(std::move(inner)) {}
  std::string name() const override { return inner_->name() + "+cruise-after-merge"; }
  // The inner plan; in lane keeping after the merge (DecisionMode::kMerged) its target speed
  // capped at the scenario's initial ego speed.
  PlanOutput plan(const WorldSnapshot& world) override;

 private:
  std::unique_ptr<Planner> inner_;
};

// The three planners of the report on s, the two RCPP variants wrapped (kPaperPlanners order,
// the planner names unchanged so that paper_claims() reads them).
std::vector<PaperRun> run_cruise_variant(const Scenario& s);

}  // namespace mg
