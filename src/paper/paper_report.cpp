#include "paper/paper_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "check/checked_run.h"
#include "core/atomic_file.h"
#include "core/fixed_text.h"
#include "core/party.h"
#include "paper/paper_figures.h"
#include "paper/paper_variant.h"
#include "planner/planner.h"
#include "sim/simulator.h"

namespace mg {
namespace {

// The paper's wording for a right-of-way holder (prose, unlike party_name's report labels).
std::string holder_name(Party holder) {
  if (holder.is_ego()) return "the ego";
  if (holder.is_main_lane()) return "the main lane";
  if (holder.is_nobody()) return "nobody";
  return "vehicle " + std::to_string(holder.vehicle_id());
}

}  // namespace

const PaperRun& paper_run_of(const PaperExperiment& e, const std::string& planner) {
  for (const PaperRun& r : e.runs)
    if (r.planner == planner) return r;
  throw std::logic_error("no run of planner " + planner);
}

std::vector<PaperRun> run_paper_planners(const Scenario& s, bool with_right_of_way) {
  std::vector<PaperRun> runs;
  for (const std::string& name : kPaperPlanners) {
    std::unique_ptr<Planner> planner = make_planner(name);
    if (!planner) throw std::logic_error("planner '" + name + "' is not registered");
    Trace trace = simulate(s, *planner);
    PaperMetrics metrics = compute_paper_metrics(s, trace);
    std::vector<std::pair<double, Party>> holders;
    if (with_right_of_way) holders = check_trace(s, trace).right_of_way;
    runs.push_back({name, std::move(trace), metrics, std::move(holders)});
  }
  return runs;
}

PaperExperiment run_paper_experiment(const Scenario& s, const std::string& scenario_path, bool with_right_of_way) {
  PaperExperiment e{s, scenario_path, {}, {}, {}, {}};
  e.runs = run_paper_planners(s, with_right_of_way);
  if (s.vehicles.empty()) return e;
  e.variant_scenario = s;
  e.variant_scenario.vehicles.resize(1);
  e.variant_runs = run_cruise_variant(e.variant_scenario);
  for (double dv : {-2.0, 0.0, 2.0})
    for (double dx : {-12.0, -6.0, 0.0, 6.0, 12.0}) {
      Scenario variant = s;
      MainVehicle& o = variant.vehicles[0];
      o.x_m += dx;
      o.speed_mps = std::max(0.0, o.speed_mps + dv);
      if (o.behaviour.desired_speed_mps >= 0.0) o.behaviour.desired_speed_mps = std::max(0.0, o.behaviour.desired_speed_mps + dv);
      SensitivityCase c{dx, dv, {}, 0};
      const std::vector<PaperRun> runs = run_paper_planners(variant);
      for (const PaperRun& r : runs) c.metrics.push_back(r.metrics);
      c.claims_reproduced = reproduced_count(paper_claims(variant, runs));
      e.sensitivity.push_back(std::move(c));
    }
  return e;
}

nlohmann::json paper_metrics_json(const PaperExperiment& e) {
  nlohmann::json planners = nlohmann::json::object(), saving = nlohmann::json::object(),
                 shorter = nlohmann::json::object();
  const PaperMetrics& base = paper_run_of(e, "tripfield").metrics;
  for (const PaperRun& r : e.runs) {
    planners[r.planner] = paper_metrics_to_json(r.metrics);
    if (r.planner == "tripfield") continue;
    saving[r.planner] = or_null(reduction_pct(base.merge_time_s, r.metrics.merge_time_s));
    shorter[r.planner] = or_null(reduction_pct(base.path_length_m, r.metrics.path_length_m));
  }
  nlohmann::json claims = nlohmann::json::array(), holders = nlohmann::json::object();
  const std::vector<PaperClaim> judged = paper_claims(e.scenario, e.runs);
  for (const PaperClaim& c : judged)
    claims.push_back({{"what", c.what}, {"paper", c.paper}, {"ours", c.ours}, {"reproduced", c.reproduced},
                      {"criterion", c.criterion}});
  for (const PaperRun& r : e.runs) {
    holders[r.planner] = nlohmann::json::array();
    for (const auto& [t, holder] : r.right_of_way)
      holders[r.planner].push_back({{"time_s", t}, {"holder", holder_name(holder)}});
  }
  return {{"scenario", e.scenario_path},
          {"planners", planners},
          {"claims", claims},
          {"claims_reproduced", reproduced_count(judged)},
          {"right_of_way", holders},
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

bool paper_results_consistent(const PaperExperiment& e, std::vector<std::string>& why) {
  why.clear();
  for (const PaperRun& r : e.runs) {
    if (!r.metrics.merged) why.push_back(r.planner + " did not complete the merge");
    if (r.metrics.collision) why.push_back(r.planner + " collided");
  }
  const PaperMetrics& base = paper_run_of(e, "tripfield").metrics;
  for (const char* name : {"rcpp", "rcpp-coop"}) {
    const PaperMetrics& m = paper_run_of(e, name).metrics;
    if (m.merge_time_s && base.merge_time_s && *m.merge_time_s > *base.merge_time_s)
      why.push_back(std::string(name) + " merges slower than the baseline");
    if (m.path_length_m && base.path_length_m && *m.path_length_m > *base.path_length_m)
      why.push_back(std::string(name) + " has a longer merge path than the baseline");
  }
  return why.empty();
}

namespace {

struct Spread {
  std::optional<double> median, lo, hi;
  int n = 0;
};

// Median (the mean of the middle two for an even count) and range of the values present.
Spread spread_of(std::vector<double> v) {
  Spread out;
  out.n = static_cast<int>(v.size());
  if (v.empty()) return out;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  out.median = v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
  out.lo = v.front();
  out.hi = v.back();
  return out;
}

std::string spread_text(const Spread& sp) {
  if (!sp.median) return "n/a";
  return fixed_or_na(*sp.median, 1) + " % (" + fixed_or_na(*sp.lo, 1) + " … " + fixed_or_na(*sp.hi, 1) +
         ", n = " + std::to_string(sp.n) + ")";
}

// The abstract's two headline numbers: on the chosen scenario and over the sensitivity grid.
std::string headline_spread_markdown(const PaperExperiment& e) {
  std::ostringstream md;
  const PaperMetrics& tf = paper_run_of(e, "tripfield").metrics;
  md << "\n## Headline numbers and their spread\n\n"
     << "Against the TriPField-style baseline; the grid is the sensitivity grid below (median, range and the number "
        "of variants in which both planners merged).\n\n"
     << "| | Paper | RCPP non-coop, this scenario | non-coop, grid | RCPP coop, this scenario | coop, grid |\n"
     << "|---|---|---|---|---|---|\n";
  for (const bool time : {true, false}) {
    md << "| " << (time ? "merge-time saving" : "path-length reduction") << " | " << (time ? "72.3 %" : "53.4 %");
    for (std::size_t k = 1; k <= 2; ++k) {
      const PaperMetrics& m = e.runs[k].metrics;
      const auto here = time ? reduction_pct(tf.merge_time_s, m.merge_time_s) : reduction_pct(tf.path_length_m, m.path_length_m);
      std::vector<double> grid;
      for (const SensitivityCase& c : e.sensitivity) {
        const PaperMetrics &b = c.metrics[0], &v = c.metrics[k];
        const auto x = time ? reduction_pct(b.merge_time_s, v.merge_time_s) : reduction_pct(b.path_length_m, v.path_length_m);
        if (x) grid.push_back(*x);
      }
      md << " | " << fixed_or_na(here, 1) << " % | " << spread_text(spread_of(grid));
    }
    md << " |\n";
  }
  return md.str();
}

// The claims on the report-only variant, beside the defaults' verdicts.
std::string variant_markdown(const PaperExperiment& e) {
  if (e.variant_runs.empty()) return "";
  std::ostringstream md;
  const std::vector<PaperClaim> ours = paper_claims(e.scenario, e.runs);
  const std::vector<PaperClaim> variant = paper_claims(e.variant_scenario, e.variant_runs);
  md << "\n## Variant, not the defaults: RCPP keeping its lane at the cruise speed\n\n"
     << "**Changed planner behaviour, shown only here** (src/paper/paper_variant.h; the fuzzer, `check` and the table "
        "above use the planners unchanged). After the merge both RCPP variants keep their lane at the ego's initial "
        "speed ("
     << fixed_or_na(e.variant_scenario.ego.speed_mps, 1) << " m/s) instead of the speed limit ("
     << fixed_or_na(e.variant_scenario.road.speed_limit_mps, 2)
     << " m/s), as the TriPField-style baseline does; the scenario "
        "is ours with the obstacle only ("
     << e.variant_scenario.vehicles.size()
     << " main-lane vehicle). "
        "It shows what the rows that need a lead vehicle, or do not reproduce, would need from the planner.\n\n"
     << "| What | Criterion | Defaults, this scenario | Variant | Variant: ours |\n|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < variant.size(); ++i)
    md << "| " << variant[i].what << " | " << variant[i].criterion << " | " << (ours[i].reproduced ? "yes" : "no")
       << " | " << (variant[i].reproduced ? "**yes**" : "**no**") << " | " << variant[i].ours << " |\n";
  md << "\nThe variant reproduces " << reproduced_count(variant) << " of " << variant.size() << " rows.\n";
  return md.str();
}

std::string sensitivity_markdown(const PaperExperiment& e) {
  std::ostringstream md;
  if (e.sensitivity.empty()) return "";
  md << "\n## Sensitivity to the scenario\n\n"
        "The paper publishes no scenario numbers, so ours is a choice. The same comparison with the obstacle "
        "vehicle started dx metres further along and dv m/s faster (its desired speed too); T = merge time [s], "
        "saving and reduction against the baseline in %, n/a = did not merge; rows = rows of the table above "
        "that reproduce on that variant:\n\n"
        "| dx [m] | dv [m/s] | T TriPField | T RCPP | T coop | time saving RCPP / coop | path reduction RCPP / coop | "
        "collision (TF/RCPP/coop) | rows |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const SensitivityCase& c : e.sensitivity) {
    const PaperMetrics &b = c.metrics[0], &r = c.metrics[1], &k = c.metrics[2];
    md << "| " << fixed_or_na(c.dx_m, 0) << " | " << fixed_or_na(c.dv_mps, 0) << " | " << fixed_or_na(b.merge_time_s)
       << " | " << fixed_or_na(r.merge_time_s) << " | " << fixed_or_na(k.merge_time_s) << " | "
       << fixed_or_na(reduction_pct(b.merge_time_s, r.merge_time_s), 1) << " / "
       << fixed_or_na(reduction_pct(b.merge_time_s, k.merge_time_s), 1) << " | "
       << fixed_or_na(reduction_pct(b.path_length_m, r.path_length_m), 1) << " / "
       << fixed_or_na(reduction_pct(b.path_length_m, k.path_length_m), 1) << " | " << (b.collision ? "yes" : "no")
       << "/" << (r.collision ? "yes" : "no") << "/" << (k.collision ? "yes" : "no") << " | " << c.claims_reproduced
       << " |\n";
  }
  return md.str();
}

// Each run's right-of-way timeline as the rule checker computes it (CheckResult::right_of_way).
std::string right_of_way_markdown(const PaperExperiment& e) {
  std::ostringstream md;
  md << "\n## Right of way\n\n"
        "Who held the right of way, as the rule checker computes it (rules/liability.h: the main-lane traffic "
        "until the ego has a Def. 1 merge decision or a delivered Def. 2 acceptance; the ego until its merge "
        "completes or aborts); see [fig_right_of_way.svg](fig_right_of_way.svg).\n\n";
  for (const PaperRun& r : e.runs) {
    md << "- **" << r.planner << "**:";
    if (r.right_of_way.empty()) md << " not computed";
    for (const auto& [t, holder] : r.right_of_way)
      md << " from " << fixed_or_na(t, 2) << " s " << holder_name(holder) << ";";
    md << "\n";
  }
  return md.str();
}

}  // namespace

// Our figures, each under what the paper's §IV says of its own (quoted, abridged).
std::string figures_markdown() {
  return "\n## Figures beside the paper's description\n\n"
         "**Fig. 4** (paper): \"The ego vehicle with TriPField-based Planner (depicted by the dashed green line) merges "
         "into the lane from an entry point that appears around X=226 m. The path towards merging (highlighted area) "
         "shows significant deviation and weaving [...] the ego vehicle successfully merges behind the obstacle "
         "vehicle. [...] the non-cooperative RCPP planner (brown dotted line) merges into the lane with less deviation "
         "[...] the close proximity to the obstacle vehicle suggests a potentially aggressive [...] merging strategy "
         "[...] Cooperative RCPP [...] shows a smooth transition into the lane with minimal deviations.\" Ours, with "
         "each planner's merge zone shaded and the obstacle's footprint at each ego's crossing of the lane marking:"
         "\n\n![Lane-merge paths](fig4_paths.svg)\n\n"
         "**Fig. 5** (paper): \"the TriPField-based planner [...] oscillates between 7.6 s and 9.7 s with an amplitude "
         "below ±0.02 rad. [...] the non-cooperative RCPP planner [...] maintains a steadier sideslip between -0.012 rad "
         "and 0.016 rad, whereas the cooperative RCPP planner [...] peaks at 0.024 rad at 7.1 s [...] the obstacle "
         "vehicle using the TriPField-based planner decelerates sharply below 10 m/s, whereas the non-cooperative RCPP "
         "planner decelerates more gradually to around 16 m/s. The cooperative RCPP planner decelerates early [...] "
         "after receiving a cooperation message. [...] the TriPField planner decelerates sharply to under 9 m/s, the "
         "non-cooperative RCPP planner briefly accelerates to 30 m/s then slows to 20 m/s post-merging, while the "
         "cooperative RCPP planner maintains a steady speed.\" Ours, with those ranges shaded in each planner's tint "
         "(panel b: the paper gives no numbers):\n\n![Motion states](fig5_motion.svg)\n\n"
         "**Right of way** (not in the paper; the rule checker's timeline, see below):\n\n"
         "![Right of way](fig_right_of_way.svg)\n";
}

// Not one of the fifteen rows, but the paper's Fig. 4 says it: on which side of the obstacle
// each ego crossed the lane marking (ego X minus obstacle X at that instant).
std::string crossing_sides_markdown(const PaperExperiment& e) {
  if (e.scenario.vehicles.empty()) return "";
  std::ostringstream md;
  md << "*Not scored:* where each ego crossed the lane marking relative to the obstacle (the paper: TriPField "
        "behind it, non-coop RCPP close ahead of it, coop RCPP ahead of it after it yielded):";
  for (const PaperRun& r : e.runs) {
    const auto crossing = first_event_s(r.trace, EventKind::kMergeMidpoint, 0);
    md << " " << planner_style(r.planner).label << " ";
    if (!crossing) {
      md << "did not cross;";
      continue;
    }
    for (const TraceStep& st : r.trace.steps)
      if (st.time_s >= *crossing - 1e-9) {
        const double ahead_m = st.ego.x_m - st.others[0].x_m;
        md << (ahead_m >= 0.0 ? "ahead by " : "behind by ") << fixed_or_na(std::abs(ahead_m), 1) << " m;";
        break;
      }
  }
  md << "\n";
  return md.str();
}

std::string paper_report_markdown(const PaperExperiment& e) {
  const Scenario& s = e.scenario;
  const PaperMetrics& tf = paper_run_of(e, "tripfield").metrics;
  const PaperMetrics& nc = paper_run_of(e, "rcpp").metrics;
  const PaperMetrics& co = paper_run_of(e, "rcpp-coop").metrics;

  std::ostringstream md;
  md << "# Reproducing the RCPP paper's simulation (arXiv 2403.13251, §IV)\n\n"
     << "Generated by `mergeguard reproduce-paper` from `" << e.scenario_path << "` (" << s.name
     << "). Do not edit: rerun the command.\n\n"
     << "**Scenario.** The paper gives no numbers, only \"initial positions and starting velocities of the ego and "
        "obstacle vehicles relatively close to each other\". Ours (`reproduce-paper --search` found it; "
        "docs/paper_reproduction.md): the ego starts in the on-ramp lane at X = "
     << fixed_or_na(s.ego.x_m, 1) << " m, " << fixed_or_na(s.ego.speed_mps, 1) << " m/s";
  if (!s.vehicles.empty()) {
    const MainVehicle& o = s.vehicles[0];
    md << "; the obstacle vehicle starts on the main lane at X = " << fixed_or_na(o.x_m, 1) << " m, "
       << fixed_or_na(o.speed_mps, 1) << " m/s, behaviour `" << to_string(o.behaviour.type) << "`, V2V "
       << (o.v2v.capable ? "capable" : "not capable") << " (latency " << fixed_or_na(o.v2v.latency_s, 2)
       << " s), a_accel^max " << fixed_or_na(o.limits.accel_max_mps2, 1) << " m/s², a_brake^min "
       << fixed_or_na(o.limits.brake_min_mps2, 1) << " m/s², IDM headway " << fixed_or_na(o.behaviour.time_headway_s, 1)
       << " s";
    for (std::size_t i = 1; i < s.vehicles.size(); ++i)
      md << "; main-lane vehicle " << s.vehicles[i].id << " at X = " << fixed_or_na(s.vehicles[i].x_m, 1) << " m, "
         << fixed_or_na(s.vehicles[i].speed_mps, 1) << " m/s, `" << to_string(s.vehicles[i].behaviour.type) << "`";
    md << "; ego V2V latency " << fixed_or_na(s.ego.v2v.latency_s, 2) << " s";
  }
  md << "; the on-ramp ends at X = " << fixed_or_na(s.road.side_lane_end_x_m, 0) << " m; lane width "
     << fixed_or_na(s.road.lane_width_m, 1) << " m; step " << s.params.sim.step_s << " s, planner cycle "
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
  const std::vector<PaperClaim> claims = paper_claims(s, e.runs);
  for (const PaperClaim& c : claims)
    md << "| " << c.what << " | " << c.paper << " | " << c.ours << " | " << (c.reproduced ? "**yes**" : "**no**") << " | "
       << c.criterion << " |\n";
  md << "\n**" << reproduced_count(claims) << " of " << claims.size() << " rows reproduce.**";
  for (const PaperClaim& c : claims)
    if (!c.reproduced)
      md << " " << c.what << ": not reproduced" << (c.why_not.empty() ? "" : "; " + c.why_not) << ".";
  md << " Why, in detail: docs/paper_reproduction.md.\n\n" << crossing_sides_markdown(e);
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
  row("merge start [s]", [](const PaperMetrics& m) { return fixed_or_na(m.merge_start_time_s); });
  row("merge time [s]", [](const PaperMetrics& m) { return fixed_or_na(m.merge_time_s); });
  row("path length [m]", [](const PaperMetrics& m) { return fixed_or_na(m.path_length_m, 1); });
  row("merge point X [m]", [](const PaperMetrics& m) { return fixed_or_na(m.merge_x_m, 1); });
  row("lateral reversals", [](const PaperMetrics& m) { return std::to_string(m.lateral_reversals); });
  row("sideslip min/max [rad]", [](const PaperMetrics& m) {
    return fixed_or_na(m.sideslip_min_rad, 4) + " / " + fixed_or_na(m.sideslip_max_rad, 4);
  });
  row("yaw min/max [rad]",
      [](const PaperMetrics& m) { return fixed_or_na(m.yaw_min_rad, 4) + " / " + fixed_or_na(m.yaw_max_rad, 4); });
  row("ego speed min/max [m/s]", [](const PaperMetrics& m) {
    return fixed_or_na(m.ego_speed_min_mps, 1) + " / " + fixed_or_na(m.ego_speed_max_mps, 1);
  });
  row("obstacle speed min [m/s]", [](const PaperMetrics& m) { return fixed_or_na(m.obstacle_speed_min_mps, 1); });
  md << headline_spread_markdown(e) << variant_markdown(e) << sensitivity_markdown(e) << right_of_way_markdown(e);
  md << figures_markdown() << "\nAll numbers: [metrics.json](metrics.json).\n\n## Planner decisions\n\n";
  for (const PaperRun& r : e.runs) {
    md << "- **" << r.planner << "**:";
    int shown = 0;
    for (const TraceEvent& ev : r.trace.events)
      if (ev.kind == EventKind::kDecision || ev.kind == EventKind::kMessageSent || ev.kind == EventKind::kMergeComplete) {
        if (++shown > 8) {
          md << " …";
          break;
        }
        md << " t = " << fixed_or_na(ev.time_s, 1) << " s " << to_string(ev.kind) << " (" << ev.detail << ");";
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
                      {dir + "fig_right_of_way.svg", right_of_way_svg(e)},
                      {dir + "report.md", paper_report_markdown(e)}});
}

}  // namespace mg
