#include "league/league_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "check/checked_run.h"
#include "core/atomic_file.h"
#include "core/fixed_text.h"
#include "fuzz/corpus_case.h"
#include "league/league_stats.h"
#include "planner/exec_planner.h"
#include "planner/planner_fault.h"
#include "report/report_json.h"
#include "report/svg_plot.h"

namespace mg::league {
namespace {

using json = nlohmann::json;

json or_null(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

std::string percent(double share) { return fixed_text(100.0 * share, 1) + " %"; }

std::string share_with_interval(const PlannerStanding& s) {
  const Interval ci = wilson_interval(s.failing, s.scenarios);
  return percent(s.failing_share()) + " [" + fixed_text(100.0 * ci.lo, 1) + ", " + fixed_text(100.0 * ci.hi, 1) + "]";
}

// "a 12, b 7, c 3 (+2 more)": the largest counts first.
std::string top_counts(const std::map<std::string, std::uint64_t>& counts, std::size_t shown) {
  std::vector<std::pair<std::string, std::uint64_t>> sorted(counts.begin(), counts.end());
  std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string out;
  for (std::size_t k = 0; k < std::min(shown, sorted.size()); ++k)
    out += (k > 0 ? ", " : "") + sorted[k].first + " " + std::to_string(sorted[k].second);
  if (sorted.size() > shown) out += " (+" + std::to_string(sorted.size() - shown) + " more)";
  return out.empty() ? "none" : out;
}

std::optional<double> median(const std::vector<double>& v) { return quantile(v, 0.5); }
std::optional<double> p95(const std::vector<double>& v) { return quantile(v, 0.95); }

// The Tableau 10 palette: distinct for ten planners, and kind to colour-blind readers.
const char* colour_of(std::size_t k) {
  static const char* const kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                         "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return kPalette[k % std::size(kPalette)];
}

std::string headline(const LeagueOptions& o, const LeagueResult& r) {
  std::ostringstream out;
  out << r.scenarios << " scenarios (seed " << o.seed << ", "
      << (o.runs ? std::to_string(*o.runs) + " runs" : "a budget of " + fixed_text(o.time_s.value_or(0.0), 0) + " s") << ", "
      << (o.gen.targeted_families ? "mixed" : "uniform") << " families, up to " << o.gen.max_vehicles
      << " vehicles), each driven by the " << r.standings.size() << " planners, in " << fixed_text(r.seconds, 1)
      << " s (--jobs " << o.jobs << ")" << (r.interrupted ? ", interrupted" + (r.stop_signal.empty() ? "" : " by " + r.stop_signal) : "")
      << ".";
  return out.str();
}

// What the columns mean (docs/league.md says the same).
const std::vector<std::string>& column_notes() {
  static const std::vector<std::string> notes = {
      "failing: runs in which a property of mergeguard fuzz failed (the ego liable for a broken rule, an unsafe "
      "state toward compliant traffic, a collision nobody is liable for, the side lane's end passed, oscillation, "
      "no progress, a planner that does not respond, a check that throws); the share's interval is Wilson's 95 % "
      "score interval.",
      "merge rate: runs in which the observed ego completed its merge (within 0.2 m of the main lane's centre, "
      "heading straight: the rules' merge phases), whatever the planner said.",
      "merge time: from the run's start to that completion, over the merged runs (median, 95th percentile).",
      "path length: the ego's arc length over the completed merge, from the observed start of that attempt to its "
      "completion.",
      "peak lat. accel.: each run's largest |dv_Y/dt| between consecutive steps, road frame (median over the runs).",
      "halted: time with the ego's speed below the rules' halted speed, mean over the runs.",
      "top failing rules and liable parties: failing runs by the rule, and by the class of the party, of their "
      "failures (a run counts once per rule and per party; the tables below have all of them).",
  };
  return notes;
}

}  // namespace

SavedCases save_worst_cases(const std::string& dir, const LeagueOptions& o, const LeagueResult& r) {
  SavedCases saved;
  for (const PlannerStanding& s : r.standings)
    for (const auto& [sig, worst] : s.worst) {
      const std::string planner = s.planner;
      const fuzz::CheckFn check = [planner](const Scenario& scenario) { return check_scenario(scenario, planner); };
      fuzz::CorpusCase c;
      c.signature = sig;
      c.scenario = fuzz::generate_scenario(fuzz::run_seed(o.seed, worst.run), o.gen).value();
      c.scenario.name = sig.file_stem();
      c.scenario.description = "The worst run of its signature in mergeguard league (seed " + std::to_string(o.seed) + ", run " +
                               std::to_string(worst.run) + "), not shrunk.";
      const fuzz::RunOutcome rerun = fuzz::run_properties(c.scenario, check, planner, /*check_determinism=*/true);
      c.verdict = fuzz::verdict_of(rerun);
      c.failure = worst.failure;
      c.provenance = {"mergeguard league", o.seed, worst.run, 0, 0, false, fuzz::utc_now_iso8601()};
      c.planner_hello = exec_planner_identity(planner);
      const std::string rel = "cases/" + sig.file_stem();
      fuzz::write_case(c, dir + "/" + rel + ".json");
      SavedCase& out = saved[sig];
      out.case_path = rel + ".json";
      if (sig.property == fuzz::property::kPlannerResponds || sig.property == fuzz::property::kCheckCompletes)
        continue;  // no run to report on
      try {
        write_check_reports(dir + "/" + rel, check_scenario(c.scenario, planner, PlannerAccount::kDecisions));
        out.liability_report = rel + "/report.html";
      } catch (const PlannerFault&) {  // an exec planner that fails only in this run (a timeout on a loaded machine)
      }
    }
  return saved;
}

ReportTable standings_table(const LeagueResult& r) {
  ReportTable t{{"planner", "scenarios", "failing", "failing share [95 % CI]", "merge rate", "merge time median (s)",
                 "merge time p95 (s)", "path length median (m)", "peak lat. accel. median (m/s2)", "halted mean (s)",
                 "top failing rules", "liable parties"},
                {}};
  for (const PlannerStanding& s : r.standings)
    t.rows.push_back({s.planner, std::to_string(s.scenarios), std::to_string(s.failing), share_with_interval(s),
                      percent(s.merge_rate()), fixed_or_na(median(s.merge_times_s), 1), fixed_or_na(p95(s.merge_times_s), 1),
                      fixed_or_na(median(s.path_lengths_m), 1), fixed_or_na(median(s.peak_lat_accels_mps2), 2),
                      fixed_or_na(s.mean_halted_s(), 2), top_counts(s.by_rule, 3), top_counts(s.by_party, 3)});
  return t;
}

ReportTable failures_table(const LeagueResult& r, bool by_party) {
  ReportTable t{{by_party ? "liable party" : "rule"}, {}};
  std::set<std::string> keys;
  for (const PlannerStanding& s : r.standings) {
    t.header.push_back(s.planner);
    for (const auto& [key, n] : by_party ? s.by_party : s.by_rule) keys.insert(key);
  }
  for (const std::string& key : keys) {
    std::vector<std::string> row{key};
    for (const PlannerStanding& s : r.standings) {
      const auto& counts = by_party ? s.by_party : s.by_rule;
      const auto it = counts.find(key);
      row.push_back(it == counts.end() ? "0" : std::to_string(it->second));
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string safety_efficiency_svg(const LeagueResult& r) {
  svg::Plot plot = svg::frame("", "median merge time [s]", "failing share [%], 95 % Wilson interval", 720, 420);
  struct Point {
    double x, y;
    std::string names;
    std::string colour;
  };
  std::vector<Point> points;
  double x_hi = 1.0, y_hi = 1.0;
  for (std::size_t k = 0; k < r.standings.size(); ++k) {
    const PlannerStanding& s = r.standings[k];
    const std::optional<double> m = median(s.merge_times_s);
    if (!m) continue;  // never merged: no merge time to place it at
    const Interval ci = wilson_interval(s.failing, s.scenarios);
    plot.series.push_back({"", {*m, *m}, {100.0 * ci.lo, 100.0 * ci.hi}, colour_of(k), "", 2.0});
    plot.series.push_back({"", {*m}, {100.0 * s.failing_share()}, colour_of(k), "", 1.6, 5.0});
    points.push_back({*m, 100.0 * s.failing_share(), s.planner, colour_of(k)});
    x_hi = std::max(x_hi, *m);
    y_hi = std::max(y_hi, 100.0 * ci.hi);
  }
  // Room on the right for the names, and below 0 for a whole marker at a share of 0.
  plot.x_range = svg::Range{0.0, x_hi * 1.3};
  const double y_top = std::min(100.0, y_hi * 1.1);
  plot.y_range = svg::Range{-0.03 * y_top, y_top};
  // Each point named beside it; planners within 1 % of the axes of one another share one name line.
  std::vector<Point> named;
  for (const Point& p : points) {
    auto same = std::find_if(named.begin(), named.end(), [&](const Point& q) {
      return std::abs(q.x - p.x) < 0.01 * plot.x_range->hi && std::abs(q.y - p.y) < 0.01 * plot.y_range->hi;
    });
    if (same == named.end()) {
      named.push_back(p);
    } else {
      same->names += ", " + p.names;
      same->colour = "#333333";
    }
  }
  for (const Point& p : named) plot.notes.push_back({p.x, p.y, p.names, p.colour});
  return svg::render(plot);
}

json league_json(const LeagueOptions& o, const LeagueResult& r, const SavedCases& saved) {
  json planners = json::array();
  for (const PlannerStanding& s : r.standings) {
    const Interval ci = wilson_interval(s.failing, s.scenarios);
    json worst = json::array();
    for (const auto& [sig, w] : s.worst) {
      const auto it = saved.find(sig);
      const bool has = it != saved.end();
      worst.push_back({{"signature", sig.key()}, {"property", sig.property}, {"rule", sig.rule}, {"party", sig.party},
                       {"scenarios", w.scenarios}, {"run", w.run}, {"margin", w.margin},
                       {"case", has ? json(it->second.case_path) : json(nullptr)},
                       {"liability_report", has && !it->second.liability_report.empty() ? json(it->second.liability_report) : json(nullptr)}});
    }
    planners.push_back({{"planner", s.planner}, {"scenarios", s.scenarios}, {"failing", s.failing},
                        {"failing_share", s.failing_share()}, {"failing_share_ci95", {ci.lo, ci.hi}},
                        {"failures_by_rule", s.by_rule}, {"failures_by_party", s.by_party}, {"merged", s.merged},
                        {"merge_rate", s.merge_rate()},
                        {"merge_time_s", {{"median", or_null(median(s.merge_times_s))}, {"p95", or_null(p95(s.merge_times_s))}}},
                        {"path_length_m", {{"median", or_null(median(s.path_lengths_m))}, {"p95", or_null(p95(s.path_lengths_m))}}},
                        {"peak_lat_accel_mps2",
                         {{"median", or_null(median(s.peak_lat_accels_mps2))}, {"p95", or_null(p95(s.peak_lat_accels_mps2))}}},
                        {"halted_s", {{"mean", or_null(s.mean_halted_s())}}}, {"judged", s.judged}, {"worst_cases", worst}});
  }
  json j = {{"seed", o.seed}, {"runs", o.runs ? json(*o.runs) : json(nullptr)},
            {"time_budget_s", o.time_s ? json(*o.time_s) : json(nullptr)}, {"jobs", o.jobs},
            {"families", o.gen.targeted_families ? "mixed" : "uniform"}, {"max_vehicles", o.gen.max_vehicles},
            {"scenarios", r.scenarios}, {"seconds", r.seconds}, {"interrupted", r.interrupted},
            {"signal", r.interrupted && !r.stop_signal.empty() ? json(r.stop_signal) : json(nullptr)},
            {"planners", planners}, {"date", fuzz::utc_now_iso8601()}};
  if (!r.planner_processes.is_null()) j["planner_processes"] = r.planner_processes;
  return j;
}

namespace {

std::string link(const std::string& text, const std::string& href) { return href.empty() ? "" : "[" + text + "](" + href + ")"; }

ReportTable worst_table(const LeagueResult& r, const SavedCases& saved) {
  ReportTable t{{"planner", "signature (property/rule/party)", "failing runs", "worst run", "margin", "case", "liability report"}, {}};
  for (const PlannerStanding& s : r.standings)
    for (const auto& [sig, w] : s.worst) {
      const auto it = saved.find(sig);
      const SavedCase c = it == saved.end() ? SavedCase{} : it->second;
      t.rows.push_back({s.planner, sig.property + "/" + sig.rule + "/" + sig.party, std::to_string(w.scenarios),
                        std::to_string(w.run), fixed_or_na(w.margin, 3), link("case", c.case_path),
                        link("report", c.liability_report)});
    }
  return t;
}

struct Section {
  std::string title;
  ReportTable table;
};

}  // namespace

void write_league_report(const std::string& dir, const LeagueOptions& o, const LeagueResult& r, const SavedCases& saved) {
  const std::vector<Section> tables = {
      {"Failing runs by rule", failures_table(r, false)},
      {"Failing runs by liable party", failures_table(r, true)},
      {"Worst runs (one per failure signature: the lowest margin, then the earliest run)", worst_table(r, saved)},
  };
  const std::string svg = safety_efficiency_svg(r);
  std::string md = "# mergeguard league\n\n" + headline(o, r) + "\n\n## Standings\n\n" + table_markdown(standings_table(r)) +
                   "\n![Safety against efficiency](league.svg)\n";
  std::string page =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>mergeguard league</title><style>body{font-family:sans-serif;"
      "margin:16px}table{border-collapse:collapse;margin-bottom:12px}td,th{border:1px solid #999;padding:2px 6px;text-align:left;"
      "font-size:13px}th{background:#eee}.note{color:#444;font-size:13px}</style></head><body>\n<h1>mergeguard league</h1>\n<p>" +
      html_escape(headline(o, r)) + "</p>\n<h2>Standings</h2>\n" + table_html(standings_table(r)) +
      "<h2>Safety against efficiency</h2>\n" + inline_svg(svg);
  md += "\n## What the columns mean\n\n";
  page += "<h2>What the columns mean</h2>\n<ul class=\"note\">\n";
  for (const std::string& n : column_notes()) {
    md += "- " + n + "\n";
    page += "<li>" + html_escape(n) + "</li>\n";
  }
  page += "</ul>\n";
  for (const Section& s : tables) {
    md += "\n## " + s.title + "\n\n" + (s.table.rows.empty() ? "None.\n" : table_markdown(s.table));
    page += "<h2>" + html_escape(s.title) + "</h2>\n" + (s.table.rows.empty() ? "<p>None.</p>\n" : table_html(s.table));
  }
  page += "</body></html>\n";
  const std::filesystem::path base(dir);
  write_files_atomic({{(base / "league.json").string(), league_json(o, r, saved).dump(2) + "\n"},
                      {(base / "league.md").string(), md},
                      {(base / "league.html").string(), page},
                      {(base / "league.svg").string(), svg}});
}

}  // namespace mg::league
