#include "paper/paper_variant.h"

#include "core/fixed_text.h"
#include "planner/rcpp_decision.h"
#include "planner/world_view.h"
#include "sim/simulator.h"

namespace mg {

PlanOutput CruiseAfterMergePlanner::plan(const WorldSnapshot& world) {
  PlanOutput out = inner_->plan(world);
  // Only plain lane keeping: an RSS proper response (kProperResponse) keeps its braking.
  if (out.mode != to_string(DecisionMode::kMerged)) return out;
  const PlannerSetup& s = *world.setup;
  const double cruise_mps = s.ego.speed_mps;
  if (out.target_speed_mps <= cruise_mps) return out;
  out.target_speed_mps = cruise_mps;
  out.accel_limit_mps2 = ego_speed_mps(world) > cruise_mps ? s.ego.limits.brake_min_mps2 : s.ego.limits.accel_max_mps2;
  out.reason += "; variant: capped at the cruise speed " + fixed_text(cruise_mps, 1) + " m/s";
  return out;
}

std::vector<PaperRun> run_cruise_variant(const Scenario& s) {
  std::vector<PaperRun> runs;
  for (const std::string& name : kPaperPlanners) {
    std::unique_ptr<Planner> planner = make_planner(name);
    if (name != "tripfield") planner = std::make_unique<CruiseAfterMergePlanner>(std::move(planner));
    Trace trace = simulate(s, *planner);
    PaperMetrics metrics = compute_paper_metrics(s, trace);
    runs.push_back({name, std::move(trace), metrics, {}});
  }
  return runs;
}

}  // namespace mg
