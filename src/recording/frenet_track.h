// A recorded vehicle in the road's curvilinear frame (docs/audit.md "Frenet
// projection" and "Smoothing"): positions projected onto the reference line, speeds and
// accelerations from the recorded states where the file gives them, and otherwise from the
// positions by a least-squares slope over a short window (local_slope).
#pragma once

#include <string>
#include <vector>

#include "recording/commonroad_recording.h"
#include "recording/reference_line.h"

namespace mg {

struct TrackState {
  int time_step = 0;
  double s_m = 0.0, d_m = 0.0;
  double vs_mps = 0.0;      // ds/dt
  double vd_mps = 0.0;      // dd/dt
  double accel_mps2 = 0.0;  // longitudinal
  double yaw_rad = 0.0;     // heading relative to the reference line at s
  double speed_mps = 0.0;   // |velocity|, recorded or derived
};

struct FrenetTrack {
  int vehicle_id = 0;
  std::string type;
  double length_m = 0.0, width_m = 0.0;
  std::vector<TrackState> states;  // consecutive time steps
  bool speed_from_positions = false;  // the file gave no velocity: derived (smoothed)
  bool accel_from_speeds = false;     // the file gave no acceleration: derived (smoothed)
  bool yaw_from_motion = false;       // the file gave no orientation: the direction of motion

  const TrackState* at_step(int time_step) const;
};

// Least-squares slope of y over samples [i - h, i + h] (clipped to the series), spaced dt apart:
// the derivative of a line fitted to the window. A series of one sample has slope 0.
double local_slope(const std::vector<double>& y, double dt, std::size_t i, int half_window);

FrenetTrack project_track(const RecordedVehicle& v, const ReferenceLine& ref, double time_step_s, int half_window);

}  // namespace mg
