// The umbrella header of the installed package (docs/package.md): what a program needs to test
// its own planner with mergeguard. Write a Planner (planner/planner.h), register it
// (planner/planner_registry.h), then either call the checker (check/checked_run.h: check_scenario
// simulates and judges; rules/check.h: check_observed judges an observable trace), the properties
// (fuzz/properties.h), the scenario generators (fuzz/scenario_gen.h) and the campaign
// (fuzz/campaign.h) and the league of planners (league/league.h) from your own
// GoogleTest/RapidCheck suite, or hand the whole command line
// your argv (cli/cli_main.h). Every other header of the modules is installed too and is included
// the same way, e.g. "paper/paper_report.h".
#pragma once

#include "check/checked_run.h"
#include "cli/cli_main.h"
#include "core/scenario.h"
#include "core/vehicle_state.h"
#include "fuzz/campaign.h"
#include "fuzz/campaign_report.h"
#include "fuzz/corpus_case.h"
#include "fuzz/properties.h"
#include "fuzz/replay.h"
#include "fuzz/scenario_gen.h"
#include "league/league.h"
#include "planner/planner.h"
#include "planner/planner_registry.h"
#include "rules/check.h"
#include "sim/simulator.h"
#include "sim/trace.h"
