#include "report/report_html.h"


#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "report/report_markdown.h"
#include "report/report_table.h"
#include "report/svg_plot.h"
#include "rules/collision_monitor.h"
#include "rules/monitor.h"
#include "rules/pair_geometry.h"
#include "rules/planner_account.h"
#include "rules/rule_catalog.h"

namespace mg {
namespace {

const char* const kPalette[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

std::string colour_of(std::size_t k) { return kPalette[k % (sizeof kPalette / sizeof *kPalette)]; }

std::string escape(const std::string& in) { return html_escape(in); }

// Times worth drawing vehicle boxes at: start, merge events, halts, first violations, end.
std::vector<double> key_moments(const CheckResult& r) {
  std::vector<double> t;
  if (r.trace.steps.empty()) return t;
  t.push_back(r.trace.steps.front().time_s);
  for (const double m : r.merge_phase_times_s) t.push_back(m);
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

// One series built point by point, one point per trace step: kept whole when every point can
// show (at most 4 per pixel column), thinned as it is built otherwise, so that the plot data of
// a long trace never exist in full (svg::render thins a plot with many series further).
class SeriesBuilder {
 public:
  SeriesBuilder(const svg::Series& style, svg::Range x_range, int width_px, std::size_t points)
      : whole_(points <= 4 * static_cast<std::size_t>(width_px)), plain_(style), thinner_(style, x_range, width_px) {}
  void add(double x, double y) {
    if (!whole_) return thinner_.add(x, y);
    plain_.x.push_back(x);
    plain_.y.push_back(y);
  }
  svg::Series take() { return whole_ ? std::move(plain_) : thinner_.take(); }

 private:
  bool whole_;
  svg::Series plain_;
  svg::Thinner thinner_;
};

svg::Range time_range(const ObservedTrace& t) { return {t.steps.front().time_s, t.steps.back().time_s}; }

// Lists longer than this show their first entries and say how many more report.json holds.
constexpr std::size_t kMaxListedEntries = 400;

void more_entries_note(std::ostringstream& h, std::size_t total) {
  if (total > kMaxListedEntries)
    h << "<li>&hellip; " << total - kMaxListedEntries << " more (report.json lists all)</li>\n";
}

std::string vehicle_label(const ObservedTrace& s, std::size_t k) { return party_name(party_of(s, k)); }

svg::Plot top_down_plot(const CheckResult& r) {
  const ObservedTrace& s = r.trace;
  svg::Plot p = svg::frame("Top-down view: trajectories, vehicle boxes at the key moments", "X [m]", "Y [m]", 960, 360);
  const auto& steps = r.trace.steps;
  const std::size_t n = s.vehicles.size();
  const double w = s.road.lane_width_m;
  double x_lo = ego_of(steps.front()).x_m, x_hi = x_lo;
  for (const ObservedStep& st : steps)  // steps outside, vehicles inside: the trace's memory order
    for (std::size_t k = 0; k < n; ++k) x_lo = std::min(x_lo, state_of(st, k).x_m), x_hi = std::max(x_hi, state_of(st, k).x_m);
  std::vector<SeriesBuilder> paths;
  for (std::size_t k = 0; k < n; ++k) {
    svg::Series path;
    path.label = vehicle_label(s, k);
    path.colour = colour_of(k);
    path.dash = k == 0 ? "" : "5 3";
    paths.emplace_back(path, svg::Range{x_lo, x_hi}, p.width_px, steps.size());
  }
  for (const ObservedStep& st : steps)
    for (std::size_t k = 0; k < n; ++k) paths[k].add(state_of(st, k).x_m, state_of(st, k).y_m);
  for (SeriesBuilder& b : paths) p.series.push_back(b.take());
  for (double t : key_moments(r)) {
    const ObservedStep& st = steps[step_at(r.trace, t)];
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
  return svg::frame(std::move(title), "time t [s]", std::move(y_label), 960, 300);
}

svg::Plot gap_plot(const CheckResult& r) {
  const ObservedTrace& s = r.trace;
  svg::Plot p = time_plot("Ego to each vehicle: centre gap |dX| against D_lon (eq. 1), while laterally unsafe", "distance [m]");
  const auto& steps = r.trace.steps;
  std::vector<SeriesBuilder> series;  // gap and D_lon of vehicle k at 2 (k - 1) and 2 (k - 1) + 1
  for (std::size_t k = 1; k < s.vehicles.size(); ++k) {
    svg::Series gap, dlon;
    gap.label = "gap to " + vehicle_label(s, k);
    dlon.label = "D_lon with " + vehicle_label(s, k);
    gap.colour = dlon.colour = colour_of(k);
    dlon.dash = "6 3";
    series.emplace_back(gap, time_range(r.trace), p.width_px, steps.size());
    series.emplace_back(dlon, time_range(r.trace), p.width_px, steps.size());
  }
  std::vector<pair_detail::PairMemo> memo(s.vehicles.size() - 1);
  const double nan = std::nan("");
  for (const ObservedStep& st : steps) {
    for (std::size_t k = 1; k < s.vehicles.size(); ++k) {
      const bool shown = pair_lat_unsafe(s, st, 0, k, memo[k - 1]);
      const PairGeometry g = shown ? pair_geometry(s, st, 0, k, memo[k - 1]) : PairGeometry{};
      series[2 * (k - 1)].add(st.time_s, shown ? g.gap_m : nan);
      series[2 * (k - 1) + 1].add(st.time_s, shown ? g.d_lon_m : nan);
    }
  }
  for (SeriesBuilder& b : series) p.series.push_back(b.take());
  return p;
}

svg::Plot speed_plot(const CheckResult& r) {
  const ObservedTrace& s = r.trace;
  svg::Plot p = time_plot("Speeds", "speed [m/s]");
  std::vector<SeriesBuilder> series;
  for (std::size_t k = 0; k < s.vehicles.size(); ++k) {
    svg::Series v;
    v.label = vehicle_label(s, k);
    v.colour = colour_of(k);
    series.emplace_back(v, time_range(r.trace), p.width_px, r.trace.steps.size());
  }
  for (const ObservedStep& st : r.trace.steps)
    for (std::size_t k = 0; k < s.vehicles.size(); ++k) series[k].add(st.time_s, speed_of(state_of(st, k)));
  for (SeriesBuilder& b : series) p.series.push_back(b.take());
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
  const double limit = r.rule_params.sideslip_max_rad;
  SeriesBuilder b(beta, time_range(r.trace), p.width_px, r.trace.steps.size());
  for (const ObservedStep& st : r.trace.steps) {
    const ObservedState& e = ego_of(st);
    const double body_vx = e.vx_mps * std::cos(e.yaw_rad) + e.vy_mps * std::sin(e.yaw_rad);
    b.add(st.time_s, body_vx >= r.rule_params.sideslip_min_speed_mps
                         ? std::remainder(std::atan2(e.vy_mps, e.vx_mps) - e.yaw_rad, 2.0 * M_PI)
                         : std::nan(""));
  }
  hi.x = lo.x = {r.trace.steps.front().time_s, r.trace.steps.back().time_s};
  hi.y = {limit, limit};
  lo.y = {-limit, -limit};
  p.series = {b.take(), hi, lo};
  return p;
}

// The planner's own account (rules/planner_account.h), shown beside the verdict, never used for it.
void planner_account_list(std::ostringstream& h, const CheckResult& r) {
  const std::vector<PlannerClaim> claims = planner_account(r);
  if (claims.empty()) return;
  h << "<h2>The planner's own account (not judged)</h2>\n<ul>\n";
  for (std::size_t k = 0; k < claims.size() && k < kMaxListedEntries; ++k) {
    const PlannerClaim& c = claims[k];
    h << "<li>t = " << format_number(c.time_s, 2) << " s: planner reported " << escape(c.mode);
    if (!c.reason.empty()) h << " &mdash; " << escape(c.reason);
    if (c.disagrees) h << " <b>(disagrees: observed, the ego did not hold the right of way then)</b>";
    h << "</li>\n";
  }
  h << "</ul>\n";
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

// The rule and RSS parameters the verdict was reached with (a verdict means nothing without them).
void judged_with_table(std::ostringstream& h, const CheckResult& r) {
  h << "<h2>Judged with</h2>\n<table><tr><th>parameter</th><th>value</th></tr>\n";
  const nlohmann::json judged = judged_with_json(r);
  for (const auto& [group, values] : judged.items())
    for (const auto& [name, value] : values.items())
      h << "<tr><td>" << escape(group + "." + name) << "</td><td>" << escape(value.dump()) << "</td></tr>\n";
  h << "</table>\n";
}

}  // namespace

std::string report_html(const CheckResult& r) {
  const ObservedTrace& s = r.trace;
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
    << "</code>; trace from " << escape(s.source) << ".</p>\n<h2>Violations</h2>\n";
  violations_table(h, r);
  h << "<h2>Right of way</h2>\n<ul>\n";
  for (std::size_t k = 0; k < std::min(r.right_of_way.size(), kMaxListedEntries); ++k) {
    const auto& [t, holder] = r.right_of_way[k];
    h << "<li>from t = " << format_number(t, 2) << " s: " << escape(party_name(holder)) << "</li>\n";
  }
  more_entries_note(h, r.right_of_way.size());
  h << "</ul>\n<p>What decided it, observed:</p>\n<ul>\n";
  for (const std::string& o : r.right_of_way_observations) h << "<li>" << escape(o) << "</li>\n";
  h << "</ul>\n";
  planner_account_list(h, r);
  if (!r.trace.steps.empty()) {
    h << "<h2>Trajectories</h2>\n" << inline_svg(svg::render(top_down_plot(r))) << "\n";
    h << "<h2>Gap against D_lon</h2>\n" << inline_svg(svg::render(gap_plot(r))) << "\n";
    h << "<h2>Speeds</h2>\n" << inline_svg(svg::render(speed_plot(r))) << "\n";
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
  h << "</table>\n";
  judged_with_table(h, r);
  h << "<h2>Timeline (V2V channel)</h2>\n<ul>\n";
  for (std::size_t k = 0; k < std::min(r.trace.channel.size(), kMaxListedEntries); ++k) {
    const ChannelEvent& e = r.trace.channel[k];
    h << "<li>t = " << format_number(e.time_s, 2) << " s &mdash; " << escape(to_string(e.message.type)) << " "
      << escape(to_string(e.kind)) << " (" << escape(party_name(Party::from_vehicle_id(e.message.from_id))) << " to "
      << escape(party_name(Party::from_vehicle_id(e.message.to_id))) << ")</li>\n";
  }
  more_entries_note(h, r.trace.channel.size());
  h << "</ul>\n</body></html>\n";
  return h.str();
}

}  // namespace mg
