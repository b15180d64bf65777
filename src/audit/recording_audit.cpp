#include "audit/recording_audit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "audit/censoring.h"
#include "rules/monitor.h"

namespace mg {
namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A recording is judged by the safety rules only (docs/audit.md, "From a merge to a trace").
CheckResult check_recorded(ObservedTrace trace) { return check_observed(std::move(trace), std::nullopt, RuleSet::kSafety); }

bool joins_at_ramp(const LaneChange& c) { return c.from_lane == kRampLane || c.to_lane == kRampLane; }

// The b_min the frontier's braking applies to: the liable follower's, else the first other
// vehicle's (the follower of a gap), else the ego's.
double follower_brake_min(const CheckResult& r) {
  const ObservedTrace& t = r.trace;
  const int k = index_of_party(t, r.liable_id);
  if (k >= 1) return t.vehicles[static_cast<std::size_t>(k)].limits.brake_min_mps2;
  return t.vehicles[t.vehicles.size() > 1 ? 1 : 0].limits.brake_min_mps2;
}

ComplianceFrontier frontier_of(const MergeAudit& m, const AuditProfile& p) {
  const JudgeAt judge = [&m](double rho_s, double scale) {
    const CheckResult r = check_recorded(with_profile_variation(m.merge.trace, rho_s, scale));
    VariedJudgement j;
    j.holds = r.holds;
    if (const RuleResult* d = deciding_rule(r)) j.first_rule = d->rule_id, j.first_rule_ref = d->paper_ref;
    return j;
  };
  return compliance_frontier(judge, p.rss.response_time_s, follower_brake_min(m.result), p.sensitivity.brake_scales);
}

// Judges the merge's trace. A blame resting on a danger under way at the first judged instant
// is not given: the trace is judged again from the end of that danger (a danger begun after the
// first instant keeps its recorded beginning: it is not censored, only judged from there), or
// the merge is undetermined when the danger lasts.
void judge(const RecordingView& view, MergeAudit& m) {
  const double dt = view.recording->time_step_s;
  const MergeTrace whole = m.merge;
  std::size_t cut = 0;
  for (int round = 0;; ++round) {
    m.result = check_recorded(m.merge.trace);
    m.result.planner = "recorded driver (CommonRoad obstacle " + std::to_string(m.merge.change.vehicle_id) + ")";
    const std::optional<DecisionWindow> w = decision_window(m.merge.trace, m.merge.change.time_step * dt);
    std::vector<std::string> missing;
    if (const auto censored = w ? decision_censoring(view, m.merge, *w, m.result, missing) : std::nullopt) {
      m.verdict = AuditVerdict::kUndetermined;
      m.censoring = Censoring{*censored, missing, judged_on_record(m.result, m.merge)};
      return;
    }
    m.verdict = m.result.holds ? AuditVerdict::kHolds : AuditVerdict::kViolated;
    const std::optional<CensoredBlame> blame = m.result.holds ? std::nullopt : censored_blame(whole.trace, m.result, whole);
    if (!blame) return;
    // A trace of a second or less judges nothing a recording can show.
    const bool trimmable = blame->end_step && *blame->end_step > cut && round < 8 &&
                           whole.trace.steps.size() - *blame->end_step > static_cast<std::size_t>(1.0 / dt);
    if (!trimmable) {
      m.verdict = AuditVerdict::kUndetermined;
      m.censoring = Censoring{blame->reason, {"how the danger between " + blame->pair + " began, before t = " + fmt(whole.first_step * dt) + " s"},
                              judged_on_record(m.result, m.merge)};
      return;
    }
    cut = *blame->end_step;
    m.merge = whole;
    m.merge.trace.steps.erase(m.merge.trace.steps.begin(), m.merge.trace.steps.begin() + static_cast<long>(cut));
    m.merge.first_step += static_cast<int>(cut);
    m.merge.window_start = {true, "the end of a danger between " + blame->pair + " under way from the first recorded instant"};
  }
}

MergeAudit try_audit(const RecordingView& view, const LaneChange& c, const AuditProfile& p, std::optional<int> earliest) {
  MergeAudit m;
  m.merge = build_merge_trace(view, c, p, earliest);
  judge(view, m);
  return m;
}

// The decision window reaching back before the audit's own window: widen it to the records.
std::optional<int> wider_start(const MergeAudit& m, double dt) {
  if (m.merge.window_start.recording_limit || m.merge.window_start.why.find("previous lane change") != std::string::npos) return std::nullopt;
  const std::optional<DecisionWindow> w = decision_window(m.merge.trace, m.merge.change.time_step * dt);
  const bool decision_before = w && w->from_s < m.merge.first_step * dt - 1e-9;
  if (decision_before && m.verdict != AuditVerdict::kUndetermined) {
    return std::max(0, static_cast<int>(std::floor(w->from_s / dt + 1e-9)));
  }
  if (m.verdict == AuditVerdict::kUndetermined) return 0;  // a danger begun before the window: look further back
  return std::nullopt;
}

}  // namespace

