#include "rules/report_html.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "rules/collision_monitor.h"
#include "rules/report_markdown.h"
#include "rules/monitor.h"
#include "rules/pair_geometry.h"
#include "rules/rule_catalog.h"
#include "sim/svg_plot.h"

namespace mg {
namespace {

const char* const kPalette[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

std::string colour_of(std::size_t k) { return kPalette[k % (sizeof kPalette / sizeof *kPalette)]; }

std::string escape(const std::string& in) { return svg::xml_escape(in); }

// Inline SVG inside HTML needs no namespace declaration: drop it so the page holds no URL.
std::string inline_svg(std::string svg) {
  const std::string ns = " xmlns=\"http://www.w3.org/2000/svg\"";
  for (auto pos = svg.find(ns); pos != std::string::npos; pos = svg.find(ns)) svg.erase(pos, ns.size());
  return svg;
}

// Times worth drawing vehicle boxes at: start, merge events, halts, first violations, end.
std::vector<double> key_moments(const CheckResult& r) {
  std::vector<double> t;
  if (r.trace.steps.empty()) return t;
  t.push_back(r.trace.steps.front().time_s);
  for (const TraceEvent& e : r.trace.events) {
    if (e.kind == EventKind::kMergeStart || e.kind == EventKind::kMergeMidpoint ||
        e.kind == EventKind::kMergeComplete || e.kind == EventKind::kHalt)
      t.push_back(e.time_s);
  }
  for (const RuleResult& rule : r.rules) {
    if (!rule.holds) t.push_back(*rule.first_violation_time_s);
  }
  t.push_back(r.trace.steps.back().time_s);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end(), [](double a, double b) { return std::abs(a - b) < 0.05; }), t.end());
  if (t.size() > 8) t.resize(8);
  return t;
}

svg::Series box_outline(const BoxPose& p, const std::string& colour) {
  svg::Series s;
  s.colour = colour;
  s.width_px = 1.2;
  const double c = std::cos(p.yaw_rad), sn = std::sin(p.yaw_rad);
  const double corners[5][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}, {1, 1}};
  for (const auto& k : corners) {
    const double lx = k[0] * p.length_m / 2.0, ly = k[1] * p.width_m / 2.0;
    s.x.push_back(p.x_m + lx * c - ly * sn);
    s.y.push_back(p.y_m + lx * sn + ly * c);
  }
  return s;
}

// A series thinned to what a plot `width_px` wide shows as soon as it is built, so that a long
// trace's plot data never exist in full (svg::render thins the whole plot further if needed).
svg::Series fit_to_width(const svg::Series& s, int width_px) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double x : s.x)
    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  return hi > lo ? svg::thinned(s, {lo, hi}, width_px) : s;
}

// Lists longer than this show their first entries and say how many more report.json holds.
constexpr std::size_t kMaxListedEntries = 400;

void more_entries_note(std::ostringstream& h, std::size_t total) {
  if (total > kMaxListedEntries)
    h << "<li>&hellip; " << total - kMaxListedEntries << " more (report.json lists all)</li>\n";
}

std::string vehicle_label(const Scenario& s, std::size_t k) { return party_name(party_of(s, k)); }

svg::Plot top_down_plot(const Scenario& s, const CheckResult& r) {
  svg::Plot p;
  p.title = "Top-down view: trajectories, vehicle boxes at the key moments";
  p.x_label = "X [m]";
  p.y_label = "Y [m]";
  p.width_px = 960;
  p.height_px = 360;
  const auto& steps = r.trace.steps;
  const std::size_t n = s.vehicles.size() + 1;
  const double w = s.road.lane_width_m;
  double x_lo = steps.front().ego.x_m, x_hi = x_lo;
  for (std::size_t k = 0; k < n; ++k) {
    svg::Series path;
    path.label = vehicle_label(s, k);
    path.colour = colour_of(k);
    path.dash = k == 0 ? "" : "5 3";
    for (const TraceStep& st : steps) {
      path.x.push_back(state_of(st, k).x_m);
      path.y.push_back(state_of(st, k).y_m);
      x_lo = std::min(x_lo, state_of(st, k).x_m);
      x_hi = std::max(x_hi, state_of(st, k).x_m);
    }
    p.series.push_back(fit_to_width(path, p.width_px));
  }
  for (double t : key_moments(r)) {
    const TraceStep& st = steps[step_at(r.trace, t)];
    for (std::size_t k = 0; k < n; ++k) p.series.push_back(box_outline(box_pose_of(s, st, k), colour_of(k)));
  }
  auto line = [&](std::string label, double x0, double x1, double y0, double y1, std::string dash) {
    svg::Series e;
    e.label = std::move(label);
    e.colour = "#555555";
    e.dash = std::move(dash);
    e.width_px = 1.0;
    e.x = {x0, x1};
    e.y = {y0, y1};
    p.series.push_back(std::move(e));
  };
  const double end = s.road.side_lane_end_x_m;
  line("road edges", x_lo - 5, x_hi + 5, (s.road.main_lanes - 0.5) * w, (s.road.main_lanes - 0.5) * w, "");
  line("", x_lo - 5, std::min(end, x_hi + 5), -1.5 * w, -1.5 * w, "");
  line("lane boundary", x_lo - 5, std::min(end, x_hi + 5), -0.5 * w, -0.5 * w, "4 4");
  if (end > x_lo - 5 && end < x_hi + 5) {
    line("side lane end", end, end, -1.5 * w, -0.5 * w, "");
    line("", std::max(end, x_lo - 5), x_hi + 5, -0.5 * w, -0.5 * w, "");
  }
  return p;
}

