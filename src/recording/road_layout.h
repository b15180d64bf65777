// The road of a recording (docs/audit.md "Road"): the lanelet network's lanes (chains
// of lanelets along their successors), the main carriageway and the on-ramp, found by
// laneletType (mainCarriageWay, accessRamp) where the file has them and otherwise from the
// topology, and the reference line along the main lane the ramp joins, in whose Frenet frame
// every lane's centre is known as a function of s.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "recording/commonroad_recording.h"
#include "recording/reference_line.h"

namespace mg {

struct Lane {
  std::vector<int> lanelet_ids;        // along the driving direction
  std::vector<Point2> centre;          // world frame
  std::vector<Point2> left_bound, right_bound;
  std::vector<FrenetPoint> centre_sd;  // the centre in the Frenet frame, by increasing s
  double start_s_m = 0.0, end_s_m = 0.0;
  double mean_width_m = 0.0;

  // The centre's d at s, interpolated (held beyond the lane's ends).
  double centre_d_at(double s_m) const;
  bool covers(double s_m, double margin_m = 0.0) const { return s_m >= start_s_m - margin_m && s_m <= end_s_m + margin_m; }
  std::string name() const;  // "lanelets 12-13"
};

inline constexpr double kMaxLaneLengthM = 20000.0;  // longer lanes are refused (work bound)

enum class RampSide { kRight, kLeft };  // the side of the main carriageway the ramp is on

struct RoadLayout {
  ReferenceLine reference;
  std::vector<Lane> main_lanes;  // ordered from the ramp side outwards
  Lane ramp;
  RampSide ramp_side = RampSide::kRight;
  double lane_width_m = 3.5;     // mean width of the main lanes
  double ramp_end_s_m = 0.0;     // where the ramp ends, along the reference line
  double speed_limit_mps = 0.0;  // from the lanelets, 0 when none is given
  std::string found_by;          // how the ramp was identified, for the report
  // Whether the join is a highway on-ramp (classify_join) and what says so: only then are its
  // merges audited as ramp merges (an urban junction's join is not, docs/audit.md "The road").
  bool highway_on_ramp = true;
  std::string on_ramp_basis;
};

// What makes a lane join a highway on-ramp, in this order: the lanelet types (accessRamp,
// highway, interstate or mainCarriageWay on the ramp or the lane it joins: yes; intersection on
// the ramp: no), the scenario's road attributes (2018b tags, 2020a scenarioTags: interstate or
// highway), else the geometry and speed limits of a ramp: running beside the main lane for at
// least kRampMinAlongsideM before it ends, and no speed limit below kRampMinSpeedLimitMps.
inline constexpr double kRampMinAlongsideM = 30.0;
inline constexpr double kRampMinSpeedLimitMps = 60.0 / 3.6;

// The road around the ramp, or nullopt when no lane joins or runs beside another (none of the
// three readings of docs/audit.md "The road" finds a ramp): no vehicle of such a recording can
// merge or change lanes, so it has nothing to audit. Raises InputError (file, lanelet, problem)
// when the lanes are unusable.
std::optional<RoadLayout> find_road_layout(const Recording& r);
// As find_road_layout, raising InputError "no ramp found" where it finds none.
RoadLayout build_road_layout(const Recording& r);

// The centre line of a lanelet: its bounds resampled to a common count and averaged.
std::vector<Point2> lanelet_centre(const Lanelet& l);

}  // namespace mg
