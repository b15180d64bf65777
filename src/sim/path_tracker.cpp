#include "sim/path_tracker.h"

#include <algorithm>
#include <cmath>

#include "core/demand.h"
#include "sim/single_track.h"

namespace mg {
namespace {

double wrap_angle(double a) { return std::remainder(a, 2.0 * M_PI); }

// Along a straight stretch parallel to X (the side lane's or a main lane's centre), where most of
// an episode is driven, these are exact without the libm calls: hypot(x, 0) = |x| and
// atan2(0, x) = 0 for x > 0 (C Annex F).
double segment_length(const PathPoint& a, const PathPoint& b) {
  const double dx = b.x_m - a.x_m, dy = b.y_m - a.y_m;
  return dy == 0.0 ? std::abs(dx) : std::hypot(dx, dy);
}

// The point at signed arc distance ds from parameter t of segment i, walking along the
// polyline; beyond an end, the end segment extends straight.
PathPoint point_along(const std::vector<PathPoint>& p, std::size_t i, double t, double ds) {
  double seg_len = segment_length(p[i], p[i + 1]);
  double at = t * seg_len + ds;  // arc position within segment i
  while (at > seg_len && i + 2 < p.size()) {
    at -= seg_len;
    ++i;
    seg_len = segment_length(p[i], p[i + 1]);
  }
  while (at < 0.0 && i > 0) {
    --i;
    seg_len = segment_length(p[i], p[i + 1]);
    at += seg_len;
  }
  const double u = seg_len > 0.0 ? at / seg_len : 0.0;
  return {p[i].x_m + u * (p[i + 1].x_m - p[i].x_m), p[i].y_m + u * (p[i + 1].y_m - p[i].y_m)};
}

double chord_heading(const PathPoint& a, const PathPoint& b) {
  const double dx = b.x_m - a.x_m, dy = b.y_m - a.y_m;
  return dy == 0.0 && dx > 0.0 ? dy : std::atan2(dy, dx);
}

}  // namespace

PathProjection project_on_path(const std::vector<PathPoint>& path, double x_m, double y_m, double preview_m) {
  MG_DEMAND(path.size() >= 2 && preview_m > 0.0);
  // The segment whose X range holds x_m, then its neighbours, by perpendicular distance.
  auto it = std::upper_bound(path.begin(), path.end(), x_m, [](double x, const PathPoint& p) { return x < p.x_m; });
  const std::size_t last_seg = path.size() - 2;
  const std::size_t guess = std::min<std::size_t>(it == path.begin() ? 0 : (it - path.begin()) - 1, last_seg);
  const std::size_t lo = guess >= 3 ? guess - 3 : 0;
  const std::size_t hi = std::min(last_seg, guess + 3);
  double best_d2 = INFINITY, best_t = 0.0;
  std::size_t best_i = guess;
  PathProjection best;
  for (std::size_t i = lo; i <= hi; ++i) {
    const double ax = path[i].x_m, ay = path[i].y_m;
    const double dx = path[i + 1].x_m - ax, dy = path[i + 1].y_m - ay;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0.0 ? ((x_m - ax) * dx + (y_m - ay) * dy) / len2 : 0.0;
    if (i > 0) t = std::max(t, 0.0);
    if (i < last_seg) t = std::min(t, 1.0);
    const double px = ax + t * dx, py = ay + t * dy;
    const double d2 = (x_m - px) * (x_m - px) + (y_m - py) * (y_m - py);
    if (d2 < best_d2) {
      best_d2 = d2;
      best_i = i;
      best_t = t;
      const double len = std::sqrt(len2);
      // Cross product sign: positive when the point is left of the segment direction.
      best.cross_track_m = len > 0.0 ? (dx * (y_m - ay) - dy * (x_m - ax)) / len : 0.0;
    }
  }
  const PathPoint back = point_along(path, best_i, best_t, -preview_m);
  const PathPoint here = point_along(path, best_i, best_t, 0.0);
  const PathPoint ahead = point_along(path, best_i, best_t, preview_m);
  best.heading_rad = chord_heading(back, ahead);
  best.curvature_per_m = wrap_angle(chord_heading(here, ahead) - chord_heading(back, here)) / preview_m;
  return best;
}

double stanley_steering_rad(const std::vector<PathPoint>& path, const VehicleState& ego, const EgoDynamics& d,
                            const PathTrackerGains& gains, const SteeringEnvelope& envelope) {
  const bool along_x = ego.yaw_rad == 0.0;  // cos and sin exactly 1 and 0
  const double front_x = ego.x_m + d.cg_to_front_m * (along_x ? 1.0 : std::cos(ego.yaw_rad));
  const double front_y = ego.y_m + d.cg_to_front_m * (along_x ? ego.yaw_rad : std::sin(ego.yaw_rad));
  const double speed = std::max(ego.vx_mps, 0.0);
  const double preview = std::max(gains.preview_min_m, gains.preview_time_s * speed);
  const PathProjection proj = project_on_path(path, front_x, front_y, preview);
  const double heading_error = wrap_angle(proj.heading_rad - ego.yaw_rad);
  const double cross_pull = -gains.cross_track_gain * proj.cross_track_m;
  const double cross_term = cross_pull == 0.0 ? cross_pull : std::atan2(cross_pull, gains.softening_mps + speed);
  const double path_yaw_rate = speed * proj.curvature_per_m;
  // Feed-forward: the steady-state steering of the linear single-track model for the path's
  // curvature, delta = kappa (L + K v^2).
  const double feed_forward = proj.curvature_per_m * (d.wheelbase_m() + understeer_gradient(d) * speed * speed);
  const double request =
      feed_forward + heading_error + cross_term + gains.yaw_rate_damping_s * (path_yaw_rate - ego.yaw_rate_radps);
  double cap_rad = std::atan(std::tan(gains.sideslip_max_rad) * d.wheelbase_m() / d.cg_to_rear_m);
  // The body's speed rises by up to kSpeedGainMargin times the commanded acceleration: the
  // single-track model's v_x' = a + r v_y adds the yaw-rate coupling of a turning ego.
  constexpr double kSpeedGainMargin = 1.25;
  const double gain_mps2 = kSpeedGainMargin * envelope.accel_max_mps2;
  const double next_speed = speed + gain_mps2 * envelope.step_s;
  if (next_speed < envelope.sideslip_judged_from_mps && gain_mps2 > 0.0)
    cap_rad = std::min(d.steer_max_rad,
                       cap_rad + d.steer_rate_max_radps * (envelope.sideslip_judged_from_mps - next_speed) / gain_mps2);
  return std::clamp(request, -cap_rad, cap_rad);
}

std::vector<PathPoint> straight_path(double x_m, double y_m) {
  return {{x_m - 1000.0, y_m}, {x_m + 1000.0, y_m}};
}

}  // namespace mg
