// The liability report as JSON (report.json; structure documented in docs/rules.md) and the
// writer of the three report files (report.json, report.md, report.html) into a directory.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/scenario.h"
#include "rules/check.h"

namespace mg {

// check_result_to_json plus the scenario's name and description.
nlohmann::json report_json(const Scenario& s, const CheckResult& r);

// Writes DIR/report.json, DIR/report.md and DIR/report.html, each atomically.
void write_check_reports(const std::string& dir, const Scenario& s, const CheckResult& r);

}  // namespace mg
