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

// "4.1 s": the time of a recording step.
std::string step_time(const RecordingView& v, int step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", step * v.recording->time_step_s);
  return buf;
}

// The ego's steps around the change: no further back than its previous lane change and no
// further on than its next, so that the window holds this one merge.
std::pair<int, int> ego_window(const RecordingView& v, const LaneChange& c, const AuditProfile& p, std::optional<int> earliest,
                               WindowStart& start) {
  const FrenetTrack& t = v.tracks[track_index(v, c.vehicle_id)];
  const double dt = v.recording->time_step_s;
  int first = c.time_step - static_cast<int>(std::lround(p.window_before_s / dt));
  if (earliest) first = std::min(first, *earliest);
  start = {false, "the audit window (window_before_s " + std::to_string(static_cast<int>(p.window_before_s)) + " s before the change)"};
  if (t.states.front().time_step >= first) {
    first = t.states.front().time_step;
    start = {true, first == 0 ? "the recording's first instant" : "the record of the ego (from " + step_time(v, first) + ")"};
  }
  int last = std::min(t.states.back().time_step, c.time_step + static_cast<int>(std::lround(p.window_after_s / dt)));
  for (const LaneChange& o : v.changes) {
    if (o.vehicle_id != c.vehicle_id || o.kind == LaneChangeKind::kRampHalt || o.time_step == c.time_step) continue;
    if (o.time_step < c.time_step && o.time_step >= first) {
      first = o.time_step;
      start = {false, "the ego's previous lane change (at " + step_time(v, o.time_step) + ")"};
    }
    // Halfway to the next lane change: its own motion, which begins before its step, is not this one's.
    if (o.time_step > c.time_step) last = std::min(last, std::max(c.time_step + 1, (c.time_step + o.time_step) / 2));
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
void shrink_to_neighbours(const RecordingView& v, std::size_t ego, const LaneChange& c, const AuditProfile& p, int& first, int& last,
                          WindowStart& start) {
  const int margin = static_cast<int>(std::lround(1.0 / v.recording->time_step_s));
  for (std::size_t i = 0; i < v.tracks.size(); ++i) {
    if (i == ego || !near_ego(v, i, ego, c, first, last, p.neighbour_range_m)) continue;
    const int from = v.tracks[i].states.front().time_step, to = v.tracks[i].states.back().time_step;
    if (from <= std::max(first, c.time_step - margin) && to >= std::min(last, c.time_step + margin)) {
      if (from > first) {
        first = from;
        start = {true, from == 0 ? "the recording's first instant"
                                 : "the record of vehicle " + std::to_string(v.tracks[i].vehicle_id) + " (from " + step_time(v, from) + ")"};
      }
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

// `entering`: members placed in the lane entered while on the ramp beyond it (R_I5).
void fill_steps(const RecordingView& v, const std::vector<std::size_t>& members, const std::vector<bool>& entering, const LaneChange& c,
                int half_window, MergeTrace& m) {
  const RoadLayout& road = *v.road;
  const double sign = merge_frame_y(road, c.from_lane, c.to_lane, 0.0, 1.0) >= merge_frame_y(road, c.from_lane, c.to_lane, 0.0, 0.0) ? 1.0 : -1.0;
  std::vector<std::vector<double>> ys(members.size());
  for (std::size_t k = 0; k < members.size(); ++k) {
    for (int step = m.first_step; step <= m.last_step; ++step) {
      const TrackState& s = *v.tracks[members[k]].at_step(step);
      const double y = merge_frame_y(road, c.from_lane, c.to_lane, s.s_m, s.d_m);
      ys[k].push_back(entering[k] ? std::min(y, 0.0) : y);
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

ObservedTrace with_profile(const MergeTrace& m, const AuditProfile& p) {
  ObservedTrace t = m.trace;
  t.params.rss = p.rss;
  for (std::size_t k = 0; k < t.vehicles.size(); ++k) t.vehicles[k].limits = p.limits_for(m.types[k]);
  return t;
}

std::vector<std::size_t> entering_vehicles(const RecordingView& v, const LaneChange& c) {
  std::vector<std::size_t> out;
  if (c.kind != LaneChangeKind::kCutIn || c.to_lane != 0 || !v.road->highway_on_ramp) return out;
  for (const LaneChange& o : v.changes) {
    if (o.kind != LaneChangeKind::kRampMerge || o.to_lane != 0 || o.vehicle_id == c.vehicle_id || o.time_step <= c.time_step) continue;
    const std::size_t i = track_index(v, o.vehicle_id);
    const FrenetTrack& t = v.tracks[i];
    const TrackState* at_change = t.at_step(c.time_step);
    if (at_change == nullptr || v.lanes[i][static_cast<std::size_t>(c.time_step - t.states.front().time_step)] != kRampLane) continue;
    if (std::find(out.begin(), out.end(), i) == out.end()) out.push_back(i);
  }
  return out;
}

MergeTrace build_merge_trace(const RecordingView& v, const LaneChange& c, const AuditProfile& p, std::optional<int> earliest_step) {
  MergeTrace m;
  m.change = c;
  const std::size_t ego = track_index(v, c.vehicle_id);
  auto [first, last] = ego_window(v, c, p, earliest_step, m.window_start);
  shrink_to_neighbours(v, ego, c, p, first, last, m.window_start);
  const std::vector<std::size_t> entering = entering_vehicles(v, c);
  std::vector<std::size_t> members{ego};
  for (std::size_t i = 0; i < v.tracks.size(); ++i) {
    const bool enters = std::find(entering.begin(), entering.end(), i) != entering.end();
    if (i == ego || !(enters || near_ego(v, i, ego, c, first, last, p.neighbour_range_m))) continue;
    const FrenetTrack& t = v.tracks[i];
    if (t.states.front().time_step <= first && t.states.back().time_step >= last) {
      members.push_back(i);
    } else {
      m.partial.push_back({t.vehicle_id, t.states.front().time_step, t.states.back().time_step});
      m.left_out.push_back("vehicle " + std::to_string(t.vehicle_id) + ": recorded from " + step_time(v, t.states.front().time_step) +
                           " to " + step_time(v, t.states.back().time_step) + ", not throughout the window");
    }
  }
  keep_nearest(v, ego, c.time_step, members, m.left_out);
  m.first_step = first;
  m.last_step = last;
  const std::vector<int> ids = trace_ids(v, members);
  std::vector<bool> placed;
  double max_s = 0.0;
  for (std::size_t k = 0; k < members.size(); ++k) {
    m.recording_ids.push_back(v.tracks[members[k]].vehicle_id);
    m.types.push_back(v.tracks[members[k]].type);
    m.trace.vehicles.push_back(declare(v.tracks[members[k]], ids[k], p));
    max_s = std::max(max_s, v.tracks[members[k]].at_step(last)->s_m);
    placed.push_back(std::find(entering.begin(), entering.end(), members[k]) != entering.end());
    if (placed.back()) m.entering_ids.push_back(v.tracks[members[k]].vehicle_id);
  }
  m.trace.name = v.recording->benchmark_id + ": " + to_string(c.kind) + " of vehicle " + std::to_string(c.vehicle_id) + " at " + step_time(v, c.time_step);
  m.trace.source = "CommonRoad " + v.recording->version + " recording " + v.recording->benchmark_id + " (mergeguard audit)";
  m.trace.road = trace_road(v, c, p, max_s);
  m.trace.params = {p.rss, p.rules};
  fill_steps(v, members, placed, c, p.smoothing_half_window_steps, m);
  add_notes(v, members, m);
  for (const int id : m.entering_ids) {
    m.notes.push_back("vehicle " + std::to_string(id) + " is entering from the ramp into the lane this lane change enters: it is placed in that lane "
                      "while on the ramp, so that the lane change is judged toward it (CommonRoad R_I5, docs/audit.md)");
  }
  return m;
}

}  // namespace mg
