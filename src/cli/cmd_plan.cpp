// mergeguard plan SCENARIO.json [--planner P] [--json]: the planner's decision at the scenario's
// initial state, without simulating (spec §10). An exec planner that misbehaves fails property
// planner_responds: exit 1 with the reason.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "cli/planner_option.h"
#include "core/scenario.h"
#include "planner/planner.h"
#include "planner/planner_fault.h"
#include "planner/planner_params.h"

namespace mg::cli {
namespace {

void print_line(const std::string& label, const std::string& value) {
  std::cout << label << ":" << std::string(label.size() < 18 ? 18 - label.size() : 1, ' ') << value << "\n";
}

// The command, then the planner's own account (its annotation's lines), then the reason.
void print_human(const std::string& scenario, const std::string& planner, const PlanOutput& out) {
  char speed[64];
  std::snprintf(speed, sizeof speed, "%.3f m/s", out.target_speed_mps);
  print_line("scenario", scenario);
  print_line("planner", planner);
  print_line("mode", out.mode.empty() ? "-" : out.mode);
  if (out.annotation)
    for (const auto& [label, value] : out.annotation->describe()) print_line(label, value);
  print_line("target speed", speed);
  print_line("proper response", out.proper_response ? "yes" : "no");
  print_line("messages sent", std::to_string(out.outbox.size()));
  print_line("reason", out.reason);
}

int run_plan(const std::vector<std::string>& args) {
  CLI::App app("The planner's decision at the scenario's initial state", "mergeguard plan");
  std::string path;
  PlannerChoice choice{"rcpp"};
  bool json = false;
  app.add_option("scenario", path, "scenario JSON file")->required();
  add_planner_options(app, choice, "a registered planner (built in: rcpp, rcpp-coop, tripfield, mobil, frenet) or 'exec:COMMAND ARGS'");
  app.add_flag("--json", json, "print one JSON document");
  if (!parse_args(app, args)) return kExitOk;
  const Scenario scenario = load_planner_scenario(path);
  const std::string& planner_name = choice.name;
  start_planner(planner_name, choice);
  auto planner = make_planner(planner_name);
  const WorldSnapshot world = initial_snapshot(scenario);
  PlanOutput out;
  try {
    out = planner->plan(world);
  } catch (const PlannerFault& fault) {
    std::cout << "planner " << planner_name << ": VIOLATED planner_responds (" << fault.kind << "): " << fault.what() << "\n";
    return kExitViolation;
  }
  if (json) {
    nlohmann::json j;
    j["scenario"] = scenario.name;
    j["planner"] = planner_name;
    j["decision"] = plan_record_to_json({world.time_s, out.mode, out.reason, out.annotation});
    j["target_speed_mps"] = out.target_speed_mps;
    j["proper_response"] = out.proper_response;
    j["messages_sent"] = out.outbox.size();
    std::cout << j.dump(2) << "\n";
  } else {
    print_human(scenario.name, planner_name, out);
  }
  return kExitOk;
}

}  // namespace

Command plan_command() {
  return {"plan", "plan SCENARIO.json [--planner rcpp|rcpp-coop|tripfield|mobil|frenet|exec:CMD] [--planner-timeout S] [--planner-start-timeout S] [--json]", run_plan};
}

}  // namespace mg::cli
