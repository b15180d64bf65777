// The merges of a recording (docs/audit.md "Merges"): each vehicle's lane at every
// state from its lateral position (a main lane when its centre is within half a lane width of
// that lane's centre, else the ramp while the ramp lasts, else the nearest lane), with runs
// shorter than a minimum dropped as noise, and the changes between lanes. Moving from the ramp
// into the main lane it joins, or between adjacent main lanes, is a merge; a lanelet change along
// a lane is none (lanelets do not matter here, only lanes). A vehicle that halts on the ramp near
// its end without merging is audited too (Definition 1.3).
#pragma once

#include <string>
#include <vector>

#include "recording/frenet_track.h"
#include "recording/road_layout.h"

namespace mg {

inline constexpr int kRampLane = -1;  // lane index of the ramp; main lanes are 0, 1, ... outwards

enum class LaneChangeKind {
  kRampMerge,  // ramp -> main lane: Definition 1 with the ramp as side lane
  kCutIn,      // main lane -> adjacent main lane: Definition 1 with a side lane that does not end
  kIntoRamp,   // main lane -> ramp: found and listed, not audited (the target lane ends)
  kRampHalt,   // halted on the ramp near its end and never merged (Definition 1.3)
};
std::string to_string(LaneChangeKind k);

struct LaneChange {
  int vehicle_id = 0;
  LaneChangeKind kind = LaneChangeKind::kRampMerge;
  int from_lane = kRampLane, to_lane = 0;
  int time_step = 0;      // first step in the new lane (for a halt: the first halted step)
  double s_m = 0.0;
};

struct MergeFinderParams {
  int min_steps_in_lane = 5;        // shorter runs in a lane are noise
  double halted_speed_mps = 0.5;    // below this a vehicle is halted
  double halt_near_end_m = 50.0;    // a halt counts when within this of the ramp's end
};

// The lane at (s, d): kRampLane or a main lane index.
int lane_at(const RoadLayout& road, double s_m, double d_m);
// Each state's lane, runs shorter than min_steps replaced by the lane before them.
std::vector<int> lane_sequence(const FrenetTrack& t, const RoadLayout& road, int min_steps);
// Every lane change and ramp halt of every track, ordered by time then vehicle id.
std::vector<LaneChange> find_lane_changes(const std::vector<FrenetTrack>& tracks, const RoadLayout& road,
                                          const MergeFinderParams& p);

}  // namespace mg
