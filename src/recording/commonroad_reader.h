// Reads a CommonRoad XML recording, versions 2018b and 2020a (docs/audit.md), and
// validates once, at the boundary, everything the audit relies on: a known version and time step,
// lanelets with bounds and no dangling references, dynamic obstacles with a rectangle shape and a
// trajectory of consecutive time steps (no gap, nothing going backwards), finite numbers inside
// physical bounds. Any defect is one mg::InputError line naming the file, the element with its
// id and the problem.
#pragma once

#include <string>
#include <string_view>

#include "recording/commonroad_recording.h"
#include "recording/xml_document.h"

namespace mg {

inline constexpr double kMaxRecordingCoordinateM = 1e6;
inline constexpr double kMaxRecordingSpeedMps = 150.0;
inline constexpr double kMaxRecordingAccelMps2 = 100.0;
inline constexpr int kMaxRecordingTimeSteps = 1'000'000;
inline constexpr int kMaxRecordingVehicles = 100'000;

Recording recording_from_xml(const XmlElement& root, const std::string& source);
Recording load_recording(const std::string& path);
// Parses XML text (the fuzz target's entry point); `source` names it in errors.
Recording parse_recording(std::string_view xml_text, const std::string& source);

}  // namespace mg
