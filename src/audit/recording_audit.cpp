#include "audit/recording_audit.h"

#include <algorithm>
#include <cstdio>

namespace mg {
namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

std::string MergeAudit::liable_name() const {
  if (result.liable_id.is_ego()) return "ego (vehicle " + std::to_string(merge.recording_ids.front()) + ")";
  if (result.liable_id.is_vehicle()) {
    for (std::size_t i = 0; i < merge.trace.vehicles.size(); ++i) {
      if (merge.trace.vehicles[i].id == result.liable_id.vehicle_id()) return "vehicle " + std::to_string(merge.recording_ids[i]);
    }
  }
  return party_name(result.liable_id);
}

bool RecordingAudit::holds() const {
  return std::all_of(merges.begin(), merges.end(), [](const MergeAudit& m) { return m.result.holds; });
}

SensitivitySweep sweep_sensitivity(const ObservedTrace& trace, const SensitivityRanges& ranges) {
  SensitivitySweep s;
  int holding = 0;
  for (const double t : ranges.response_times_s) {
    for (const double scale : ranges.brake_scales) {
      ObservedTrace varied = trace;
      varied.params.rss.response_time_s = t;
      for (VehicleDeclaration& d : varied.vehicles) {
        d.limits.brake_min_mps2 = std::min(15.0, d.limits.brake_min_mps2 * scale);
        d.limits.brake_max_mps2 = std::min(15.0, d.limits.brake_max_mps2 * scale);
      }
      const CheckResult r = check_observed(std::move(varied));
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

RecordingAudit audit_recording(const Recording& r, const RoadLayout& road, const AuditProfile& p, std::optional<int> only_vehicle) {
  RecordingAudit a;
  a.source = r.source;
  a.recording = &r;
  a.road = &road;
  a.profile = p;
  const RecordingView view = view_recording(r, road, p);
  a.changes = view.changes;
  for (const LaneChange& c : view.changes) {
    if (only_vehicle && c.vehicle_id != *only_vehicle) continue;
    MergeAudit m;
    m.merge = build_merge_trace(view, c, p);
    m.result = check_observed(m.merge.trace);
    m.result.planner = "recorded driver (CommonRoad obstacle " + std::to_string(c.vehicle_id) + ")";
    if (!m.result.holds) m.sensitivity = sweep_sensitivity(m.merge.trace, p.sensitivity);
    a.merges.push_back(std::move(m));
  }
  return a;
}

}  // namespace mg
