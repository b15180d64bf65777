#include "recording/frenet_track.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mg {
namespace {

double wrap(double a) {
  while (a > std::numbers::pi) a -= 2 * std::numbers::pi;
  while (a < -std::numbers::pi) a += 2 * std::numbers::pi;
  return a;
}

}  // namespace

const TrackState* FrenetTrack::at_step(int time_step) const {
  if (states.empty()) return nullptr;
  const long i = static_cast<long>(time_step) - states.front().time_step;
  if (i < 0 || i >= static_cast<long>(states.size())) return nullptr;
  return &states[static_cast<std::size_t>(i)];
}

double local_slope(const std::vector<double>& y, double dt, std::size_t i, int half_window) {
  const long n = static_cast<long>(y.size());
  const long lo = std::max(0L, static_cast<long>(i) - half_window);
  const long hi = std::min(n - 1, static_cast<long>(i) + half_window);
  if (hi <= lo) return 0.0;
  double mt = 0, my = 0;
  for (long k = lo; k <= hi; ++k) mt += k, my += y[k];
  mt /= (hi - lo + 1), my /= (hi - lo + 1);
  double num = 0, den = 0;
  for (long k = lo; k <= hi; ++k) num += (k - mt) * (y[k] - my), den += (k - mt) * (k - mt);
  return num / den / dt;
}

FrenetTrack project_track(const RecordedVehicle& v, const ReferenceLine& ref, double dt, int half_window) {
  FrenetTrack t{v.id, v.type, v.length_m, v.width_m, {}, false, false, false};
  std::vector<double> s, d;
  for (const RecordedState& r : v.states) {
    const FrenetPoint f = ref.project({r.x_m, r.y_m});
    s.push_back(f.s_m);
    d.push_back(f.d_m);
  }
  std::vector<double> vs(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const RecordedState& r = v.states[i];
    TrackState ts;
    ts.time_step = r.time_step;
    ts.s_m = s[i];
    ts.d_m = d[i];
    ts.vd_mps = local_slope(d, dt, i, half_window);
    const double ds_fit = local_slope(s, dt, i, half_window);
    const double theta = ref.heading_at(s[i]);
    if (r.orientation_rad) {
      ts.yaw_rad = wrap(*r.orientation_rad - theta);
    } else {
      ts.yaw_rad = std::atan2(ts.vd_mps, ds_fit);
      t.yaw_from_motion = true;
    }
    if (r.speed_mps) {
      // Along a curve ds/dt = v cos(yaw) / (1 - kappa d): the foot point moves slower than a
      // vehicle outside the bend.
      const double scale = 1.0 - ref.curvature_at(s[i]) * d[i];
      ts.vs_mps = *r.speed_mps * std::cos(ts.yaw_rad) / (std::abs(scale) > 0.2 ? scale : 1.0);
      ts.speed_mps = *r.speed_mps;
    } else {
      ts.vs_mps = ds_fit;
      ts.speed_mps = std::hypot(ds_fit, ts.vd_mps);
      t.speed_from_positions = true;
    }
    vs[i] = ts.vs_mps;
    t.states.push_back(ts);
  }
  for (std::size_t i = 0; i < t.states.size(); ++i) {
    if (v.states[i].accel_mps2) {
      t.states[i].accel_mps2 = *v.states[i].accel_mps2;
    } else {
      t.states[i].accel_mps2 = local_slope(vs, dt, i, half_window);
      t.accel_from_speeds = true;
    }
  }
  return t;
}

}  // namespace mg
