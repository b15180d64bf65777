// A simulated run's observable trace as a recording (the round trip): the trace's road
// laid out along a straight line or a circular arc of the given radius (its X the arc length, its
// Y the offset to the left), lanelets for the side lane (typed nothing: the audit must find it by
// topology) and each main lane, and every vehicle's states at the trace's steps (positions,
// headings, speeds and accelerations as a recorder would write them). Vehicle k of the trace is
// obstacle kTraceObstacleIdBase + k; vehicles with different declared limits get different
// obstacle types (car, truck, bus, motorcycle, in order of first appearance), so that an audit
// profile can give each its limits back (at most 4 different sets).
#pragma once

#include <map>
#include <string>

#include "core/observed_trace.h"
#include "recording/commonroad_recording.h"

namespace mg {

inline constexpr int kTraceObstacleIdBase = 1000;

struct TraceRecording {
  Recording recording;
  std::map<std::string, Limits> limits_by_type;  // the declared limits each obstacle type stands for
};

// `bend_radius_m` 0: a straight road; otherwise an arc turning left with this radius (>= 50 m).
// Raises std::invalid_argument when the trace's vehicles declare more than 4 different limits or
// its time steps are not evenly spaced.
TraceRecording trace_to_recording(const ObservedTrace& t, double bend_radius_m);

}  // namespace mg
