// The liability report as JSON (report.json; structure documented in docs/rules.md) and the
// writer of the three report files (report.json, report.md, report.html) into a directory.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "rules/check.h"

namespace mg {

// check_result_to_json plus the trace's name and source.
nlohmann::json report_json(const CheckResult& r);

// Writes DIR/report.json, DIR/report.md and DIR/report.html, each atomically.
void write_check_reports(const std::string& dir, const CheckResult& r);

}  // namespace mg
