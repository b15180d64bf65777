#include "sim/paper_report.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/fixed_text.h"
#include "core/atomic_file.h"
#include "planner/planner.h"
#include "sim/simulator.h"
#include "sim/single_track.h"
#include "sim/svg_plot.h"

namespace mg {
namespace {

struct Style {
  const char* colour;
  const char* dash;
  const char* label;
};

Style style_of(const std::string& planner) {
  if (planner == "tripfield") return {"#2ca02c", "8 4", "TriPField-style baseline"};
  if (planner == "rcpp") return {"#8c564b", "2 3", "RCPP non-cooperative"};
  return {"#d62728", "10 3 2 3", "RCPP cooperative"};
}

const PaperRun& run_of(const PaperExperiment& e, const std::string& planner) {
  for (const PaperRun& r : e.runs)
    if (r.planner == planner) return r;
  throw std::logic_error("no run of planner " + planner);
}

std::string fmt(double v, int decimals = 2) {
  if (!std::isfinite(v)) return "n/a";
  return fixed_text(v, decimals);
}

std::string fmt(const std::optional<double>& v, int decimals = 2) { return v ? fmt(*v, decimals) : "n/a"; }

nlohmann::json or_null(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

// Time series of one planner's run.
std::vector<double> series(const Trace& t, double (*f)(const TraceStep&)) {
  std::vector<double> out;
  out.reserve(t.steps.size());
  for (const TraceStep& s : t.steps) out.push_back(f(s));
  return out;
}

double obstacle_speed(const TraceStep& s) { return s.others.empty() ? NAN : s.others[0].vx_mps; }

// Time of the largest |sideslip| and its signed value.
std::pair<double, double> sideslip_peak(const Trace& t) {
  double best = 0.0, when = 0.0;
  for (const TraceStep& s : t.steps) {
    const double b = sideslip_rad(s.ego);
    if (std::abs(b) > std::abs(best)) best = b, when = s.time_s;
  }
  return {when, best};
}

// First time the obstacle (vehicle 0 of the scenario) brakes harder than 0.5 m/s^2.
std::optional<double> obstacle_first_braking_s(const Trace& t) {
  for (const TraceStep& s : t.steps)
    if (!s.others.empty() && s.others[0].accel_mps2 < -0.5) return s.time_s;
  return std::nullopt;
}

std::optional<double> first_event_s(const Trace& t, EventKind k, int vehicle_id) {
  for (const TraceEvent& e : t.events)
    if (e.kind == k && e.vehicle_id == vehicle_id) return e.time_s;
  return std::nullopt;
}

std::vector<PaperRun> run_planners(const Scenario& s) {
  std::vector<PaperRun> runs;
  for (const std::string& name : kPaperPlanners) {
    std::unique_ptr<Planner> planner = make_planner(name);
    if (!planner) throw std::logic_error("planner '" + name + "' is not registered");
    Trace trace = simulate(s, *planner);
    PaperMetrics metrics = compute_paper_metrics(s, trace);
    runs.push_back({name, std::move(trace), metrics});
  }
  return runs;
}

}  // namespace

PaperExperiment run_paper_experiment(const Scenario& s, const std::string& scenario_path) {
  PaperExperiment e{s, scenario_path, {}, {}};
  e.runs = run_planners(s);
  if (s.vehicles.empty()) return e;
  for (double dv : {-2.0, 0.0, 2.0})
    for (double dx : {-12.0, -6.0, 0.0, 6.0, 12.0}) {
      Scenario variant = s;
      MainVehicle& o = variant.vehicles[0];
      o.x_m += dx;
      o.speed_mps = std::max(0.0, o.speed_mps + dv);
      if (o.behaviour.desired_speed_mps >= 0.0) o.behaviour.desired_speed_mps = std::max(0.0, o.behaviour.desired_speed_mps + dv);
      SensitivityCase c{dx, dv, {}};
      for (const PaperRun& r : run_planners(variant)) c.metrics.push_back(r.metrics);
      e.sensitivity.push_back(std::move(c));
    }
  return e;
}

nlohmann::json paper_metrics_json(const PaperExperiment& e) {
  nlohmann::json planners = nlohmann::json::object(), saving = nlohmann::json::object(),
                 shorter = nlohmann::json::object();
  const PaperMetrics& base = run_of(e, "tripfield").metrics;
  for (const PaperRun& r : e.runs) {
    planners[r.planner] = paper_metrics_to_json(r.metrics);
    if (r.planner == "tripfield") continue;
    saving[r.planner] = or_null(reduction_pct(base.merge_time_s, r.metrics.merge_time_s));
    shorter[r.planner] = or_null(reduction_pct(base.path_length_m, r.metrics.path_length_m));
  }
  return {{"scenario", e.scenario_path},
          {"planners", planners},
          {"merge_time_saving_pct", saving},
          {"path_length_reduction_pct", shorter},
          {"definitions",
           {{"merge_time_s", "time from the ego first leaving the side lane centre (|Y - Y_side| > 0.1 m) to "
                             "merge completion (centre within 0.2 m of the main lane centre, |yaw| < 0.02 rad)"},
            {"path_length_m", "arc length of the ego's centre of gravity over the same interval"},
            {"lateral_reversals", "sign changes of the ego's road-frame lateral speed (dead band 0.1 m/s) over the "
                                  "whole run; a single S-shaped merge counts 0"},
            {"merge_time_saving_pct", "100 (T_tripfield - T_planner) / T_tripfield"},
            {"path_length_reduction_pct", "100 (L_tripfield - L_planner) / L_tripfield"}}}};
}

std::string fig4_paths_svg(const PaperExperiment& e) {
  const Road& road = e.scenario.road;
  const double w = road.lane_width_m;
  svg::Plot p;
  p.title = "Lane-merge paths (cf. paper Fig. 4)";
  p.x_label = "X along the road [m]";
  p.y_label = "Y lateral [m]";
  p.width_px = 1100;
  p.height_px = 380;
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
  p.y_range = svg::Range{-1.6 * w, (road.main_lanes - 0.5) * w + 1.6 * w};
  auto line = [&](std::vector<double> x, std::vector<double> y, const std::string& label, const char* dash) {
    p.series.push_back({label, std::move(x), std::move(y), "#999999", dash, 1.0});
  };
  line({x_lo, x_hi}, {(road.main_lanes - 0.5) * w, (road.main_lanes - 0.5) * w}, "road edge", "");
  line({x_lo, road.side_lane_end_x_m}, {-0.5 * w, -0.5 * w}, "lane marking", "6 6");
  line({road.side_lane_end_x_m, x_hi}, {-0.5 * w, -0.5 * w}, "", "");
  line({road.side_lane_start_x_m, road.side_lane_end_x_m, road.side_lane_end_x_m},
       {-1.5 * w, -1.5 * w, -0.5 * w}, "", "");
  const PaperRun& base = run_of(e, "tripfield");
  for (std::size_t i = 0; i < e.scenario.vehicles.size(); ++i) {
    std::vector<double> x, y;
    for (const TraceStep& s : base.trace.steps) x.push_back(s.others[i].x_m), y.push_back(s.others[i].y_m);
    p.series.push_back({"obstacle vehicle " + std::to_string(e.scenario.vehicles[i].id), x, y, "#1f77b4", "", 2.0});
  }
  for (const PaperRun& r : e.runs) {
    const Style st = style_of(r.planner);
    std::vector<double> x, y;
    for (const TraceStep& s : r.trace.steps) x.push_back(s.ego.x_m), y.push_back(s.ego.y_m);
    p.series.push_back({std::string("ego: ") + st.label, x, y, st.colour, st.dash, 2.0});
  }
  return svg::render(p);
}

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
  for (const Panel& panel : panels) {
    svg::Plot p;
    p.title = panel.title;
    p.x_label = "time t [s]";
    p.y_label = panel.y_label;
    p.legend = panel.legend;
    for (const PaperRun& r : e.runs) {
      const Style st = style_of(r.planner);
      p.series.push_back({st.label, series(r.trace, [](const TraceStep& s) { return s.time_s; }),
                          series(r.trace, panel.value), st.colour, st.dash, 1.8});
    }
    plots.push_back(std::move(p));
  }
  return svg::render_grid(plots, 2, "Motion states of the ego and obstacle vehicles (cf. paper Fig. 5)");
}

bool paper_results_consistent(const PaperExperiment& e, std::vector<std::string>& why) {
  why.clear();
  for (const PaperRun& r : e.runs) {
    if (!r.metrics.merged) why.push_back(r.planner + " did not complete the merge");
    if (r.metrics.collision) why.push_back(r.planner + " collided");
  }
  const PaperMetrics& base = run_of(e, "tripfield").metrics;
  for (const char* name : {"rcpp", "rcpp-coop"}) {
    const PaperMetrics& m = run_of(e, name).metrics;
    if (m.merge_time_s && base.merge_time_s && *m.merge_time_s > *base.merge_time_s)
      why.push_back(std::string(name) + " merges slower than the baseline");
    if (m.path_length_m && base.path_length_m && *m.path_length_m > *base.path_length_m)
      why.push_back(std::string(name) + " has a longer merge path than the baseline");
  }
  return why.empty();
}

std::string paper_report_markdown(const PaperExperiment& e) {
  const Scenario& s = e.scenario;
  const PaperMetrics& tf = run_of(e, "tripfield").metrics;
  const PaperMetrics& nc = run_of(e, "rcpp").metrics;
  const PaperMetrics& co = run_of(e, "rcpp-coop").metrics;
  const Trace& co_trace = run_of(e, "rcpp-coop").trace;
  const auto save_nc = reduction_pct(tf.merge_time_s, nc.merge_time_s), save_co = reduction_pct(tf.merge_time_s, co.merge_time_s);
  const auto len_nc = reduction_pct(tf.path_length_m, nc.path_length_m), len_co = reduction_pct(tf.path_length_m, co.path_length_m);
  const auto [co_peak_t, co_peak] = sideslip_peak(co_trace);
  const int obstacle_id = s.vehicles.empty() ? -1 : s.vehicles[0].id;
  const auto co_request_s = first_event_s(co_trace, EventKind::kMessageDelivered, obstacle_id);
  const auto co_brake_s = obstacle_first_braking_s(co_trace);
  const auto nc_brake_s = obstacle_first_braking_s(run_of(e, "rcpp").trace);
  auto within = [](const std::optional<double>& v, double target, double tol) { return v && std::abs(*v - target) <= tol; };

  std::ostringstream md;
  md << "# Reproducing the RCPP paper's simulation (arXiv 2403.13251, §IV)\n\n"
     << "Generated by `mergeguard reproduce-paper` from `" << e.scenario_path << "` (" << s.name
     << "). Do not edit: rerun the command.\n\n"
     << "**Scenario.** The paper gives no numbers, only \"initial positions and starting velocities of the ego and "
        "obstacle vehicles relatively close to each other\". Ours: the ego starts in the on-ramp lane at X = "
     << fmt(s.ego.x_m, 1) << " m, " << fmt(s.ego.speed_mps, 1) << " m/s";
  if (!s.vehicles.empty()) {
    const MainVehicle& o = s.vehicles[0];
    md << "; the obstacle vehicle starts on the main lane at X = " << fmt(o.x_m, 1) << " m, " << fmt(o.speed_mps, 1)
       << " m/s, behaviour `" << to_string(o.behaviour.type) << "`, V2V " << (o.v2v.capable ? "capable" : "not capable")
       << " (latency " << fmt(o.v2v.latency_s, 2) << " s)";
  }
  md << "; the on-ramp ends at X = " << fmt(s.road.side_lane_end_x_m, 0) << " m; lane width "
     << fmt(s.road.lane_width_m, 1) << " m; step " << s.params.sim.step_s << " s, planner cycle "
     << s.params.sim.planner_cycle_s << " s, horizon " << s.params.sim.horizon_s << " s.\n\n"
     << "**Definitions.** *Merge time*: from the moment the ego first leaves the on-ramp lane centre "
        "(|Y − Y_side| > 0.1 m) to merge completion (centre within 0.2 m of the main-lane centre and "
        "|ψ| < 0.02 rad). *Path length*: arc length of the ego's centre of gravity over that same interval. "
        "*Saving / reduction* of a planner: 100 (baseline − planner) / baseline, baseline = TriPField-style. "
        "*Lateral reversals*: sign changes of the ego's road-frame lateral speed with a 0.1 m/s dead band over "
        "the whole run (one clean S-shaped merge counts 0). *Collision*: the ego's and a main-lane vehicle's "
        "rectangles overlap at some step. The paper does not define its merge time and path length; these are "
        "our readings.\n\n"
     << "## Paper vs. ours\n\n"
     << "| What | Paper | Ours | Reproduced | Criterion |\n|---|---|---|---|---|\n";
  auto verdict = [&](const std::string& what, const std::string& paper, const std::string& ours, bool yes,
                     const std::string& criterion) {
    md << "| " << what << " | " << paper << " | " << ours << " | " << (yes ? "**yes**" : "**no**") << " | " << criterion
       << " |\n";
  };
  auto pct_pair = [](const std::optional<double>& a, const std::optional<double>& b) {
    return "non-coop " + fmt(a, 1) + " %, coop " + fmt(b, 1) + " %";
  };
  verdict("Merge-time saving of RCPP vs. TriPField", "72.3 %", pct_pair(save_nc, save_co),
          within(save_nc, 72.3, 10.0) || within(save_co, 72.3, 10.0), "a variant within 10 points");
  verdict("Path-length reduction of RCPP vs. TriPField", "53.4 %", pct_pair(len_nc, len_co),
          within(len_nc, 53.4, 10.0) || within(len_co, 53.4, 10.0), "a variant within 10 points");
  verdict("RCPP is faster and shorter than TriPField", "yes", pct_pair(save_nc, save_co) + " / " + pct_pair(len_nc, len_co),
          save_nc > 0.0 && save_co > 0.0 && len_nc > 0.0 && len_co > 0.0, "all four savings > 0");
  verdict("RCPP trajectories do not oscillate", "no oscillation",
          "lateral reversals: non-coop " + std::to_string(nc.lateral_reversals) + ", coop " +
              std::to_string(co.lateral_reversals),
          nc.lateral_reversals == 0 && co.lateral_reversals == 0, "0 reversals each");
  verdict("TriPField weaves before merging", "weaving", "lateral reversals " + std::to_string(tf.lateral_reversals),
          tf.lateral_reversals > 0, "at least 1 reversal");
  verdict("TriPField merge point", "X ≈ 226 m", "X = " + fmt(tf.merge_x_m, 1) + " m", within(tf.merge_x_m, 226.0, 25.0),
          "within 25 m (centre crossing the lane marking)");
  verdict("TriPField sideslip", "oscillates within ±0.02 rad (7.6–9.7 s)",
          fmt(tf.sideslip_min_rad, 4) + " … " + fmt(tf.sideslip_max_rad, 4) + " rad",
          tf.sideslip_max_rad <= 0.02 && tf.sideslip_min_rad >= -0.02 && tf.lateral_reversals > 0,
          "within ±0.02 rad and weaving");
  verdict("TriPField: obstacle speed minimum", "below 10 m/s", fmt(tf.obstacle_speed_min_mps, 1) + " m/s",
          tf.obstacle_speed_min_mps < 10.0, "below 10 m/s");
  verdict("TriPField: ego speed minimum", "below 9 m/s", fmt(tf.ego_speed_min_mps, 1) + " m/s", tf.ego_speed_min_mps < 9.0,
          "below 9 m/s");
  verdict("Non-coop RCPP sideslip", "−0.012 … 0.016 rad", fmt(nc.sideslip_min_rad, 4) + " … " + fmt(nc.sideslip_max_rad, 4) + " rad",
          nc.sideslip_min_rad >= -0.02 && nc.sideslip_max_rad <= 0.02, "within ±0.02 rad");
  verdict("Non-coop RCPP ego speed", "briefly 30 m/s, then 20 m/s",
          fmt(nc.ego_speed_min_mps, 1) + " … " + fmt(nc.ego_speed_max_mps, 1) + " m/s", nc.ego_speed_max_mps > 27.0,
          "peak above 27 m/s");
  verdict("Non-coop RCPP: obstacle slows gradually", "to about 16 m/s",
          "minimum " + fmt(nc.obstacle_speed_min_mps, 1) + " m/s, first braking at " + fmt(nc_brake_s, 1) + " s",
          nc_brake_s.has_value() && within(nc.obstacle_speed_min_mps, 16.0, 2.0), "brakes, minimum within 2 m/s of 16");
  verdict("Coop RCPP sideslip peak", "0.024 rad at 7.1 s", fmt(co_peak, 4) + " rad at " + fmt(co_peak_t, 1) + " s",
          std::abs(co_peak) <= 0.03 && std::abs(co_peak) > std::max(std::abs(nc.sideslip_min_rad), std::abs(nc.sideslip_max_rad)),
          "larger than non-coop's peak, at most 0.03 rad");
  verdict("Coop RCPP ego speed", "steady", fmt(co.ego_speed_min_mps, 1) + " … " + fmt(co.ego_speed_max_mps, 1) + " m/s",
          co.ego_speed_max_mps - co.ego_speed_min_mps < 2.0, "range below 2 m/s");
  verdict("Coop RCPP: obstacle slows early, after the message", "early deceleration",
          "request delivered at " + fmt(co_request_s, 2) + " s, obstacle brakes from " + fmt(co_brake_s, 2) +
              " s, minimum " + fmt(co.obstacle_speed_min_mps, 1) + " m/s",
          co_request_s && co_brake_s && *co_brake_s >= *co_request_s && (!nc_brake_s || *co_brake_s < *nc_brake_s),
          "brakes after the request, earlier than in the non-coop run");
  md << "\n"
     << "\"Reproduced\" is judged mechanically by the criterion in the last column. Absolute "
        "values depend on the scenario, which the paper does not publish, and on the baseline, of which no code "
        "exists (see docs/planner.md).\n\n"
     << "## Our measurements\n\n"
     << "| Metric | TriPField-style | RCPP non-coop | RCPP coop |\n|---|---|---|---|\n";
  auto row = [&](const char* name, auto get) {
    md << "| " << name << " | " << get(tf) << " | " << get(nc) << " | " << get(co) << " |\n";
  };
  row("merged", [](const PaperMetrics& m) { return std::string(m.merged ? "yes" : "no"); });
  row("collision", [](const PaperMetrics& m) { return std::string(m.collision ? "yes" : "no"); });
  row("merge start [s]", [](const PaperMetrics& m) { return fmt(m.merge_start_time_s); });
  row("merge time [s]", [](const PaperMetrics& m) { return fmt(m.merge_time_s); });
  row("path length [m]", [](const PaperMetrics& m) { return fmt(m.path_length_m, 1); });
  row("merge point X [m]", [](const PaperMetrics& m) { return fmt(m.merge_x_m, 1); });
  row("lateral reversals", [](const PaperMetrics& m) { return std::to_string(m.lateral_reversals); });
  row("sideslip min/max [rad]", [](const PaperMetrics& m) { return fmt(m.sideslip_min_rad, 4) + " / " + fmt(m.sideslip_max_rad, 4); });
  row("yaw min/max [rad]", [](const PaperMetrics& m) { return fmt(m.yaw_min_rad, 4) + " / " + fmt(m.yaw_max_rad, 4); });
  row("ego speed min/max [m/s]", [](const PaperMetrics& m) { return fmt(m.ego_speed_min_mps, 1) + " / " + fmt(m.ego_speed_max_mps, 1); });
  row("obstacle speed min [m/s]", [](const PaperMetrics& m) { return fmt(m.obstacle_speed_min_mps, 1); });
  if (!e.sensitivity.empty()) {
    md << "\n## Sensitivity to the scenario\n\n"
          "The paper publishes no scenario numbers, so ours is a choice. The same comparison with the obstacle "
          "vehicle started dx metres further along and dv m/s faster (its desired speed too); T = merge time [s], "
          "saving and reduction against the baseline in %, n/a = did not merge:\n\n"
          "| dx [m] | dv [m/s] | T TriPField | T RCPP | T coop | time saving RCPP / coop | path reduction RCPP / coop | "
          "collision (TF/RCPP/coop) |\n|---|---|---|---|---|---|---|---|\n";
    for (const SensitivityCase& c : e.sensitivity) {
      const PaperMetrics &b = c.metrics[0], &r = c.metrics[1], &k = c.metrics[2];
      md << "| " << fmt(c.dx_m, 0) << " | " << fmt(c.dv_mps, 0) << " | " << fmt(b.merge_time_s) << " | "
         << fmt(r.merge_time_s) << " | " << fmt(k.merge_time_s) << " | "
         << fmt(reduction_pct(b.merge_time_s, r.merge_time_s), 1) << " / "
         << fmt(reduction_pct(b.merge_time_s, k.merge_time_s), 1) << " | "
         << fmt(reduction_pct(b.path_length_m, r.path_length_m), 1) << " / "
         << fmt(reduction_pct(b.path_length_m, k.path_length_m), 1) << " | " << (b.collision ? "yes" : "no") << "/"
         << (r.collision ? "yes" : "no") << "/" << (k.collision ? "yes" : "no") << " |\n";
    }
  }
  md << "\nFigures: [fig4_paths.svg](fig4_paths.svg) (X–Y paths, cf. paper Fig. 4) and "
        "[fig5_motion.svg](fig5_motion.svg) (sideslip, yaw, obstacle speed, ego speed, cf. paper Fig. 5). "
        "All numbers: [metrics.json](metrics.json).\n\n## Planner decisions\n\n";
  for (const PaperRun& r : e.runs) {
    md << "- **" << r.planner << "**:";
    int shown = 0;
    for (const TraceEvent& ev : r.trace.events)
      if (ev.kind == EventKind::kDecision || ev.kind == EventKind::kMessageSent || ev.kind == EventKind::kMergeComplete) {
        if (++shown > 8) {
          md << " …";
          break;
        }
        md << " t = " << fmt(ev.time_s, 1) << " s " << to_string(ev.kind) << " (" << ev.detail << ");";
      }
    md << "\n";
  }
  std::vector<std::string> why;
  md << "\n## Consistency\n\n";
  if (paper_results_consistent(e, why)) {
    md << "Every planner merged without collision, and both RCPP variants merge no slower and along no longer a "
          "path than the baseline.\n";
  } else {
    for (const std::string& w : why) md << "- " << w << "\n";
  }
  return md.str();
}

void write_paper_report(const PaperExperiment& e, const std::string& out_dir) {
  const std::string dir = out_dir.empty() || out_dir.back() == '/' ? out_dir : out_dir + "/";
  write_files_atomic({{dir + "metrics.json", paper_metrics_json(e).dump(2) + "\n"},
                      {dir + "fig4_paths.svg", fig4_paths_svg(e)},
                      {dir + "fig5_motion.svg", fig5_motion_svg(e)},
                      {dir + "report.md", paper_report_markdown(e)}});
}

}  // namespace mg