svg::Plot time_plot(std::string title, std::string y_label) {
  svg::Plot p;
  p.title = std::move(title);
  p.x_label = "time t [s]";
  p.y_label = std::move(y_label);
  p.width_px = 960;
  p.height_px = 300;
  return p;
}

svg::Plot gap_plot(const Scenario& s, const CheckResult& r) {
  svg::Plot p = time_plot("Ego to each vehicle: centre gap |dX| against D_lon (eq. 1), while laterally unsafe", "distance [m]");
  for (std::size_t k = 1; k <= s.vehicles.size(); ++k) {
    svg::Series gap, dlon;
    gap.label = "gap to " + vehicle_label(s, k);
    dlon.label = "D_lon with " + vehicle_label(s, k);
    gap.colour = dlon.colour = colour_of(k);
    dlon.dash = "6 3";
    for (const TraceStep& st : r.trace.steps) {
      const PairGeometry g = pair_geometry(s, st, 0, k);
      const double nan = std::nan("");
      gap.x.push_back(st.time_s);
      dlon.x.push_back(st.time_s);
      gap.y.push_back(g.lat_unsafe() ? g.gap_m : nan);
      dlon.y.push_back(g.lat_unsafe() ? g.d_lon_m : nan);
    }
    p.series.push_back(fit_to_width(gap, p.width_px));
    p.series.push_back(fit_to_width(dlon, p.width_px));
  }
  return p;
}

svg::Plot speed_plot(const Scenario& s, const CheckResult& r) {
  svg::Plot p = time_plot("Speeds", "speed [m/s]");
  for (std::size_t k = 0; k <= s.vehicles.size(); ++k) {
    svg::Series v;
    v.label = vehicle_label(s, k);
    v.colour = colour_of(k);
    for (const TraceStep& st : r.trace.steps) {
      v.x.push_back(st.time_s);
      v.y.push_back(speed_of(state_of(st, k)));
    }
    p.series.push_back(fit_to_width(v, p.width_px));
  }
  return p;
}

svg::Plot sideslip_plot(const CheckResult& r) {
  svg::Plot p = time_plot("Ego sideslip beta = atan2(v_y, v_x)", "sideslip [rad]");
  svg::Series beta, hi, lo;
  beta.label = "beta";
  beta.colour = colour_of(0);
  hi.label = "bound";
  hi.colour = lo.colour = "#555555";
  hi.dash = lo.dash = "4 4";
  const double limit = catalog_params().sideslip_max_rad;
  for (const TraceStep& st : r.trace.steps) {
    beta.x.push_back(st.time_s);
    beta.y.push_back(st.ego.vx_mps >= catalog_params().sideslip_min_speed_mps ? std::atan2(st.ego.vy_mps, st.ego.vx_mps)
                                                                              : std::nan(""));
  }
  if (!beta.x.empty()) {
    hi.x = lo.x = {beta.x.front(), beta.x.back()};
    hi.y = {limit, limit};
    lo.y = {-limit, -limit};
  }
  p.series = {fit_to_width(beta, p.width_px), hi, lo};
  return p;
}

