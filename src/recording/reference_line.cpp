#include "recording/reference_line.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/demand.h"

namespace mg {
namespace {

double wrap_angle(double a) {
  while (a > std::numbers::pi) a -= 2 * std::numbers::pi;
  while (a < -std::numbers::pi) a += 2 * std::numbers::pi;
  return a;
}

RoadShape measure_shape(const std::vector<Point2>& c) {
  RoadShape r;
  r.length_m = polyline_length_m(c);
  const Point2 a = c.front(), b = c.back();
  const double cx = b.x_m - a.x_m, cy = b.y_m - a.y_m, cl = std::hypot(cx, cy);
  for (const Point2& p : c) {
    const double off = cl > 0 ? std::abs(cx * (p.y_m - a.y_m) - cy * (p.x_m - a.x_m)) / cl : 0.0;
    r.max_offset_from_chord_m = std::max(r.max_offset_from_chord_m, off);
  }
  const std::size_t n = c.size();
  const double h0 = std::atan2(c[1].y_m - c[0].y_m, c[1].x_m - c[0].x_m);
  const double h1 = std::atan2(c[n - 1].y_m - c[n - 2].y_m, c[n - 1].x_m - c[n - 2].x_m);
  r.heading_change_rad = wrap_angle(h1 - h0);
  return r;
}

}  // namespace

double polyline_length_m(const std::vector<Point2>& pts) {
  double len = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) len += std::hypot(pts[i].x_m - pts[i - 1].x_m, pts[i].y_m - pts[i - 1].y_m);
  return len;
}

std::vector<Point2> resample_polyline(const std::vector<Point2>& pts, double spacing_m) {
  const double total = polyline_length_m(pts);
  // The reader bounds coordinates and refuses bounds of zero length; a spacing of 0 or a count
  // beyond int would make the cast below undefined.
  MG_DEMAND(spacing_m > 0.0 && total / spacing_m < 1e9);
  // The small allowance keeps an exact multiple from rounding up to one sample more.
  const int n = std::max(2, static_cast<int>(std::ceil(total / spacing_m - 1e-9)) + 1);
  std::vector<Point2> out;
  out.reserve(n);
  std::size_t seg = 0;
  double seg_start = 0.0;
  for (int k = 0; k < n; ++k) {
    const double target = total * k / (n - 1);
    while (seg + 2 < pts.size()) {
      const double len = std::hypot(pts[seg + 1].x_m - pts[seg].x_m, pts[seg + 1].y_m - pts[seg].y_m);
      if (seg_start + len >= target) break;
      seg_start += len;
      ++seg;
    }
    const double len = std::hypot(pts[seg + 1].x_m - pts[seg].x_m, pts[seg + 1].y_m - pts[seg].y_m);
    const double t = len > 0 ? std::clamp((target - seg_start) / len, 0.0, 1.0) : 0.0;
    out.push_back({pts[seg].x_m + t * (pts[seg + 1].x_m - pts[seg].x_m), pts[seg].y_m + t * (pts[seg + 1].y_m - pts[seg].y_m)});
  }
  return out;
}

// The window shrinks near the ends so that the line keeps its end points (its extent).
std::vector<Point2> smooth_polyline(const std::vector<Point2>& pts, int half_window) {
  const int n = static_cast<int>(pts.size());
  std::vector<Point2> out(pts.size());
  for (int i = 0; i < n; ++i) {
    const int h = std::min({half_window, i, n - 1 - i});
    double x = 0, y = 0;
    for (int j = i - h; j <= i + h; ++j) {
      x += pts[j].x_m;
      y += pts[j].y_m;
    }
    out[i] = {x / (2 * h + 1), y / (2 * h + 1)};
  }
  return out;
}