MergeAudit audit_merge(const RecordingView& view, const LaneChange& c, const AuditProfile& p, const AuditOptions& o) {
  if (!view.road->highway_on_ramp && !o.all_lane_joins && joins_at_ramp(c)) {
    MergeAudit m;
    m.merge = build_merge_trace(view, c, p);
    m.verdict = AuditVerdict::kNotJudged;
    m.not_judged_reason = "not a highway on-ramp (" + view.road->on_ramp_basis + "); --all-lane-joins judges it";
    m.result.trace = m.merge.trace;
    return m;
  }
  MergeAudit m = try_audit(view, c, p, std::nullopt);
  if (const auto earlier = wider_start(m, view.recording->time_step_s)) m = try_audit(view, c, p, earlier);
  if (m.judged() && o.frontier) {
    m.frontier = frontier_of(m, p);
    m.sensitivity = sweep_sensitivity(m.merge.trace, p.sensitivity);
  }
  return m;
}

std::string to_string(AuditVerdict v) {
  switch (v) {
    case AuditVerdict::kHolds: return "holds";
    case AuditVerdict::kViolated: return "violated";
    case AuditVerdict::kUndetermined: return "undetermined";
    case AuditVerdict::kNotJudged: return "not judged";
  }
  return "?";
}

std::string MergeAudit::recording_name(int trace_id) const {
  for (std::size_t i = 0; i < merge.trace.vehicles.size(); ++i) {
    if (merge.trace.vehicles[i].id == trace_id) return "vehicle " + std::to_string(merge.recording_ids[i]);
  }
  return party_name(Party::from_vehicle_id(trace_id));
}

std::string MergeAudit::liable_name() const {
  if (verdict != AuditVerdict::kViolated) return verdict == AuditVerdict::kHolds ? "none" : "-";
  if (result.liable_id.is_ego()) return "ego (vehicle " + std::to_string(merge.recording_ids.front()) + ")";
  if (result.liable_id.is_vehicle()) return recording_name(result.liable_id.vehicle_id());
  return party_name(result.liable_id);
}

int RecordingAudit::count(AuditVerdict v) const {
  return static_cast<int>(std::count_if(merges.begin(), merges.end(), [v](const MergeAudit& m) { return m.verdict == v; }));
}

std::string RecordingAudit::nothing_to_audit() const {
  if (recording->vehicles.empty()) {
    return "nothing to audit: the recording has no moving vehicle (" + std::to_string(recording->static_obstacles) + " static obstacles)";
  }
  if (road == nullptr) return "nothing to audit: " + std::string(kNoLaneJoinText) + ", so no vehicle can merge or change lanes";
  if (changes.empty()) return "nothing to audit: no vehicle changes lanes in the recording";
  return "";
}

ObservedTrace with_profile_variation(const ObservedTrace& t, double response_time_s, double brake_scale) {
  ObservedTrace varied = t;
  varied.params.rss.response_time_s = response_time_s;
  for (VehicleDeclaration& d : varied.vehicles) {
    d.limits.brake_min_mps2 = std::min(kMaxBrakeMps2, d.limits.brake_min_mps2 * brake_scale);
    d.limits.brake_max_mps2 = std::min(kMaxBrakeMps2, d.limits.brake_max_mps2 * brake_scale);
  }
  return varied;
}

SensitivitySweep sweep_sensitivity(const ObservedTrace& trace, const SensitivityRanges& ranges) {
  SensitivitySweep s;
  int holding = 0;
  for (const double t : ranges.response_times_s) {
    for (const double scale : ranges.brake_scales) {
      const CheckResult r = check_recorded(with_profile_variation(trace, t, scale));
      s.points.push_back({t, scale, r.holds, r.liable_id});
      holding += r.holds ? 1 : 0;
    }
  }
  const int n = static_cast<int>(s.points.size());
  const bool liable_varies = std::any_of(s.points.begin(), s.points.end(), [&](const SensitivityPoint& p) { return p.liable_id != s.points.front().liable_id; });
  s.flips = (holding != 0 && holding != n) || liable_varies;
  s.summary = std::to_string(holding) + " of " + std::to_string(n) + " profile variations hold (response time " +
              fmt(ranges.response_times_s.front()) + "-" + fmt(ranges.response_times_s.back()) + " s, braking x" +
              fmt(ranges.brake_scales.front()) + "-" + fmt(ranges.brake_scales.back()) + ")" +
              (s.flips ? ": the verdict or liable party changes within the plausible range, not certain" : ": the same verdict throughout");
  return s;
}

RecordingAudit audit_recording(const Recording& r, const RoadLayout& road, const AuditProfile& p, const AuditOptions& o) {
  RecordingAudit a;
  a.source = r.source;
  a.recording = &r;
  a.road = &road;
  a.profile = p;
  const RecordingView view = view_recording(r, road, p);
  a.changes = view.changes;
  for (const LaneChange& c : view.changes) {
    if (o.only_vehicle && c.vehicle_id != *o.only_vehicle) continue;
    a.merges.push_back(audit_merge(view, c, p, o));
  }
  return a;
}

RecordingAudit audit_recording_without_lane_join(const Recording& r, const AuditProfile& p) {
  RecordingAudit a;
  a.source = r.source;
  a.recording = &r;
  a.profile = p;
  return a;
}

}  // namespace mg
