#include "paper/paper_search.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/fixed_text.h"
#include "paper/paper_report.h"

namespace mg {
namespace {

// Stage 1's axes: the situation "relatively close to each other" (§IV) in which who goes first
// is ambiguous, and on-ramps long enough for the baseline to merge near X = 226 m (Fig. 4).
const std::vector<double> kGapsM{-20.0, -15.0, -10.0, -5.0, 0.0, 5.0, 10.0, 15.0};
const std::vector<double> kEgoSpeedsMps{18.0, 20.0, 22.0, 24.0, 26.0, 28.0};
const std::vector<double> kObstacleSpeedsMps{16.0, 18.0, 20.0, 22.0};
const std::vector<double> kRampEndsM{240.0, 270.0, 300.0};
const std::vector<double> kLeadGapsM{0.0, 60.0, 100.0, 140.0, 180.0};  // 0 = no lead vehicle
const std::vector<double> kLeadSpeedsMps{16.0, 20.0, 24.0};
// Stage 2's axes: how the obstacle may and does drive, and how fast it hears the ego.
const std::vector<double> kObstacleAccelsMps2{1.0, 2.0, 3.0};
const std::vector<double> kObstacleBrakeMinsMps2{2.0, 4.0};
const std::vector<double> kObstacleHeadwaysS{1.0, 1.5, 2.0};
const std::vector<double> kLatenciesS{0.05, 0.1, 0.3};
const std::vector<double> kObstacleComfortBrakesMps2{1.0, 2.0, 3.0};
// Stage 3's steps around the best candidate.
constexpr double kGapStepM = 2.5;
constexpr double kSpeedStepMps = 1.0;
constexpr double kLeadStepM = 15.0;

// Distance of the better RCPP variant's headline numbers from the paper's, in units of the
// claims' 10-point tolerance.
double headline_miss(const std::vector<PaperRun>& runs) {
  const PaperMetrics& tf = runs[0].metrics;
  double time_miss = 1e3, length_miss = 1e3;
  for (std::size_t i = 1; i < runs.size(); ++i) {
    const auto save = reduction_pct(tf.merge_time_s, runs[i].metrics.merge_time_s);
    const auto shorter = reduction_pct(tf.path_length_m, runs[i].metrics.path_length_m);
    if (save) time_miss = std::min(time_miss, std::abs(*save - 72.3) / 10.0);
    if (shorter) length_miss = std::min(length_miss, std::abs(*shorter - 53.4) / 10.0);
  }
  return time_miss + length_miss;
}

void evaluate_all(const Scenario& base, const std::vector<PaperSearchCandidate>& cs, int stage, PaperSearch& out) {
  for (const PaperSearchCandidate& c : cs) out.results.push_back(evaluate_search_candidate(base, c, stage));
  out.stage_sizes.push_back(static_cast<int>(cs.size()));
  std::stable_sort(out.results.begin(), out.results.end(), search_result_better);
}

std::vector<PaperSearchCandidate> stage1() {
  // The obstacle's limits and IDM at the scenario format's defaults, not the base's: the search
  // finds the same scenario from the old paper_merge.json as from the one it chose.
  const PaperSearchCandidate start;
  std::vector<PaperSearchCandidate> cs;
  for (double lead : kLeadGapsM)
    for (double v_lead : kLeadSpeedsMps) {
      if (lead <= 0.0 && v_lead != kLeadSpeedsMps.front()) continue;  // no lead vehicle: once
      for (double ramp : kRampEndsM)
        for (double v_o : kObstacleSpeedsMps)
          for (double v_e : kEgoSpeedsMps)
            for (double gap : kGapsM) {
              PaperSearchCandidate c = start;
              c.gap_m = gap, c.ego_speed_mps = v_e, c.obstacle_speed_mps = v_o, c.ramp_end_x_m = ramp;
              c.lead_gap_m = lead, c.lead_speed_mps = v_lead;
              cs.push_back(c);
            }
    }
  return cs;
}

std::vector<PaperSearchCandidate> stage2(const PaperSearch& so_far) {
  std::vector<PaperSearchCandidate> cs;
  const std::size_t seeds = std::min<std::size_t>(kStage2Seeds, so_far.results.size());
  for (std::size_t k = 0; k < seeds; ++k)
    for (double a : kObstacleAccelsMps2)
      for (double b : kObstacleBrakeMinsMps2)
        for (double h : kObstacleHeadwaysS)
          for (double comfort : kObstacleComfortBrakesMps2)
            for (double lat : kLatenciesS) {
              PaperSearchCandidate c = so_far.results[k].candidate;
              c.obstacle_accel_max_mps2 = a, c.obstacle_brake_min_mps2 = b, c.obstacle_headway_s = h;
              c.obstacle_comfort_brake_mps2 = comfort, c.latency_s = lat;
              cs.push_back(c);
            }
  return cs;
}

bool same_candidate(const PaperSearchCandidate& a, const PaperSearchCandidate& b) {
  return a.gap_m == b.gap_m && a.ego_speed_mps == b.ego_speed_mps && a.obstacle_speed_mps == b.obstacle_speed_mps &&
         a.obstacle_accel_max_mps2 == b.obstacle_accel_max_mps2 && a.obstacle_brake_min_mps2 == b.obstacle_brake_min_mps2 &&
         a.obstacle_headway_s == b.obstacle_headway_s && a.obstacle_comfort_brake_mps2 == b.obstacle_comfort_brake_mps2 &&
         a.latency_s == b.latency_s && a.ramp_end_x_m == b.ramp_end_x_m && a.lead_gap_m == b.lead_gap_m &&
         a.lead_speed_mps == b.lead_speed_mps;
}

bool evaluated(const PaperSearch& so_far, const std::vector<PaperSearchCandidate>& queued, const PaperSearchCandidate& c) {
  const auto same = [&](const PaperSearchCandidate& o) { return same_candidate(o, c); };
  return std::any_of(queued.begin(), queued.end(), same) ||
         std::any_of(so_far.results.begin(), so_far.results.end(), [&](const PaperSearchResult& r) { return same(r.candidate); });
}

// The joint neighbourhood (gap, both speeds, lead gap one step either way) of the best
// kRefineSeeds results, less what was evaluated already.
std::vector<PaperSearchCandidate> refine(const PaperSearch& so_far) {
  std::vector<PaperSearchCandidate> cs;
  const std::size_t seeds = std::min<std::size_t>(kRefineSeeds, so_far.results.size());
  for (std::size_t k = 0; k < seeds; ++k) {
    const PaperSearchCandidate best = so_far.results[k].candidate;
    const int lead_steps = best.lead_gap_m > 0.0 ? 1 : 0;
    for (int dg = -1; dg <= 1; ++dg)
      for (int de = -1; de <= 1; ++de)
        for (int dobs = -1; dobs <= 1; ++dobs)
          for (int dl = -lead_steps; dl <= lead_steps; ++dl) {
            PaperSearchCandidate c = best;
            c.gap_m += dg * kGapStepM;
            c.ego_speed_mps += de * kSpeedStepMps;
            c.obstacle_speed_mps += dobs * kSpeedStepMps;
            c.lead_gap_m += dl * kLeadStepM;
            if (!evaluated(so_far, cs, c)) cs.push_back(c);
          }
  }
  return cs;
}

std::string candidate_cells(const PaperSearchCandidate& c) {
  return fixed_text(c.gap_m, 1) + " | " + fixed_text(c.ego_speed_mps, 1) + " | " + fixed_text(c.obstacle_speed_mps, 1) +
         " | " + fixed_text(c.obstacle_accel_max_mps2, 1) + " | " + fixed_text(c.obstacle_brake_min_mps2, 1) + " | " +
         fixed_text(c.obstacle_headway_s, 1) + " | " + fixed_text(c.obstacle_comfort_brake_mps2, 1) + " | " +
         fixed_text(c.latency_s, 2) + " | " + fixed_text(c.ramp_end_x_m, 0) + " | " +
         (c.lead_gap_m > 0.0 ? fixed_text(c.lead_gap_m, 0) + " at " + fixed_text(c.lead_speed_mps, 0) + " m/s"
                             : std::string("none"));
}

std::string axis_text(const std::vector<double>& v, int decimals) {
  std::string out;
  for (double x : v) out += (out.empty() ? "" : ", ") + fixed_text(x, decimals);
  return "{" + out + "}";
}

}  // namespace

Scenario apply_search_candidate(const Scenario& base, const PaperSearchCandidate& c) {
  Scenario s = base;
  s.ego.x_m = 0.0;
  s.ego.speed_mps = c.ego_speed_mps;
  s.ego.v2v.latency_s = c.latency_s;
  s.road.side_lane_end_x_m = c.ramp_end_x_m;
  if (!s.vehicles.empty()) {
    MainVehicle& o = s.vehicles[0];
    o.x_m = c.gap_m;
    o.speed_mps = c.obstacle_speed_mps;
    o.behaviour.desired_speed_mps = c.obstacle_speed_mps;
    o.behaviour.time_headway_s = c.obstacle_headway_s;
    o.behaviour.comfort_brake_mps2 = c.obstacle_comfort_brake_mps2;
    o.limits.accel_max_mps2 = c.obstacle_accel_max_mps2;
    o.limits.brake_min_mps2 = std::min(c.obstacle_brake_min_mps2, o.limits.brake_max_mps2);
    o.v2v.latency_s = c.latency_s;
    s.vehicles.resize(1);  // the lead vehicle is the candidate's, not the base scenario's
    if (c.lead_gap_m > 0.0) {
      MainVehicle lead;
      lead.id = o.id + 1;
      lead.x_m = c.lead_gap_m;
      lead.speed_mps = c.lead_speed_mps;
      lead.behaviour.type = BehaviourType::kIdm;
      s.vehicles.push_back(lead);
    }
  }
  return s;
}

PaperSearchResult evaluate_search_candidate(const Scenario& base, const PaperSearchCandidate& c, int stage) {
  const Scenario s = apply_search_candidate(base, c);
  const std::vector<PaperRun> runs = run_paper_planners(s);
  PaperSearchResult r{c, stage, true, 0, headline_miss(runs), {}};
  for (const PaperRun& run : runs) r.consistent = r.consistent && run.metrics.merged && !run.metrics.collision;
  const std::vector<PaperClaim> claims = paper_claims(s, runs);
  r.reproduced = reproduced_count(claims);
  for (std::size_t i = 0; i < claims.size(); ++i)
    if (!claims[i].reproduced) r.failed_rows.push_back(static_cast<int>(i) + 1);
  return r;
}

bool search_result_better(const PaperSearchResult& a, const PaperSearchResult& b) {
  if (a.consistent != b.consistent) return a.consistent;
  if (a.reproduced != b.reproduced) return a.reproduced > b.reproduced;
  return a.headline_miss < b.headline_miss;
}

PaperSearch run_paper_search(const Scenario& base) {
  PaperSearch out;
  evaluate_all(base, stage1(), 1, out);
  evaluate_all(base, stage2(out), 2, out);
  for (int round = 0; round < kRefineRounds; ++round) evaluate_all(base, refine(out), 3 + round, out);
  return out;
}

std::string paper_search_markdown(const PaperSearch& search, const std::string& base_path, int top) {
  std::ostringstream md;
  int total = 0;
  for (int n : search.stage_sizes) total += n;
  std::string refine_sizes;
  for (std::size_t k = 2; k < search.stage_sizes.size(); ++k)
    refine_sizes += (refine_sizes.empty() ? "" : ", ") + std::to_string(search.stage_sizes[k]);
  md << "# Search for the paper's scenario (generated)\n\n"
     << "Generated by `mergeguard reproduce-paper --search` from `" << base_path
     << "`. Do not edit: rerun the command. See docs/paper_reproduction.md for what it means.\n\n"
     << "Planners at their default parameters; each candidate runs the three planners once and is scored by the "
        "report's "
     << kPaperClaimCount
     << " claims (src/paper/paper_claims.cpp). Order: every planner merged without "
        "collision, then rows reproduced, then the headline miss (|saving − 72.3| + |reduction − 53.4|, best variant "
        "each, in units of 10 points).\n\n"
     << "**Space.** Stage 1 (" << (search.stage_sizes.empty() ? 0 : search.stage_sizes[0]) << "): gap obstacle − ego "
     << axis_text(kGapsM, 0) << " m × ego speed " << axis_text(kEgoSpeedsMps, 0)
     << " m/s × obstacle speed (= its desired speed) " << axis_text(kObstacleSpeedsMps, 0) << " m/s × on-ramp end "
     << axis_text(kRampEndsM, 0) << " m × lead vehicle (IDM, no V2V) none or "
     << axis_text(std::vector<double>(kLeadGapsM.begin() + 1, kLeadGapsM.end()), 0) << " m ahead of the ego at "
     << axis_text(kLeadSpeedsMps, 0) << " m/s. Stage 2 (" << (search.stage_sizes.size() > 1 ? search.stage_sizes[1] : 0)
     << "): around the best " << kStage2Seeds << " of stage 1, obstacle a_accel^max "
     << axis_text(kObstacleAccelsMps2, 0) << " m/s² × a_brake^min " << axis_text(kObstacleBrakeMinsMps2, 0)
     << " m/s² × IDM headway " << axis_text(kObstacleHeadwaysS, 1) << " s × IDM comfortable braking "
     << axis_text(kObstacleComfortBrakesMps2, 0) << " m/s² × V2V latency " << axis_text(kLatenciesS, 2)
     << " s. Stages 3 to " << 2 + kRefineRounds << " (" << refine_sizes << "): around each of the best " << kRefineSeeds
     << " so far, jointly gap ± " << fixed_text(kGapStepM, 1) << " m, both speeds ± " << fixed_text(kSpeedStepMps, 0)
     << " m/s and the lead gap ± " << fixed_text(kLeadStepM, 0)
     << " m (when there is a lead vehicle), skipping what was evaluated. " << total << " candidates in all.\n\n"
     << "Rows reproduced over all candidates:";
  std::vector<int> histogram(kPaperClaimCount + 1, 0);
  for (const PaperSearchResult& r : search.results) ++histogram[static_cast<std::size_t>(r.reproduced)];
  for (int k = kPaperClaimCount; k >= 0; --k)
    if (histogram[static_cast<std::size_t>(k)] > 0) md << " " << k << ": " << histogram[static_cast<std::size_t>(k)] << ";";
  // How often each row reproduces over the whole space: a row that (almost) never does is a
  // limit of the planners or the simulator, not of our choice of scenario.
  // And the most rows any candidate reproducing that row reaches: which rows exclude each other.
  std::vector<int> per_row(kPaperClaimCount, 0), best_with_row(kPaperClaimCount, 0);
  for (const PaperSearchResult& r : search.results) {
    std::vector<bool> failed(kPaperClaimCount, false);
    for (int row : r.failed_rows) failed[static_cast<std::size_t>(row - 1)] = true;
    for (std::size_t k = 0; k < failed.size(); ++k) {
      if (failed[k]) continue;
      ++per_row[k];
      best_with_row[k] = std::max(best_with_row[k], r.reproduced);
    }
  }
  md << "\n\nCandidates reproducing each row (of " << search.results.size()
     << "), and in brackets the most rows reproduced by one of them:";
  for (std::size_t k = 0; k < per_row.size(); ++k)
    md << " row " << k + 1 << ": " << per_row[k] << " (" << best_with_row[k] << ");";
  md << "\n\n## Best " << top << " candidates\n\n"
     << "| # | stage | gap [m] | v_e [m/s] | v_o [m/s] | a_acc,o [m/s²] | b_min,o [m/s²] | headway [s] | IDM b [m/s²] | "
        "latency [s] | ramp end [m] | lead vehicle [m ahead] | merged, no collision | rows | headline miss | "
        "rows not reproduced |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (int i = 0; i < top && i < static_cast<int>(search.results.size()); ++i) {
    const PaperSearchResult& r = search.results[static_cast<std::size_t>(i)];
    std::string failed;
    for (int row : r.failed_rows) failed += (failed.empty() ? "" : ", ") + std::to_string(row);
    md << "| " << i + 1 << " | " << r.stage << " | " << candidate_cells(r.candidate) << " | "
       << (r.consistent ? "yes" : "no") << " | " << r.reproduced << " | " << fixed_text(r.headline_miss, 2) << " | "
       << (failed.empty() ? "none" : failed) << " |\n";
  }
  return md.str();
}

nlohmann::json best_search_scenario_json(const Scenario& base, const PaperSearch& search) {
  return scenario_to_json(apply_search_candidate(base, search.results.front().candidate));
}

}  // namespace mg
