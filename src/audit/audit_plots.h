// The audit's plots: of one merge, the road in its own shape (the file's x, y: lane bounds, the
// ramp, every participant's path over the window), the same in the curvilinear frame the rules
// judge in (X = s, Y across the road, lane lines at +-W/2) and its compliance frontier; of a
// dataset, the distribution of the frontiers.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "audit/recording_audit.h"

namespace mg {

std::string road_shape_svg(const RecordingAudit& a, const MergeAudit& m);
std::string curvilinear_svg(const MergeAudit& m);
// The sensitivity sweep (every (rho, brake scale) judged: holds or violated) with the compliance
// frontier through it: the largest rho that holds at each brake scale, and the profile's rho.
std::string frontier_svg(const MergeAudit& m);
// The distribution of the judged merges' frontier values (largest rho that holds), 0.25 s bins
// over [0, 5] s; merges violated even at rho = 0 and those holding throughout get a bin each.
std::string frontier_histogram_svg(const std::vector<std::optional<double>>& max_response_times_s, const std::vector<bool>& throughout);

}  // namespace mg
