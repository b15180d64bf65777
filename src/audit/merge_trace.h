// One merge of a recording as an observable trace (docs/audit.md "From a merge to a
// trace"): the merging vehicle is the ego (id 0), the lane it leaves is the side lane and the
// lane it enters the main lane, in the curvilinear frame of the road: X = s along the reference
// line, Y across it measured from the target lane's centre (scaled so that the side lane's centre
// is at -W where the two lanes are more than a lane apart, mirrored when the ego moves right).
// The side lane ends at the ramp's end for a ramp merge and beyond the recording for a cut-in.
// Every other vehicle recorded throughout the window, in either lane and within range, takes
// part; those recorded only for part of it are named as left out.
#pragma once

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

struct MergeTrace {
  LaneChange change;
  int first_step = 0, last_step = 0;   // the window, in recording time steps
  std::vector<int> recording_ids;      // trace vehicle i -> CommonRoad obstacle id ([0] the ego)
  std::vector<std::string> left_out;   // others near the ego but not recorded throughout
  std::vector<std::string> notes;      // what the reader should know (sets, derived speeds ...)
  ObservedTrace trace;
};

// Trace Y of a point at (s, d) for a merge from lane `origin` into lane `target`.
double merge_frame_y(const RoadLayout& road, int origin, int target, double s_m, double d_m);

MergeTrace build_merge_trace(const RecordingView& v, const LaneChange& c, const AuditProfile& p);

}  // namespace mg
