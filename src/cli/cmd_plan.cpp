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

namespace mg::cli {
namespace {

std::string num(double v, const char* unit) {
  if (std::isnan(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f %s", v, unit);
  return buf;
}

std::string id_or_open(int id) { return id < 0 ? "open" : std::to_string(id); }

void print_human(const std::string& scenario, const std::string& planner, const Decision& d, const PlanOutput& out) {
  std::cout << "scenario:          " << scenario << "\n"
            << "planner:           " << planner << "\n"
            << "mode:              " << to_string(d.mode) << "\n"
            << "gap:               "
            << (d.gap ? "follower " + id_or_open(d.gap->follower_id) + ", leader " + id_or_open(d.gap->leader_id) : "-")
            << "\n"
            << "v_e* interval:     [" << num(d.ve_min_mps, "m/s") << ", " << num(d.ve_max_mps, "m/s") << "]\n"
            << "v_e* chosen:       " << num(d.ve_star_mps, "m/s") << "\n"
            << "P_c bounds:        [" << num(d.pc_min_m, "m") << ", " << num(d.pc_max_m, "m") << "]\n"
            << "P_c chosen:        " << num(d.pc_m, "m") << "\n"
            << "kappa:             " << num(d.kappa_per_m, "1/m") << "\n"
            << "merge duration:    " << num(d.merge_duration_s, "s") << "\n"
            << "cooperation:       "
            << (d.coop_partner_id < 0 ? std::string("-")
                                      : "vehicle " + std::to_string(d.coop_partner_id) + ", v_o* " +
                                            num(d.vo_star_mps, "m/s") + ", D*_lon " + num(d.d_lon_star_m, "m"))
            << "\n"
            << "target speed:      " << num(out.target_speed_mps, "m/s") << "\n"
            << "proper response:   " << (out.proper_response ? "yes" : "no") << "\n"
            << "messages sent:     " << out.outbox.size() << "\n"
            << "reason:            " << d.reason << "\n";
}

int run_plan(const std::vector<std::string>& args) {
  CLI::App app("The planner's decision at the scenario's initial state", "mergeguard plan");
  std::string path;
  PlannerChoice choice{"rcpp"};
  bool json = false;
  app.add_option("scenario", path, "scenario JSON file")->required();
  add_planner_options(app, choice, "a registered planner (built in: rcpp, rcpp-coop, tripfield) or 'exec:COMMAND ARGS'");
  app.add_flag("--json", json, "print one JSON document");
  if (!parse_args(app, args)) return kExitOk;
  const Scenario scenario = load_scenario(path);
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
    j["decision"] = decision_to_json(out.decision);
    j["target_speed_mps"] = out.target_speed_mps;
    j["proper_response"] = out.proper_response;
    j["messages_sent"] = out.outbox.size();
    if (!out.decision.annotation.is_null()) j["annotation"] = out.decision.annotation;
    std::cout << j.dump(2) << "\n";
  } else {
    print_human(scenario.name, planner_name, out.decision, out);
  }
  return kExitOk;
}

}  // namespace

Command plan_command() {
  return {"plan", "plan SCENARIO.json [--planner rcpp|rcpp-coop|tripfield|exec:CMD] [--planner-timeout S] [--json]", run_plan};
}

}  // namespace mg::cli
