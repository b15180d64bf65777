#include "audit/merge_trace.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace mg {
namespace {

const Lane& lane_of(const RoadLayout& road, int index) {
  return index == kRampLane ? road.ramp : road.main_lanes.at(static_cast<std::size_t>(index));
}

std::size_t track_index(const RecordingView& v, int vehicle_id) {
  for (std::size_t i = 0; i < v.tracks.size(); ++i) {
    if (v.tracks[i].vehicle_id == vehicle_id) return i;
  }
  return 0;
}

// The ego's steps around the change: no further back than its previous lane change and no
// further on than its next, so that the window holds this one merge.
std::pair<int, int> ego_window(const RecordingView& v, const LaneChange& c, const AuditProfile& p) {
  const FrenetTrack& t = v.tracks[track_index(v, c.vehicle_id)];
  const double dt = v.recording->time_step_s;
  int first = std::max(t.states.front().time_step, c.time_step - static_cast<int>(std::lround(p.window_before_s / dt)));
  int last = std::min(t.states.back().time_step, c.time_step + static_cast<int>(std::lround(p.window_after_s / dt)));
  for (const LaneChange& o : v.changes) {
    if (o.vehicle_id != c.vehicle_id || o.kind == LaneChangeKind::kRampHalt || o.time_step == c.time_step) continue;
    if (o.time_step < c.time_step) first = std::max(first, o.time_step);
    if (o.time_step > c.time_step) last = std::min(last, o.time_step - 1);
  }
  return {first, last};
}

// Whether track i is, at some step of [first, last], in the origin or target lane within range of the ego.
bool near_ego(const RecordingView& v, std::size_t i, std::size_t ego, const LaneChange& c, int first, int last, double range_m) {
  const FrenetTrack& t = v.tracks[i];
  for (int step = first; step <= last; ++step) {
    const TrackState* s = t.at_step(step);
    const TrackState* e = v.tracks[ego].at_step(step);
    if (s == nullptr || e == nullptr) continue;
    const int lane = v.lanes[i][static_cast<std::size_t>(step - t.states.front().time_step)];
    if (lane != c.from_lane && lane != c.to_lane) continue;
    // In the lane, not merely nearest to it (a vehicle far off the road is nearest to some lane).
    const bool in_lane = std::abs(s->d_m - lane_of(*v.road, lane).centre_d_at(s->s_m)) < v.road->lane_width_m;
    if (in_lane && std::abs(s->s_m - e->s_m) <= range_m) return true;
  }
  return false;
}

// Neighbours recorded for only part of the window still take part when they are there from a
// second before the lane change to a second after it: the window shrinks to their record.
void shrink_to_neighbours(const RecordingView& v, std::size_t ego, const LaneChange& c, const AuditProfile& p, int& first, int& last) {
  const int margin = static_cast<int>(std::lround(1.0 / v.recording->time_step_s));
  for (std::size_t i = 0; i < v.tracks.size(); ++i) {
    if (i == ego || !near_ego(v, i, ego, c, first, last, p.neighbour_range_m)) continue;
    const int from = v.tracks[i].states.front().time_step, to = v.tracks[i].states.back().time_step;
    if (from <= std::max(first, c.time_step - margin) && to >= std::min(last, c.time_step + margin)) {
      first = std::max(first, from);
      last = std::min(last, to);
    }
  }
}

// A trace holds at most kMaxVehicles: the nearest to the ego at the lane change stay.
void keep_nearest(const RecordingView& v, std::size_t ego, int step, std::vector<std::size_t>& members, std::vector<std::string>& left_out) {
  if (members.size() <= kMaxVehicles) return;
  const double ego_s = v.tracks[ego].at_step(step)->s_m;
  const auto gap = [&](std::size_t i) {
    const TrackState* s = v.tracks[i].at_step(step);
    return s != nullptr ? std::abs(s->s_m - ego_s) : 1e300;
  };
  std::stable_sort(members.begin() + 1, members.end(), [&](std::size_t a, std::size_t b) { return gap(a) < gap(b); });
  for (std::size_t k = kMaxVehicles; k < members.size(); ++k) {
    left_out.push_back("vehicle " + std::to_string(v.tracks[members[k]].vehicle_id) + ": beyond the " + std::to_string(kMaxVehicles) +
                       " vehicles a trace holds (the nearest are kept)");
  }
  members.resize(kMaxVehicles);
}

std::string step_time(const RecordingView& v, int step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", step * v.recording->time_step_s);
  return buf;
}

void add_notes(const RecordingView& v, const std::vector<std::size_t>& members, MergeTrace& m) {
  const Recording& r = *v.recording;
  if (r.set_valued_states > 0) {
    m.notes.push_back(std::to_string(r.set_valued_states) + " recorded states give a position or value as a set: the audit uses each set's centre");
  }
  std::set<std::string> derived;
  for (const std::size_t i : members) {
    if (v.tracks[i].speed_from_positions) derived.insert("speeds derived from the positions (local least-squares slope, docs/audit.md)");
    if (v.tracks[i].accel_from_speeds) derived.insert("accelerations derived from the speeds (local least-squares slope)");
    if (v.tracks[i].yaw_from_motion) derived.insert("headings derived from the direction of motion");
  }
  m.notes.insert(m.notes.end(), derived.begin(), derived.end());
}

VehicleDeclaration declare(const FrenetTrack& t, int id, const AuditProfile& p) {
  VehicleDeclaration d;
  d.id = id;
  d.size.length_m = t.length_m;
  d.size.width_m = t.width_m;
  d.limits = p.limits_for(t.type);
  return d;
}

// Trace ids are the CommonRoad ids where they fit the trace format ([1, 10^6], the ego 0).
std::vector<int> trace_ids(const RecordingView& v, const std::vector<std::size_t>& members) {
  std::vector<int> ids{0};
  std::set<int> used;
  for (std::size_t k = 1; k < members.size(); ++k) {
    int id = v.tracks[members[k]].vehicle_id;
    if (id < 1 || id > 1'000'000 || used.count(id)) {
      id = 1;
      while (used.count(id)) ++id;
    }
    used.insert(id);
    ids.push_back(id);
  }
  return ids;
}

void fill_steps(const RecordingView& v, const std::vector<std::size_t>& members, const LaneChange& c, int half_window, MergeTrace& m) {
  const RoadLayout& road = *v.road;
  const double sign = merge_frame_y(road, c.from_lane, c.to_lane, 0.0, 1.0) >= merge_frame_y(road, c.from_lane, c.to_lane, 0.0, 0.0) ? 1.0 : -1.0;
  std::vector<std::vector<double>> ys(members.size());
  for (std::size_t k = 0; k < members.size(); ++k) {
    for (int step = m.first_step; step <= m.last_step; ++step) {
      const TrackState& s = *v.tracks[members[k]].at_step(step);
      ys[k].push_back(merge_frame_y(road, c.from_lane, c.to_lane, s.s_m, s.d_m));
    }
  }
  const double dt = v.recording->time_step_s;
  for (int step = m.first_step; step <= m.last_step; ++step) {
    ObservedStep o;
    o.time_s = step * dt;
    const std::size_t i = static_cast<std::size_t>(step - m.first_step);
    for (std::size_t k = 0; k < members.size(); ++k) {
      const TrackState& s = *v.tracks[members[k]].at_step(step);
      o.vehicles.push_back({s.s_m, ys[k][i], sign * s.yaw_rad, s.vs_mps, local_slope(ys[k], dt, i, half_window), s.accel_mps2});
    }
    m.trace.steps.push_back(std::move(o));
  }
}

Road trace_road(const RecordingView& v, const LaneChange& c, const AuditProfile& p, double max_s_m) {
  const RoadLayout& road = *v.road;
  Road r;
  r.lane_width_m = road.lane_width_m;
  // Main lanes in the trace: the target and those beyond it, away from the side lane (at most 4).
  int beyond = 1;
  if (c.to_lane != kRampLane) beyond = c.to_lane > c.from_lane ? static_cast<int>(road.main_lanes.size()) - c.to_lane : c.to_lane + 1;
  if (c.from_lane == kRampLane) beyond = static_cast<int>(road.main_lanes.size());
  r.main_lanes = std::clamp(beyond, 1, 4);
  const bool ramp_side = c.from_lane == kRampLane;
  r.side_lane_start_x_m = std::max(-1e4, std::min(road.reference.start_s_m(), road.ramp.start_s_m - 1.0));
  r.side_lane_end_x_m = ramp_side ? road.ramp_end_s_m : std::min(1e5, max_s_m + 1000.0);
  if (r.side_lane_end_x_m < r.side_lane_start_x_m + 10.0) r.side_lane_end_x_m = r.side_lane_start_x_m + 10.0;
  r.speed_limit_mps = road.speed_limit_mps > 0 ? std::min(road.speed_limit_mps, 100.0) : p.default_speed_limit_mps;
  return r;
}

}  // namespace

