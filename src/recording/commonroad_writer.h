// Writes a Recording as CommonRoad 2020a XML: the inverse of commonroad_reader.h for
// everything the audit reads (lanelets with bounds, neighbours and successors; dynamic obstacles
// with a rectangle, an initial state and a trajectory of exact states). The round trip of a
// simulated run through a recording (trace_recording.h) uses it.
#pragma once

#include <string>

#include "recording/commonroad_recording.h"

namespace mg {

std::string recording_to_xml(const Recording& r);

}  // namespace mg
