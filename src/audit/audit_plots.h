// The audit's two plots of one merge: the road in its own shape (the file's x, y:
// lane bounds, the ramp, every participant's path over the window) and the same in the
// curvilinear frame the rules judge in (X = s, Y across the road, lane lines at +-W/2).
#pragma once

#include <string>

#include "audit/recording_audit.h"

namespace mg {

std::string road_shape_svg(const RecordingAudit& a, const MergeAudit& m);
std::string curvilinear_svg(const MergeAudit& m);

}  // namespace mg