RecordingView view_recording(const Recording& r, const RoadLayout& road, const AuditProfile& p) {
  RecordingView v{&r, &road, {}, {}, {}};
  const int min_steps = std::max(1, static_cast<int>(std::lround(p.min_lane_time_s / r.time_step_s)));
  for (const RecordedVehicle& veh : r.vehicles) {
    v.tracks.push_back(project_track(veh, road.reference, r.time_step_s, p.smoothing_half_window_steps));
    v.lanes.push_back(lane_sequence(v.tracks.back(), road, min_steps));
  }
  v.changes = find_lane_changes(v.tracks, road, {min_steps, p.halted_speed_mps, p.halt_near_end_m});
  return v;
}

double merge_frame_y(const RoadLayout& road, int origin, int target, double s_m, double d_m) {
  const double c_target = lane_of(road, target).centre_d_at(s_m);
  const double c_origin = origin == target ? c_target - road.lane_width_m : lane_of(road, origin).centre_d_at(s_m);
  const double sep = c_target - c_origin;
  const double dir = sep >= 0 ? 1.0 : -1.0;
  // Where the lanes are further apart than a lane (a ramp still curving in) the side lane's centre
  // is drawn in to -W; where they are closer (a ramp's taper) distances are kept as recorded.
  const double scale = road.lane_width_m / std::max(std::abs(sep), road.lane_width_m);
  return dir * (d_m - c_target) * scale;
}

