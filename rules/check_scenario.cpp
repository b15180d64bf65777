// check_scenario lives apart from check_trace so that tools which only judge existing traces
// do not link the planners and the simulator.
#include <stdexcept>

#include "planner/planner.h"
#include "rules/check.h"
#include "sim/simulator.h"

namespace mg {

CheckResult check_scenario(const Scenario& scenario, const std::string& planner_name) {
  std::unique_ptr<Planner> planner = make_planner(planner_name);
  if (!planner) throw std::invalid_argument("unknown planner '" + planner_name + "'");
  return check_trace(scenario, simulate(scenario, *planner));
}

}  // namespace mg
