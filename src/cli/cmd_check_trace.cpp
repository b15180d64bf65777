// mergeguard check-trace TRACE.json [--report DIR] [--json] [--params FILE]: judge a saved
// observable trace (docs/trace_format.md) by every rule and assign liability, with no simulation.
// Prints and writes exactly what `check` printed and wrote for the run the trace was saved from
// (`check --save-trace`): the same summary or report JSON, the same report files, the same exit
// code (0 every rule holds, 1 a violation, 2 bad input: one line on stderr naming the file and the
// JSON path, nothing written).
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include "cli/check_output.h"
#include "cli/command.h"
#include "core/json_reader.h"
#include "core/observed_trace_json.h"
#include "core/params.h"
#include "planner/planner_params.h"
#include "rules/check.h"

namespace mg::cli {
namespace {

// --params FILE: a params object in the format of a scenario's "params" (docs/scenario_format.md),
// read strictly by params_from_json (unknown keys, wrong types, out-of-range values and repeated
// keys are errors). A trace's own "params" object ({"rss": ..., "rules": ...}) is one. Only "rss"
// and "rules" bear on a judgement: each of them present in the file replaces the trace's (its
// absent keys take their defaults, as in a scenario); an absent one leaves the trace's. "planner"
// and "sim" are accepted and validated but change nothing.
void apply_params_file(const std::string& path, ObservedTrace& trace) {
  const nlohmann::json j = parse_json_file(path, DuplicateKeys::kReject);
  Params p = params_from_json(j, path, "");
  check_planner_tunables(p.planner, path, "/planner");
  if (j.contains("rss")) trace.params.rss = p.rss;
  if (j.contains("rules")) trace.params.rules = p.rules;
}

int run_check_trace(const std::vector<std::string>& args) {
  CLI::App app("Judge a saved observable trace by every rule and assign liability (no simulation)",
               "mergeguard check-trace");
  std::string path;
  std::string params_path;
  CheckOutput output;
  app.add_option("trace", path, "observable trace JSON file (docs/trace_format.md), e.g. from check --save-trace")
      ->required();
  add_check_output_options(app, output);
  app.add_option("--params", params_path,
                 "judge with the rss and rules parameters of this params JSON file instead of the trace's own");
  if (!parse_args(app, args)) return kExitOk;
  ObservedTrace trace = load_observed_trace(path);
  if (!params_path.empty()) apply_params_file(params_path, trace);
  prepare_check_output(output);
  return emit_check_result(check_observed(std::move(trace)), output);
}

}  // namespace

Command check_trace_command() {
  return {"check-trace", "check-trace TRACE.json [--report DIR] [--json] [--params FILE]", run_check_trace};
}

}  // namespace mg::cli