MergeTrace build_merge_trace(const RecordingView& v, const LaneChange& c, const AuditProfile& p) {
  MergeTrace m;
  m.change = c;
  const std::size_t ego = track_index(v, c.vehicle_id);
  auto [first, last] = ego_window(v, c, p);
  shrink_to_neighbours(v, ego, c, p, first, last);
  std::vector<std::size_t> members{ego};
  for (std::size_t i = 0; i < v.tracks.size(); ++i) {
    if (i == ego || !near_ego(v, i, ego, c, first, last, p.neighbour_range_m)) continue;
    const FrenetTrack& t = v.tracks[i];
    if (t.states.front().time_step <= first && t.states.back().time_step >= last) {
      members.push_back(i);
    } else {
      m.left_out.push_back("vehicle " + std::to_string(t.vehicle_id) + ": recorded from " + step_time(v, t.states.front().time_step) +
                           " to " + step_time(v, t.states.back().time_step) + ", not throughout the window");
    }
  }
  keep_nearest(v, ego, c.time_step, members, m.left_out);
  m.first_step = first;
  m.last_step = last;
  const std::vector<int> ids = trace_ids(v, members);
  double max_s = 0.0;
  for (std::size_t k = 0; k < members.size(); ++k) {
    m.recording_ids.push_back(v.tracks[members[k]].vehicle_id);
    m.trace.vehicles.push_back(declare(v.tracks[members[k]], ids[k], p));
    max_s = std::max(max_s, v.tracks[members[k]].at_step(last)->s_m);
  }
  m.trace.name = v.recording->benchmark_id + ": " + to_string(c.kind) + " of vehicle " + std::to_string(c.vehicle_id) + " at " + step_time(v, c.time_step);
  m.trace.source = "CommonRoad " + v.recording->version + " recording " + v.recording->benchmark_id + " (mergeguard audit)";
  m.trace.road = trace_road(v, c, p, max_s);
  m.trace.params = {p.rss, p.rules};
  fill_steps(v, members, c, p.smoothing_half_window_steps, m);
  add_notes(v, members, m);
  return m;
}

}  // namespace mg
