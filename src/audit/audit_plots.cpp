#include "audit/audit_plots.h"

#include <algorithm>
#include <cmath>

#include "report/svg_plot.h"

namespace mg {
namespace {

svg::Series polyline(const std::vector<Point2>& pts, const std::string& label, const std::string& colour, const std::string& dash) {
  svg::Series s;
  s.label = label;
  s.colour = colour;
  s.dash = dash;
  s.width_px = 1.0;
  for (const Point2& p : pts) s.x.push_back(p.x_m), s.y.push_back(p.y_m);
  return s;
}

std::string colour_of(std::size_t i) {
  static const char* kColours[] = {"#1f77b4", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return i == 0 ? "#d62728" : kColours[(i - 1) % 8];
}

// Equal scales on both axes, so that the road keeps its shape.
void equal_aspect(svg::Plot& p) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const svg::Series& s : p.series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]), y0 = std::min(y0, s.y[i]), y1 = std::max(y1, s.y[i]);
  }
  const double ratio = static_cast<double>(p.height_px) / p.width_px;
  double w = x1 - x0, h = y1 - y0;
  if (h / std::max(w, 1e-9) > ratio) w = h / ratio; else h = w * ratio;
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  p.x_range = svg::Range{cx - 0.55 * w, cx + 0.55 * w};
  p.y_range = svg::Range{cy - 0.55 * h, cy + 0.55 * h};
}

}  // namespace

std::string road_shape_svg(const RecordingAudit& a, const MergeAudit& m) {
  svg::Plot p = svg::frame("The road in its own shape (file x, y), paths over the window", "x [m]", "y [m]", 720, 480);
  for (std::size_t k = 0; k < a.road->main_lanes.size(); ++k) {
    const Lane& l = a.road->main_lanes[k];
    p.series.push_back(polyline(l.left_bound, k == 0 ? "main lanes" : "", "#999999", ""));
    p.series.push_back(polyline(l.right_bound, "", "#999999", ""));
  }
  p.series.push_back(polyline(a.road->ramp.left_bound, "ramp", "#ff7f0e", "5 3"));
  p.series.push_back(polyline(a.road->ramp.right_bound, "", "#ff7f0e", "5 3"));
  for (std::size_t i = 0; i < m.merge.recording_ids.size(); ++i) {
    const RecordedVehicle* v = nullptr;
    for (const RecordedVehicle& rv : a.recording->vehicles) {
      if (rv.id == m.merge.recording_ids[i]) v = &rv;
    }
    std::vector<Point2> path;
    for (const RecordedState& s : v->states) {
      if (s.time_step >= m.merge.first_step && s.time_step <= m.merge.last_step) path.push_back({s.x_m, s.y_m});
    }
    svg::Series s = polyline(path, (i == 0 ? "ego " : "") + std::to_string(m.merge.recording_ids[i]), colour_of(i), "");
    s.width_px = i == 0 ? 2.4 : 1.6;
    p.series.push_back(s);
  }
  equal_aspect(p);
  return svg::render(p);
}

std::string curvilinear_svg(const MergeAudit& m) {
  svg::Plot p = svg::frame("Curvilinear frame (judged): target lane at Y = 0, side lane at Y = -W", "X = s along the reference line [m]", "Y across the road [m]", 720, 360);
  const ObservedTrace& t = m.merge.trace;
  double x0 = 1e300, x1 = -1e300;
  for (std::size_t i = 0; i < t.vehicles.size(); ++i) {
    svg::Series s;
    s.label = (i == 0 ? "ego " : "") + std::to_string(m.merge.recording_ids[i]);
    s.colour = colour_of(i);
    s.width_px = i == 0 ? 2.4 : 1.6;
    for (const ObservedStep& st : t.steps) {
      s.x.push_back(st.vehicles[i].x_m), s.y.push_back(st.vehicles[i].y_m);
      x0 = std::min(x0, st.vehicles[i].x_m), x1 = std::max(x1, st.vehicles[i].x_m);
    }
    p.series.push_back(s);
  }
  const double w = t.road.lane_width_m;
  for (const double y : {-1.5 * w, -0.5 * w, 0.5 * w}) {
    svg::Series line;
    line.label = y == -0.5 * w ? "lane lines" : "";
    line.colour = "#999999";
    line.dash = "4 3";
    line.width_px = 1.0;
    line.x = {x0, std::min(x1, t.road.side_lane_end_x_m)};
    line.y = {y, y};
    if (y == -1.5 * w || y == -0.5 * w) p.series.push_back(line);
    if (y == 0.5 * w) line.x = {x0, x1}, p.series.push_back(line);
  }
  if (t.road.side_lane_end_x_m <= x1 + 1.0) {
    p.bands.push_back({t.road.side_lane_end_x_m, t.road.side_lane_end_x_m + 0.5, "side lane ends", "#f4b183", svg::Range{-1.5 * w, -0.5 * w}});
  }
  p.legend = svg::LegendCorner::kBottomRight;
  return svg::render(p);
}

}  // namespace mg

