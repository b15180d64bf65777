// The liability report as one self-contained HTML page (report.html): inline CSS and inline
// SVG, no external URL, opens offline. Verdict and liable party in the first lines; then per
// violation the rule, paper reference, required and actual values, margin and time; a top-down
// plot of the trajectories with vehicle boxes at the key moments; gap against D_lon over time;
// speeds; sideslip; all rules; the timeline. Plots use src/report/svg_plot.h.
#pragma once

#include <string>

#include "rules/check.h"

namespace mg {

std::string report_html(const CheckResult& r);

}  // namespace mg
