// A CommonRoad recording as the audit needs it: the lanelet network and the
// recorded vehicles, validated by commonroad_reader.h. Positions are the file's Cartesian
// coordinates (metres), times are whole time steps of `time_step_s`.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace mg {

struct Point2 {
  double x_m = 0.0;
  double y_m = 0.0;
};

struct Lanelet {
  int id = 0;
  std::vector<Point2> left_bound;   // >= 2 points, in the driving direction
  std::vector<Point2> right_bound;  // >= 2 points
  std::vector<int> predecessors;
  std::vector<int> successors;
  std::optional<int> adjacent_left;   // only neighbours driving the same way
  std::optional<int> adjacent_right;
  std::vector<std::string> types;     // laneletType values (2020a), may be empty
  std::optional<double> speed_limit_mps;
};

// One recorded state. A value the file gives as a set (a rectangle, circle or polygon for the
// position, an interval for a scalar) is read as its centre, and the state says so.
struct RecordedState {
  int time_step = 0;
  double x_m = 0.0;
  double y_m = 0.0;
  std::optional<double> orientation_rad;
  std::optional<double> speed_mps;
  std::optional<double> accel_mps2;
  bool set_valued = false;  // some value above is the centre of a set
};

struct RecordedVehicle {
  int id = 0;
  std::string type;          // "car", "truck", ... (CommonRoad obstacle type)
  double length_m = 4.8;
  double width_m = 1.9;
  std::vector<RecordedState> states;  // consecutive time steps, no gap
};

struct Recording {
  std::string source;        // the file
  std::string benchmark_id;
  std::string version;       // "2018b" or "2020a"
  double time_step_s = 0.1;
  std::vector<Lanelet> lanelets;
  std::vector<RecordedVehicle> vehicles;  // dynamic obstacles with a trajectory (may be none)
  int set_valued_states = 0;              // how many states were read from sets (their centres)
  int static_obstacles = 0;               // present in the file, not audited
  // The scenario's road attributes: 2018b's `tags` attribute, 2020a's <scenarioTags> elements
  // ("interstate", "highway", "urban", "intersection", ...), as written.
  std::vector<std::string> scenario_tags;

  const Lanelet* lanelet(int id) const;
};

}  // namespace mg