namespace mg {
namespace {

// A "+" marker of half-size h at (x, y) as two strokes of a series (NaN breaks them).
void marker(svg::Series& s, double x, double hx, double y, double hy) {
  const double nan = std::nan("");
  s.x.insert(s.x.end(), {x - hx, x + hx, nan, x, x, nan});
  s.y.insert(s.y.end(), {y, y, nan, y - hy, y + hy, nan});
}

}  // namespace

std::string frontier_svg(const MergeAudit& m) {
  svg::Plot p = svg::frame("Compliance frontier: where the merge holds", "response time rho [s]", "braking limits b_min, b_max x scale", 640, 360);
  const ComplianceFrontier& f = *m.frontier;
  double y_lo = 1.0, y_hi = 1.0;
  for (const FrontierCurvePoint& c : f.curve) y_lo = std::min(y_lo, c.brake_scale), y_hi = std::max(y_hi, c.brake_scale);
  const double hy = 0.02 * std::max(y_hi - y_lo, 0.5);
  svg::Series holds{"holds", {}, {}, "#2ca02c", "", 2.0}, fails{"violated", {}, {}, "#d62728", "", 2.0};
  if (m.sensitivity) {
    for (const SensitivityPoint& pt : m.sensitivity->points) marker(pt.holds ? holds : fails, pt.response_time_s, 0.06, pt.brake_scale, hy);
  }
  svg::Series frontier{"frontier (largest rho that holds)", {}, {}, "#1f77b4", "", 2.0};
  for (const FrontierCurvePoint& c : f.curve) {
    // No point where it fails even at rho = 0: there is no frontier to draw there.
    frontier.x.push_back(c.rho.max_response_time_s ? *c.rho.max_response_time_s : std::nan(""));
    frontier.y.push_back(c.brake_scale);
  }
  svg::Series profile{"profile's rho", {f.profile_response_time_s, f.profile_response_time_s}, {y_lo - 4 * hy, y_hi + 4 * hy}, "#7f7f7f", "5 3", 1.2};
  p.series = {frontier, holds, fails, profile};
  p.x_range = svg::Range{0.0, kMaxFrontierResponseTimeS};
  p.y_range = svg::Range{y_lo - 5 * hy, y_hi + 5 * hy};
  return svg::render(p);
}

std::string frontier_histogram_svg(const std::vector<std::optional<double>>& max_response_times_s, const std::vector<bool>& throughout) {
  constexpr double kBinS = 0.25;
  const int bins = static_cast<int>(std::lround(kMaxFrontierResponseTimeS / kBinS));
  std::vector<int> count(static_cast<std::size_t>(bins) + 2, 0);  // [0]: violated at 0; [bins + 1]: holds throughout
  for (std::size_t i = 0; i < max_response_times_s.size(); ++i) {
    if (throughout[i]) ++count.back();
    else if (!max_response_times_s[i]) ++count.front();
    else ++count[static_cast<std::size_t>(std::clamp(static_cast<int>(*max_response_times_s[i] / kBinS), 0, bins - 1)) + 1];
  }
  svg::Plot p = svg::frame("Compliance frontiers of the judged merges", "largest rho that holds [s] (left of 0: fails even at 0; right of 5: holds up to 5 s)",
                           "merges", 720, 360);
  svg::Series bars{"merges per 0.25 s", {}, {}, "#1f77b4", "", 1.5};
  for (std::size_t b = 0; b < count.size(); ++b) {
    const double x0 = (static_cast<double>(b) - 1.0) * kBinS, x1 = x0 + kBinS;
    bars.x.insert(bars.x.end(), {x0, x0, x1, x1});
    bars.y.insert(bars.y.end(), {0.0, static_cast<double>(count[b]), static_cast<double>(count[b]), 0.0});
  }
  p.series = {bars};
  p.x_range = svg::Range{-kBinS, kMaxFrontierResponseTimeS + kBinS};
  const int top = *std::max_element(count.begin(), count.end());
  p.y_range = svg::Range{0.0, std::max(4.0, top * 1.15)};
  p.legend = svg::LegendCorner::kTopLeft;
  return svg::render(p);
}

}  // namespace mg