ReferenceLine::ReferenceLine(const std::vector<Point2>& centre, double spacing_m, int smooth_points, double extension_m) {
  if (centre.size() < 2 || polyline_length_m(centre) < spacing_m) throw std::invalid_argument("reference line: too short");
  std::vector<Point2> c = smooth_polyline(resample_polyline(centre, spacing_m), smooth_points);
  shape_ = measure_shape(c);
  const std::size_t n = c.size();
  const double h0 = std::atan2(c[1].y_m - c[0].y_m, c[1].x_m - c[0].x_m);
  const double h1 = std::atan2(c[n - 1].y_m - c[n - 2].y_m, c[n - 1].x_m - c[n - 2].x_m);
  pts_.push_back({c[0].x_m - extension_m * std::cos(h0), c[0].y_m - extension_m * std::sin(h0)});
  pts_.insert(pts_.end(), c.begin(), c.end());
  pts_.push_back({c[n - 1].x_m + extension_m * std::cos(h1), c[n - 1].y_m + extension_m * std::sin(h1)});
  s_.push_back(-extension_m);
  for (std::size_t i = 1; i < pts_.size(); ++i) {
    s_.push_back(s_.back() + std::hypot(pts_[i].x_m - pts_[i - 1].x_m, pts_[i].y_m - pts_[i - 1].y_m));
    heading_.push_back(std::atan2(pts_[i].y_m - pts_[i - 1].y_m, pts_[i].x_m - pts_[i - 1].x_m));
  }
  // Curvature over a baseline of +-kCurvatureBase segments: the change of heading between single
  // segments of a polyline drawn from coarse lanelet points is mostly the kinks of the drawing.
  constexpr std::size_t kCurvatureBase = 5;
  curvature_.assign(pts_.size(), 0.0);
  for (std::size_t i = 1; i + 1 < pts_.size(); ++i) {
    const std::size_t a = i > kCurvatureBase ? i - kCurvatureBase : 0;
    const std::size_t b = std::min(heading_.size() - 1, i + kCurvatureBase - 1);
    const double ds = 0.5 * (s_[b + 1] + s_[b]) - 0.5 * (s_[a + 1] + s_[a]);
    curvature_[i] = ds > 0 ? wrap_angle(heading_[b] - heading_[a]) / ds : 0.0;
    shape_.max_abs_curvature_per_m = std::max(shape_.max_abs_curvature_per_m, std::abs(curvature_[i]));
  }
}

FrenetPoint ReferenceLine::project(Point2 p) const {
  double best = std::numeric_limits<double>::infinity();
  FrenetPoint f;
  for (std::size_t i = 0; i + 1 < pts_.size(); ++i) {
    const double ex = pts_[i + 1].x_m - pts_[i].x_m, ey = pts_[i + 1].y_m - pts_[i].y_m;
    const double len2 = ex * ex + ey * ey;
    const double px = p.x_m - pts_[i].x_m, py = p.y_m - pts_[i].y_m;
    const double t = len2 > 0 ? std::clamp((px * ex + py * ey) / len2, 0.0, 1.0) : 0.0;
    const double qx = px - t * ex, qy = py - t * ey;
    const double dist2 = qx * qx + qy * qy;
    if (dist2 < best) {
      best = dist2;
      const double len = std::sqrt(len2);
      f.s_m = s_[i] + t * len;
      // Signed by the side of the segment: + left of the driving direction.
      const double cross = len > 0 ? (ex * py - ey * px) / len : 0.0;
      f.d_m = (cross >= 0 ? 1.0 : -1.0) * std::sqrt(dist2);
    }
  }
  return f;
}

std::size_t ReferenceLine::segment_at(double s_m) const {
  const auto it = std::upper_bound(s_.begin(), s_.end(), s_m);
  const std::size_t i = it == s_.begin() ? 0 : static_cast<std::size_t>(it - s_.begin()) - 1;
  return std::min(i, heading_.size() - 1);
}

Point2 ReferenceLine::point_at(FrenetPoint f) const {
  const std::size_t i = segment_at(f.s_m);
  const double h = heading_[i];
  const double along = f.s_m - s_[i];
  return {pts_[i].x_m + along * std::cos(h) - f.d_m * std::sin(h), pts_[i].y_m + along * std::sin(h) + f.d_m * std::cos(h)};
}

double ReferenceLine::heading_at(double s_m) const { return heading_[segment_at(s_m)]; }

double ReferenceLine::curvature_at(double s_m) const { return curvature_[segment_at(s_m)]; }

}  // namespace mg
