// What `check` and `check-trace` do with a judgement (one code path, so that judging a saved trace
// prints and writes exactly what checking the run did): the --report and --json options, the
// report files, the human or JSON summary on stdout and the exit code.
#pragma once

#include <string>

#include "rules/check.h"

namespace CLI {
class App;
}

namespace mg::cli {

struct CheckOutput {
  std::string report_dir;  // --report DIR: report.json, report.md, report.html
  bool json = false;       // --json: the report JSON on stdout instead of the summary
};

// Adds --report DIR and --json to `app`.
void add_check_output_options(CLI::App& app, CheckOutput& out);

// Checks the output paths (core/output_path.h); call before the work starts.
void prepare_check_output(const CheckOutput& out);

// Writes the reports (when asked), prints the summary or the report JSON and returns the exit
// code: kExitOk when every rule holds, kExitViolation otherwise.
int emit_check_result(const CheckResult& result, const CheckOutput& out);

}  // namespace mg::cli
