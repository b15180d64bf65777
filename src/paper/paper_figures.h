// The paper report's figures (RCPP paper §IV, Fig. 4 and 5) and the right-of-way timeline, as
// SVG, drawn from a PaperExperiment (paper/paper_report.h).
#pragma once

#include <string>

#include "paper/paper_report.h"

namespace mg {

// How a planner is drawn and named in the figures and the report's text.
struct PlannerStyle {
  const char* colour;
  const char* dash;
  const char* label;
};
PlannerStyle planner_style(const std::string& planner);

std::string fig4_paths_svg(const PaperExperiment& e);
std::string fig5_motion_svg(const PaperExperiment& e);
// One strip per planner: who held the right of way over its run, the merge shaded.
std::string right_of_way_svg(const PaperExperiment& e);

}  // namespace mg
