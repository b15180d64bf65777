// The paper report's figures: what each planner's run looks like, beside the ranges the paper's
// §IV gives (paper/paper_figures.h).
#include "paper/paper_figures.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "report/svg_plot.h"
#include "sim/single_track.h"
#include "sim/trace.h"

namespace mg {
namespace {

// Light tint of a planner's colour, for the bands of its merge zone and of the paper's ranges.
const char* tint_of(const std::string& planner) {
  if (planner == "tripfield") return "#cfe8cf";
  if (planner == "rcpp") return "#e6d6cf";
  return "#f6cccc";
}

// The ego's X at the first step at or after time_s (its last X when none is).
double ego_x_at(const Trace& t, double time_s) {
  for (const TraceStep& s : t.steps)
    if (s.time_s >= time_s - 1e-9) return s.ego.x_m;
  return t.steps.empty() ? 0.0 : t.steps.back().ego.x_m;
}

// Time series of one planner's run.
std::vector<double> series(const Trace& t, double (*f)(const TraceStep&)) {
  std::vector<double> out;
  out.reserve(t.steps.size());
  for (const TraceStep& s : t.steps) out.push_back(f(s));
  return out;
}

double obstacle_speed(const TraceStep& s) { return s.others.empty() ? NAN : s.others[0].vx_mps; }

// The obstacle's footprint at the instant each ego's centre crosses the lane marking, in that
// planner's colour: a path alone does not show who went first, the paper's point.
void add_obstacle_at_crossings(const PaperExperiment& e, svg::Plot& p) {
  if (e.scenario.vehicles.empty()) return;
  const VehicleSize& size = e.scenario.vehicles[0].size;
  for (const PaperRun& r : e.runs) {
    const auto crossing = first_event_s(r.trace, EventKind::kMergeMidpoint, 0);
    if (!crossing) continue;
    for (const TraceStep& st : r.trace.steps) {
      if (st.time_s < *crossing - 1e-9) continue;
      const VehicleState& o = st.others[0];
      const double x0 = o.x_m - 0.5 * size.length_m, x1 = o.x_m + 0.5 * size.length_m;
      const double y0 = o.y_m - 0.5 * size.width_m, y1 = o.y_m + 0.5 * size.width_m;
      const char* who = r.planner == "tripfield" ? "TriPField" : r.planner == "rcpp" ? "non-coop" : "coop";
      p.series.push_back({std::string("obstacle at ") + who + " crossing", {x0, x1, x1, x0, x0},
                          {y0, y0, y1, y1, y0}, planner_style(r.planner).colour, "", 1.6});
      break;
    }
  }
}

}  // namespace

PlannerStyle planner_style(const std::string& planner) {
  if (planner == "tripfield") return {"#2ca02c", "8 4", "TriPField-style baseline"};
  if (planner == "rcpp") return {"#8c564b", "2 3", "RCPP non-cooperative"};
  return {"#d62728", "10 3 2 3", "RCPP cooperative"};
}

std::string fig4_paths_svg(const PaperExperiment& e) {
  const Road& road = e.scenario.road;
  const double w = road.lane_width_m;
  svg::Plot p = svg::frame("Lane-merge paths (cf. paper Fig. 4)", "X along the road [m]", "Y lateral [m]", 1100, 480);
  // Up to 100 m past the last merge completion (or the end of the run), at least past the ramp.
  double x_hi = road.side_lane_end_x_m + 50.0, x_lo = e.scenario.ego.x_m - 10.0;
  for (const PaperRun& r : e.runs) {
    const auto done = first_event_s(r.trace, EventKind::kMergeComplete, 0);
    double x_end = r.trace.steps.back().ego.x_m;
    for (const TraceStep& st : r.trace.steps)
      if (done && st.time_s >= *done) {
        x_end = std::min(x_end, st.ego.x_m + 100.0);
        break;
      }
    x_hi = std::max(x_hi, x_end);
  }
  p.x_range = svg::Range{x_lo, x_hi};
  p.y_range = svg::Range{-1.6 * w, (road.main_lanes - 0.5) * w + 2.6 * w};  // room for the legend
  auto line = [&](std::vector<double> x, std::vector<double> y, const std::string& label, const char* dash) {
    p.series.push_back({label, std::move(x), std::move(y), "#999999", dash, 1.0});
  };
  line({x_lo, x_hi}, {(road.main_lanes - 0.5) * w, (road.main_lanes - 0.5) * w}, "road edge", "");
  line({x_lo, road.side_lane_end_x_m}, {-0.5 * w, -0.5 * w}, "lane marking", "6 6");
  line({road.side_lane_end_x_m, x_hi}, {-0.5 * w, -0.5 * w}, "", "");
  line({road.side_lane_start_x_m, road.side_lane_end_x_m, road.side_lane_end_x_m},
       {-1.5 * w, -1.5 * w, -0.5 * w}, "", "");
  // Each planner's merge zone (merge start to completion) as a strip above the road, in its tint.
  const double strip_m = 0.45 * w, strip_base_m = (road.main_lanes - 0.5) * w + 0.1 * w;
  for (std::size_t k = 0; k < e.runs.size(); ++k) {
    const PaperRun& r = e.runs[k];
    if (!r.metrics.merge_start_time_s || !r.metrics.merge_time_s) continue;
    const double from = ego_x_at(r.trace, *r.metrics.merge_start_time_s);
    const double to = ego_x_at(r.trace, *r.metrics.merge_start_time_s + *r.metrics.merge_time_s);
    const double lo = strip_base_m + static_cast<double>(k) * strip_m;
    p.bands.push_back({from, to, std::string("merge zone: ") + planner_style(r.planner).label, tint_of(r.planner),
                       svg::Range{lo, lo + 0.9 * strip_m}});
  }
  const PaperRun& base = paper_run_of(e, "tripfield");
  for (std::size_t i = 0; i < e.scenario.vehicles.size(); ++i) {
    std::vector<double> x, y;
    for (const TraceStep& s : base.trace.steps) x.push_back(s.others[i].x_m), y.push_back(s.others[i].y_m);
    // The first main-lane vehicle is the paper's obstacle; any other is traffic (e.g. a lead vehicle).
    const std::string id = std::to_string(e.scenario.vehicles[i].id);
    p.series.push_back({i == 0 ? "obstacle vehicle " + id : "main-lane vehicle " + id, x, y,
                        i == 0 ? "#1f77b4" : "#17becf", i == 0 ? "" : "1 2", 2.0});
  }
  for (const PaperRun& r : e.runs) {
    const PlannerStyle st = planner_style(r.planner);
    std::vector<double> x, y;
    for (const TraceStep& s : r.trace.steps) x.push_back(s.ego.x_m), y.push_back(s.ego.y_m);
    p.series.push_back({std::string("ego: ") + st.label, x, y, st.colour, st.dash, 2.0});
  }
  add_obstacle_at_crossings(e, p);
  return svg::render(p);
}

// The ranges §IV reports for Fig. 5, drawn behind our curves in the planner's tint (the paper
// gives no numbers for the yaw angle, panel b).
constexpr double kInf = std::numeric_limits<double>::infinity();
const std::vector<svg::Band> kSideslipBands{
    {7.6, 9.7, "paper: TriPField within ±0.02 rad, 7.6–9.7 s", "#cfe8cf", svg::Range{-0.02, 0.02}},
    {-kInf, kInf, "paper: non-coop −0.012 … 0.016 rad", "#e6d6cf", svg::Range{-0.012, 0.016}},
    {6.9, 7.3, "paper: coop peak 0.024 rad at 7.1 s", "#f6cccc", svg::Range{0.022, 0.026}}};
const std::vector<svg::Band> kNoBands{};
const std::vector<svg::Band> kObstacleSpeedBands{
    {-kInf, kInf, "paper: with TriPField below 10 m/s", "#cfe8cf", svg::Range{0.0, 10.0}},
    {-kInf, kInf, "paper: with non-coop RCPP to about 16 m/s", "#e6d6cf", svg::Range{15.0, 17.0}}};
const std::vector<svg::Band> kEgoSpeedBands{
    {-kInf, kInf, "paper: TriPField below 9 m/s", "#cfe8cf", svg::Range{0.0, 9.0}},
    {-kInf, kInf, "paper: non-coop briefly 30 m/s", "#e6d6cf", svg::Range{29.0, 31.0}},
    {-kInf, kInf, "paper: non-coop 20 m/s after merging", "#e6d6cf", svg::Range{19.5, 20.5}}};

std::string fig5_motion_svg(const PaperExperiment& e) {
  struct Panel {
    const char* title;
    const char* y_label;
    double (*value)(const TraceStep&);
    svg::LegendCorner legend;
  };
  const Panel panels[] = {
      {"(a) Sideslip angle of the ego", "sideslip beta [rad]", [](const TraceStep& s) { return sideslip_rad(s.ego); },
       svg::LegendCorner::kBottomRight},
      {"(b) Yaw angle of the ego", "yaw psi [rad]", [](const TraceStep& s) { return s.ego.yaw_rad; },
       svg::LegendCorner::kTopRight},
      {"(c) Longitudinal speed of the obstacle vehicle", "speed v_o [m/s]", obstacle_speed, svg::LegendCorner::kBottomRight},
      {"(d) Longitudinal speed of the ego vehicle", "speed v_x [m/s]", [](const TraceStep& s) { return s.ego.vx_mps; },
       svg::LegendCorner::kBottomRight},
  };
  std::vector<svg::Plot> plots;
  const std::vector<svg::Band>* band_of[] = {&kSideslipBands, &kNoBands, &kObstacleSpeedBands, &kEgoSpeedBands};
  for (std::size_t k = 0; k < std::size(panels); ++k) {
    const Panel& panel = panels[k];
    svg::Plot p = svg::frame(panel.title, "time t [s]", panel.y_label, 640, 360);
    p.bands = *band_of[k];
    p.legend = panel.legend;
    for (const PaperRun& r : e.runs) {
      const PlannerStyle st = planner_style(r.planner);
      p.series.push_back({st.label, series(r.trace, [](const TraceStep& s) { return s.time_s; }),
                          series(r.trace, panel.value), st.colour, st.dash, 1.8});
    }
    plots.push_back(std::move(p));
  }
  return svg::render_grid(plots, 2, "Motion states of the ego and obstacle vehicles (cf. paper Fig. 5)");
}

std::string right_of_way_svg(const PaperExperiment& e) {
  std::vector<svg::Plot> plots;
  for (const PaperRun& r : e.runs) {
    const PlannerStyle st = planner_style(r.planner);
    svg::Plot p = svg::frame(std::string("Right of way: ") + st.label, "time t [s]", "ego holds (1) or not", 1100, 190);
    p.y_range = svg::Range{-0.2, 1.2};
    const double t_end = r.trace.steps.empty() ? 0.0 : r.trace.steps.back().time_s;
    p.x_range = svg::Range{0.0, t_end};
    // A step function: each change holds until the next one.
    std::vector<double> x, y;
    for (std::size_t k = 0; k < r.right_of_way.size(); ++k) {
      const auto& [t, holder] = r.right_of_way[k];
      const double until = k + 1 < r.right_of_way.size() ? r.right_of_way[k + 1].first : t_end;
      const double level = holder.is_ego() ? 1.0 : 0.0;
      x.insert(x.end(), {t, until});
      y.insert(y.end(), {level, level});
    }
    p.series.push_back({"", std::move(x), std::move(y), st.colour, "", 2.4});
    if (r.metrics.merge_start_time_s && r.metrics.merge_time_s)
      p.bands.push_back({*r.metrics.merge_start_time_s, *r.metrics.merge_start_time_s + *r.metrics.merge_time_s,
                         "merge (start to completion)", tint_of(r.planner), std::nullopt});
    plots.push_back(std::move(p));
  }
  return svg::render_grid(plots, 1, "Who holds the right of way (rule checker, rules/liability.h)");
}

}  // namespace mg
