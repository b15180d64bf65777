#include "recording/merge_finder.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace mg {

std::string to_string(LaneChangeKind k) {
  switch (k) {
    case LaneChangeKind::kRampMerge: return "ramp merge";
    case LaneChangeKind::kCutIn: return "cut-in";
    case LaneChangeKind::kIntoRamp: return "into the ramp";
    case LaneChangeKind::kRampHalt: return "halt on the ramp";
  }
  return "?";
}

int lane_at(const RoadLayout& road, double s_m, double d_m) {
  const double half = 0.5 * road.lane_width_m;
  for (std::size_t k = 0; k < road.main_lanes.size(); ++k) {
    if (std::abs(d_m - road.main_lanes[k].centre_d_at(s_m)) < half) return static_cast<int>(k);
  }
  int best = 0;
  double best_dist = std::abs(d_m - road.main_lanes[0].centre_d_at(s_m));
  for (std::size_t k = 1; k < road.main_lanes.size(); ++k) {
    const double dist = std::abs(d_m - road.main_lanes[k].centre_d_at(s_m));
    if (dist < best_dist) best_dist = dist, best = static_cast<int>(k);
  }
  if (s_m <= road.ramp_end_s_m && std::abs(d_m - road.ramp.centre_d_at(s_m)) < best_dist) return kRampLane;
  return best;
}

std::vector<int> lane_sequence(const FrenetTrack& t, const RoadLayout& road, int min_steps) {
  std::vector<int> lanes;
  for (const TrackState& s : t.states) lanes.push_back(lane_at(road, s.s_m, s.d_m));
  // Short runs (noise at a lane line) take the lane of the last long run (at the start: of the
  // first long one). One pass, so that a hostile track flipping lanes every step costs O(n).
  std::vector<std::pair<std::size_t, std::size_t>> runs;  // [begin, end)
  for (std::size_t i = 0; i < lanes.size();) {
    std::size_t j = i;
    while (j < lanes.size() && lanes[j] == lanes[i]) ++j;
    runs.emplace_back(i, j);
    i = j;
  }
  std::optional<int> accepted;
  for (const auto& [b, e] : runs) {
    if (static_cast<int>(e - b) >= min_steps) {
      if (!accepted) std::fill(lanes.begin(), lanes.begin() + static_cast<long>(b), lanes[b]);
      accepted = lanes[b];
    } else if (accepted) {
      std::fill(lanes.begin() + static_cast<long>(b), lanes.begin() + static_cast<long>(e), *accepted);
    }
  }
  return lanes;
}

namespace {

void changes_of(const FrenetTrack& t, const RoadLayout& road, const MergeFinderParams& p, std::vector<LaneChange>& out) {
  const std::vector<int> lanes = lane_sequence(t, road, p.min_steps_in_lane);
  bool merged_from_ramp = false;
  for (std::size_t i = 1; i < lanes.size(); ++i) {
    if (lanes[i] == lanes[i - 1]) continue;
    LaneChange c{t.vehicle_id, LaneChangeKind::kCutIn, lanes[i - 1], lanes[i], t.states[i].time_step, t.states[i].s_m};
    if (lanes[i - 1] == kRampLane) {
      c.kind = LaneChangeKind::kRampMerge;
      merged_from_ramp = true;
    } else if (lanes[i] == kRampLane) {
      c.kind = LaneChangeKind::kIntoRamp;
    }
    out.push_back(c);
  }
  if (merged_from_ramp) return;
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    const TrackState& s = t.states[i];
    if (lanes[i] == kRampLane && s.speed_mps < p.halted_speed_mps && road.ramp_end_s_m - s.s_m < p.halt_near_end_m) {
      out.push_back({t.vehicle_id, LaneChangeKind::kRampHalt, kRampLane, 0, s.time_step, s.s_m});
      return;
    }
  }
}

}  // namespace

std::vector<LaneChange> find_lane_changes(const std::vector<FrenetTrack>& tracks, const RoadLayout& road,
                                          const MergeFinderParams& p) {
  std::vector<LaneChange> out;
  for (const FrenetTrack& t : tracks) changes_of(t, road, p, out);
  std::sort(out.begin(), out.end(), [](const LaneChange& a, const LaneChange& b) {
    return a.time_step != b.time_step ? a.time_step < b.time_step : a.vehicle_id < b.vehicle_id;
  });
  return out;
}

}  // namespace mg
