#include "check/checked_run.h"

#include <memory>
#include <stdexcept>

#include "check/observed_run.h"
#include "sim/simulator.h"

namespace mg {

CheckResult check_trace(const Scenario& scenario, const Trace& trace, PlannerAccount account) {
  return check_observed(observed_trace_of(scenario, trace, account));
}

CheckResult check_scenario(const Scenario& scenario, const std::string& planner_name, PlannerAccount account) {
  std::unique_ptr<Planner> planner = make_planner(planner_name);
  if (!planner) throw std::invalid_argument("unknown planner '" + planner_name + "'");
  return check_scenario(scenario, *planner, account);
}

CheckResult check_scenario(const Scenario& scenario, Planner& planner, PlannerAccount account) {
  return check_trace(scenario, simulate(scenario, planner), account);
}

}  // namespace mg
