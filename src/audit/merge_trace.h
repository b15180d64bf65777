// One merge of a recording as an observable trace (docs/audit.md "From a merge to a
// trace"): the merging vehicle is the ego (id 0), the lane it leaves is the side lane and the
// lane it enters the main lane, in the curvilinear frame of the road: X = s along the reference
// line, Y across it measured from the target lane's centre (scaled so that the side lane's centre
// is at -W where the two lanes are more than a lane apart, mirrored when the ego moves right).
// The side lane ends at the ramp's end for a ramp merge and beyond the recording for a cut-in.
// Every other vehicle recorded throughout the window, in either lane and within range, takes
// part; those recorded only for part of it are named as left out.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "audit/audit_profile.h"
#include "core/observed_trace.h"
#include "recording/commonroad_recording.h"
#include "recording/frenet_track.h"
#include "recording/merge_finder.h"
#include "recording/road_layout.h"

namespace mg {

// Everything the audit derived from the recording, shared by the merges.
struct RecordingView {
  const Recording* recording = nullptr;
  const RoadLayout* road = nullptr;
  std::vector<FrenetTrack> tracks;      // one per recorded vehicle, recording order
  std::vector<std::vector<int>> lanes;  // lane_sequence of each track
  std::vector<LaneChange> changes;
};

RecordingView view_recording(const Recording& r, const RoadLayout& road, const AuditProfile& p);

// What puts the window's first step where it is: the audit's own window (window_before_s), the
// ego's previous lane change, or the recording (its first instant, or the record of the ego or
// of a participant): only the last is a limit of what was observed (censoring, docs/audit.md).
struct WindowStart {
  bool recording_limit = false;
  std::string why;  // "the recording's first instant", "the record of vehicle 375 (from 1.2 s)", ...
};

// A vehicle near the ego recorded for only part of the window (left out of the trace).
struct PartialRecord {
  int vehicle_id = 0;
  int first_step = 0, last_step = 0;
};

struct MergeTrace {
  LaneChange change;
  int first_step = 0, last_step = 0;   // the window, in recording time steps
  WindowStart window_start;
  std::vector<PartialRecord> partial;  // the left-out vehicles recorded for part of the window
  // Vehicles on the ramp entering the lane this cut-in enters (R_I5): placed in that lane, as
  // the lane they are entering, so that the lane change is judged toward them.
  std::vector<int> entering_ids;
  std::vector<int> recording_ids;      // trace vehicle i -> CommonRoad obstacle id ([0] the ego)
  std::vector<std::string> types;      // trace vehicle i -> CommonRoad obstacle type (its profile class)
  std::vector<std::string> left_out;   // others near the ego but not recorded throughout
  std::vector<std::string> notes;      // what the reader should know (sets, derived speeds ...)
  ObservedTrace trace;
};

// Trace Y of a point at (s, d) for a merge from lane `origin` into lane `target`.
double merge_frame_y(const RoadLayout& road, int origin, int target, double s_m, double d_m);

// The merge's trace judged with another profile's response time and class limits.
ObservedTrace with_profile(const MergeTrace& m, const AuditProfile& p);

// `earliest_step`: a window reaching back at least to this step where the records allow (the
// audit widens it to hold a merge's decision window).
MergeTrace build_merge_trace(const RecordingView& v, const LaneChange& c, const AuditProfile& p,
                             std::optional<int> earliest_step = std::nullopt);

// The vehicles of the recording on the ramp at the cut-in's step that later merge from the ramp
// into the lane the cut-in enters (R_I5's "entering vehicles"); none unless the cut-in enters
// the lane the ramp joins of a highway on-ramp.
std::vector<std::size_t> entering_vehicles(const RecordingView& v, const LaneChange& c);

}  // namespace mg
