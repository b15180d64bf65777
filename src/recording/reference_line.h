// The road's reference line (docs/audit.md "Road"): a smooth polyline along a main
// lane's centre, resampled at a fixed spacing, smoothed, and extended straight beyond both ends so
// that every recorded position has a foot point. It defines the curvilinear (Frenet) frame the
// audit judges in: s along the line, d to its left (+d left, as the rules' +Y).
#pragma once

#include <vector>

#include "recording/commonroad_recording.h"

namespace mg {

struct FrenetPoint {
  double s_m = 0.0;  // arc length along the line; 0 at the start of the centreline it was made from
  double d_m = 0.0;  // signed distance, + left of the driving direction
};

// How far the line deviates from a straight road, for the report.
struct RoadShape {
  double length_m = 0.0;             // of the centreline, extensions excluded
  double max_offset_from_chord_m = 0.0;  // largest distance from the straight line joining its ends
  double heading_change_rad = 0.0;   // end heading minus start heading
  double max_abs_curvature_per_m = 0.0;
};

class ReferenceLine {
 public:
  // `centre`: >= 2 points in the driving direction. Resampled every `spacing_m`, smoothed by a
  // moving average over +-`smooth_points` samples (ends kept), extended by `extension_m` both ways.
  ReferenceLine(const std::vector<Point2>& centre, double spacing_m = 1.0, int smooth_points = 5,
                double extension_m = 500.0);

  FrenetPoint project(Point2 p) const;
  Point2 point_at(FrenetPoint f) const;
  double heading_at(double s_m) const;
  double curvature_at(double s_m) const;
  const RoadShape& shape() const { return shape_; }
  double start_s_m() const { return s_.front(); }
  double end_s_m() const { return s_.back(); }

 private:
  std::size_t segment_at(double s_m) const;
  std::vector<Point2> pts_;
  std::vector<double> s_;
  std::vector<double> heading_;    // of segment i (pts_[i] -> pts_[i+1])
  std::vector<double> curvature_;  // at point i
  RoadShape shape_;
};

// Pure helpers, tested on their own.
std::vector<Point2> resample_polyline(const std::vector<Point2>& pts, double spacing_m);
std::vector<Point2> smooth_polyline(const std::vector<Point2>& pts, int half_window);
double polyline_length_m(const std::vector<Point2>& pts);

}  // namespace mg