void violations_table(std::ostringstream& h, const CheckResult& r) {
  bool any = false;
  for (const RuleResult& rule : r.rules) {
    if (rule.holds) continue;
    if (!any) {
      h << "<table><tr><th>rule</th><th>paper reference</th><th>liable</th><th>first violation [s]</th>"
           "<th>required</th><th>actual</th><th>margin</th><th>worst at [s]</th><th>what happened</th></tr>\n";
    }
    any = true;
    h << "<tr class=\"bad\"><td>" << escape(rule.rule_id) << "</td><td>" << escape(rule.paper_ref) << "</td><td>"
      << escape(party_name(rule.liable_id)) << "</td><td>" << format_number(*rule.first_violation_time_s, 2)
      << "</td><td>" << format_number(rule.required_value) << " " << escape(rule.unit) << "</td><td>"
      << format_number(rule.actual_value) << " " << escape(rule.unit) << "</td><td>" << format_number(rule.min_margin)
      << " " << escape(rule.unit) << "</td><td>" << format_number(rule.min_margin_time_s, 2) << "</td><td>"
      << escape(rule.detail) << "</td></tr>\n";
  }
  h << (any ? "</table>\n" : "<p>None: every rule holds.</p>\n");
}

}  // namespace

std::string report_html(const Scenario& s, const CheckResult& r) {
  std::ostringstream h;
  const std::string verdict = r.holds ? "HOLDS" : "VIOLATED";
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>mergeguard: " << escape(s.name)
    << " - " << verdict << "</title>\n<style>body{font-family:sans-serif;max-width:1000px;margin:1em auto;}"
       "table{border-collapse:collapse;font-size:90%;}td,th{border:1px solid #bbb;padding:2px 6px;vertical-align:top;}"
       ".bad td{background:#fde8e8;}.verdict{font-size:140%;font-weight:bold;}.holds{color:#1a7f37;}"
       ".violated{color:#b42318;}</style></head><body>\n";
  h << "<p class=\"verdict " << (r.holds ? "holds" : "violated") << "\">Verdict: " << verdict
    << " &mdash; liable: " << escape(party_name(r.liable_id)) << "</p>\n";
  if (r.collision) h << "<p><b>Collision</b> (liable: " << escape(party_name(r.collision_liable_id)) << ")</p>\n";
  if (!r.liability_detail.empty()) h << "<p>" << escape(r.liability_detail) << "</p>\n";
  h << "<h1>mergeguard liability report: " << escape(s.name) << "</h1>\n<p>Planner <code>" << escape(r.planner)
    << "</code>. " << escape(s.description) << "</p>\n<h2>Violations</h2>\n";
  violations_table(h, r);
  h << "<h2>Right of way</h2>\n<ul>\n";
  for (std::size_t k = 0; k < std::min(r.right_of_way.size(), kMaxListedEntries); ++k) {
    const auto& [t, holder] = r.right_of_way[k];
    h << "<li>from t = " << format_number(t, 2) << " s: " << escape(party_name(holder)) << "</li>\n";
  }
  more_entries_note(h, r.right_of_way.size());
  h << "</ul>\n";
  if (!r.trace.steps.empty()) {
    h << "<h2>Trajectories</h2>\n" << inline_svg(svg::render(top_down_plot(s, r))) << "\n";
    h << "<h2>Gap against D_lon</h2>\n" << inline_svg(svg::render(gap_plot(s, r))) << "\n";
    h << "<h2>Speeds</h2>\n" << inline_svg(svg::render(speed_plot(s, r))) << "\n";
    h << "<h2>Sideslip</h2>\n" << inline_svg(svg::render(sideslip_plot(r))) << "\n";
  }
  h << "<h2>All rules</h2>\n<table><tr><th>rule</th><th>paper reference</th><th>holds</th><th>min margin</th>"
       "<th>at [s]</th><th>statement</th><th>liability logic</th></tr>\n";
  for (const RuleResult& rule : r.rules) {
    const RuleSpec& spec = rule_spec(rule.rule_id);
    h << "<tr" << (rule.holds ? "" : " class=\"bad\"") << "><td>" << escape(rule.rule_id) << "</td><td>"
      << escape(rule.paper_ref) << "</td><td>" << (rule.holds ? "yes" : "no") << "</td><td>"
      << (std::isfinite(rule.min_margin) ? format_number(rule.min_margin) + " " + escape(rule.unit) : "n/a")
      << "</td><td>" << format_number(rule.min_margin_time_s, 2) << "</td><td>" << escape(spec.statement)
      << "</td><td>" << escape(spec.liability) << "</td></tr>\n";
  }
  h << "</table>\n<h2>Timeline</h2>\n<ul>\n";
  for (std::size_t k = 0; k < std::min(r.trace.events.size(), kMaxListedEntries); ++k) {
    const TraceEvent& e = r.trace.events[k];
    h << "<li>t = " << format_number(e.time_s, 2) << " s &mdash; " << escape(to_string(e.kind)) << " ("
      << escape(party_name(e.vehicle_id)) << "): " << escape(e.detail) << "</li>\n";
  }
  more_entries_note(h, r.trace.events.size());
  h << "</ul>\n</body></html>\n";
  return h.str();
}

}  // namespace mg
