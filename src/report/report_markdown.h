// The liability report as Markdown (report.md): verdict and liable party first, then per
// violation the rule, its paper reference, required and actual values, margin and time; the
// right of way over time; every rule's minimum margin; the timeline of events.
#pragma once

#include <string>

#include "rules/check.h"

namespace mg {

std::string report_markdown(const CheckResult& r);

// Shared by the Markdown and HTML reports: "12.345" or "-" for non-finite values.
std::string format_number(double v, int decimals = 3);

}  // namespace mg
