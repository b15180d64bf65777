#include "recording/trace_recording.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mg {
namespace {

// The road's centre line (main lane 0's centre) and its left normal at arc length s.
struct Bend {
  double radius_m = 0.0;  // 0: straight
  double x0_m = 0.0;      // the trace's X at the start of the map
  Point2 at(double x_m, double y_m) const {
    const double s = x_m - x0_m;
    if (radius_m <= 0.0) return {s, y_m};
    const double a = s / radius_m;
    return {radius_m * std::sin(a) - y_m * std::sin(a), radius_m * (1 - std::cos(a)) + y_m * std::cos(a)};
  }
  double heading(double x_m) const { return radius_m <= 0.0 ? 0.0 : (x_m - x0_m) / radius_m; }
  double scale(double y_m) const { return radius_m <= 0.0 ? 1.0 : 1.0 - y_m / radius_m; }  // ds along an offset line
};

std::vector<Point2> line(const Bend& b, double y_m, double from_x, double to_x) {
  std::vector<Point2> pts;
  const int n = std::max(2, static_cast<int>(std::ceil((to_x - from_x) / 2.0)) + 1);
  for (int i = 0; i < n; ++i) pts.push_back(b.at(from_x + (to_x - from_x) * i / (n - 1), y_m));
  return pts;
}

std::vector<Lanelet> lanelets(const Road& road, const Bend& b, double from_x, double to_x) {
  const double w = road.lane_width_m;
  std::vector<Lanelet> out;
  Lanelet ramp;
  ramp.id = 1;
  ramp.left_bound = line(b, -0.5 * w, std::max(from_x, road.side_lane_start_x_m), road.side_lane_end_x_m);
  ramp.right_bound = line(b, -1.5 * w, std::max(from_x, road.side_lane_start_x_m), road.side_lane_end_x_m);
  ramp.adjacent_left = 2;
  out.push_back(ramp);
  for (int k = 0; k < road.main_lanes; ++k) {
    Lanelet l;
    l.id = 2 + k;
    l.left_bound = line(b, (k + 0.5) * w, from_x, to_x);
    l.right_bound = line(b, (k - 0.5) * w, from_x, to_x);
    l.adjacent_right = k == 0 ? 1 : 1 + k;
    if (k + 1 < road.main_lanes) l.adjacent_left = 3 + k;
    out.push_back(l);
  }
  return out;
}

std::string type_for(const Limits& l, std::map<std::string, Limits>& types) {
  for (const auto& [type, limits] : types) {
    if (limits == l) return type;
  }
  static const char* kTypes[] = {"car", "truck", "bus", "motorcycle"};
  if (types.size() >= 4) throw std::invalid_argument("trace_to_recording: more than 4 different declared limits");
  const std::string type = kTypes[types.size()];
  types[type] = l;
  return type;
}

RecordedState recorded(const ObservedState& s, const Bend& b, int step) {
  RecordedState r;
  r.time_step = step;
  const Point2 p = b.at(s.x_m, s.y_m);
  r.x_m = p.x_m;
  r.y_m = p.y_m;
  r.orientation_rad = s.yaw_rad + b.heading(s.x_m);
  r.speed_mps = std::hypot(s.vx_mps * b.scale(s.y_m), s.vy_mps);
  r.accel_mps2 = s.accel_mps2;
  return r;
}

}  // namespace

TraceRecording trace_to_recording(const ObservedTrace& t, double bend_radius_m) {
  if (t.steps.size() < 2) throw std::invalid_argument("trace_to_recording: fewer than 2 steps");
  const double dt = t.steps[1].time_s - t.steps[0].time_s;
  double min_x = t.road.side_lane_start_x_m, max_x = t.road.side_lane_end_x_m;
  for (const ObservedStep& s : t.steps) {
    if (std::abs(s.time_s - t.steps[0].time_s - dt * std::round((s.time_s - t.steps[0].time_s) / dt)) > 1e-6) {
      throw std::invalid_argument("trace_to_recording: time steps are not evenly spaced");
    }
    for (const ObservedState& v : s.vehicles) min_x = std::min(min_x, v.x_m), max_x = std::max(max_x, v.x_m);
  }
  const Bend bend{bend_radius_m, min_x - 50.0};
  TraceRecording out;
  Recording& r = out.recording;
  r.benchmark_id = "MG_" + t.name;
  r.version = "2020a";
  r.time_step_s = dt;
  r.lanelets = lanelets(t.road, bend, min_x - 50.0, max_x + 50.0);
  for (std::size_t k = 0; k < t.vehicles.size(); ++k) {
    RecordedVehicle v;
    v.id = kTraceObstacleIdBase + t.vehicles[k].id;
    v.type = type_for(t.vehicles[k].limits, out.limits_by_type);
    v.length_m = t.vehicles[k].size.length_m;
    v.width_m = t.vehicles[k].size.width_m;
    for (std::size_t i = 0; i < t.steps.size(); ++i) v.states.push_back(recorded(t.steps[i].vehicles[k], bend, static_cast<int>(i)));
    r.vehicles.push_back(std::move(v));
  }
  return out;
}

}  // namespace mg
