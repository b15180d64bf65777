#include "recording/road_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>

#include "core/input_error.h"

namespace mg {
namespace {

using LaneletMap = std::map<int, const Lanelet*>;

bool has_type(const Lanelet& l, const std::string& t) { return std::find(l.types.begin(), l.types.end(), t) != l.types.end(); }

// Distance of p from the line through a with heading h.
double off_line_m(Point2 p, Point2 a, double h) {
  return std::abs(-(p.x_m - a.x_m) * std::sin(h) + (p.y_m - a.y_m) * std::cos(h));
}

// Of the predecessors of a lanelet where lanes join, the one it continues straight (the others
// merge into it): the one whose start lies closest to the line of its first segment.
int straight_predecessor(const Lanelet& s, const LaneletMap& by_id) {
  const std::vector<Point2> c = lanelet_centre(s);
  const double h = std::atan2(c[1].y_m - c[0].y_m, c[1].x_m - c[0].x_m);
  int best = s.predecessors.front();
  double best_off = 1e300;
  for (const int p : s.predecessors) {
    const double off = off_line_m(lanelet_centre(*by_id.at(p)).front(), c.front(), h);
    if (off < best_off) best_off = off, best = p;
  }
  return best;
}

// The successor that continues lanelet p's lane, if any.
std::optional<int> continuation(const Lanelet& p, const LaneletMap& by_id) {
  if (p.successors.size() != 1) return std::nullopt;
  const Lanelet& s = *by_id.at(p.successors.front());
  if (s.predecessors.size() == 1) return s.id;
  if (straight_predecessor(s, by_id) == p.id) return s.id;
  return std::nullopt;
}

std::vector<std::vector<int>> lane_chains(const Recording& r, const LaneletMap& by_id) {
  std::set<int> continued;
  for (const Lanelet& l : r.lanelets) {
    if (const auto c = continuation(l, by_id)) continued.insert(*c);
  }
  std::vector<std::vector<int>> chains;
  for (const Lanelet& l : r.lanelets) {
    if (continued.count(l.id)) continue;
    std::vector<int> chain{l.id};
    while (const auto c = continuation(*by_id.at(chain.back()), by_id)) {
      if (std::find(chain.begin(), chain.end(), *c) != chain.end()) break;  // a loop: stop
      chain.push_back(*c);
    }
    chains.push_back(chain);
  }
  return chains;
}

std::vector<Point2> joined(const std::vector<int>& ids, const LaneletMap& by_id, std::vector<Point2> (*part)(const Lanelet&)) {
  std::vector<Point2> out;
  for (const int id : ids) {
    for (const Point2& p : part(*by_id.at(id))) {
      if (!out.empty() && std::hypot(p.x_m - out.back().x_m, p.y_m - out.back().y_m) < 1e-6) continue;
      out.push_back(p);
    }
  }
  return out;
}

Lane make_lane(const std::vector<int>& ids, const LaneletMap& by_id, const std::string& source) {
  Lane lane;
  lane.lanelet_ids = ids;
  lane.centre = joined(ids, by_id, lanelet_centre);
  // The road is resampled every metre and every position projected onto it: bound the work.
  if (polyline_length_m(lane.centre) > kMaxLaneLengthM) {
    throw InputError(source, "lanelet " + std::to_string(ids.front()),
                     "a lane of " + std::to_string(polyline_length_m(lane.centre)) + " m is longer than a recording covers (at most 20 km)");
  }
  lane.left_bound = joined(ids, by_id, [](const Lanelet& l) { return l.left_bound; });
  lane.right_bound = joined(ids, by_id, [](const Lanelet& l) { return l.right_bound; });
  double width = 0.0;
  const auto l = resample_polyline(lane.left_bound, 1.0);
  const auto rr = resample_polyline(lane.right_bound, l.size() > 1 ? polyline_length_m(lane.right_bound) / (l.size() - 1) : 1.0);
  const std::size_t n = std::min(l.size(), rr.size());
  for (std::size_t i = 0; i < n; ++i) width += std::hypot(l[i].x_m - rr[i].x_m, l[i].y_m - rr[i].y_m) / n;
  lane.mean_width_m = width;
  return lane;
}

void locate_lane(Lane& lane, const ReferenceLine& ref) {
  for (const Point2& p : resample_polyline(lane.centre, 1.0)) lane.centre_sd.push_back(ref.project(p));
  std::sort(lane.centre_sd.begin(), lane.centre_sd.end(), [](const FrenetPoint& a, const FrenetPoint& b) { return a.s_m < b.s_m; });
  lane.start_s_m = lane.centre_sd.front().s_m;
  lane.end_s_m = lane.centre_sd.back().s_m;
}

struct Chains {
  std::vector<std::vector<int>> lanes;
  std::map<int, std::size_t> chain_of;  // lanelet id -> index in lanes
};

// The chain on the given side of chain c (through any of its lanelets' adjacency), if any.
std::optional<std::size_t> neighbour(const Chains& ch, std::size_t c, bool left, const LaneletMap& by_id) {
  for (const int id : ch.lanes[c]) {
    const Lanelet& l = *by_id.at(id);
    const auto adj = left ? l.adjacent_left : l.adjacent_right;
    if (adj && ch.chain_of.at(*adj) != c) return ch.chain_of.at(*adj);
  }
  return std::nullopt;
}

struct RampChoice {
  std::size_t ramp = 0;
  std::size_t joins = 0;  // the main lane it joins
  RampSide side = RampSide::kRight;
  std::string found_by;
};

std::optional<RampChoice> ramp_by_type(const Chains& ch, const LaneletMap& by_id) {
  for (std::size_t c = 0; c < ch.lanes.size(); ++c) {
    if (!std::any_of(ch.lanes[c].begin(), ch.lanes[c].end(), [&](int id) { return has_type(*by_id.at(id), "accessRamp"); })) continue;
    for (const bool left : {true, false}) {
      const auto n = neighbour(ch, c, left, by_id);
      if (n) return RampChoice{c, *n, left ? RampSide::kRight : RampSide::kLeft, "laneletType accessRamp"};
    }
    const int last = ch.lanes[c].back();
    for (const int s : by_id.at(last)->successors) {
      return RampChoice{c, ch.chain_of.at(s), RampSide::kRight, "laneletType accessRamp (joins by its successor)"};
    }
  }
  return std::nullopt;
}

std::optional<RampChoice> ramp_by_topology(const Chains& ch, const LaneletMap& by_id) {
  // A lane whose successor continues another lane: it merges into that lane (a zipper or a ramp).
  for (std::size_t c = 0; c < ch.lanes.size(); ++c) {
    const Lanelet& last = *by_id.at(ch.lanes[c].back());
    if (last.successors.size() != 1) continue;
    const std::size_t into = ch.chain_of.at(last.successors.front());
    if (into == c) continue;
    const bool main_on_right = neighbour(ch, c, false, by_id).has_value();
    return RampChoice{c, into, main_on_right ? RampSide::kLeft : RampSide::kRight,
                      "topology: its successor is a main lane's continuation (the lanes join)"};
  }
  // Otherwise the rightmost lane that ends with a main lane on its left.
  for (std::size_t c = 0; c < ch.lanes.size(); ++c) {
    if (neighbour(ch, c, false, by_id)) continue;
    const auto left = neighbour(ch, c, true, by_id);
    if (!left || !by_id.at(ch.lanes[c].back())->successors.empty()) continue;
    return RampChoice{c, *left, RampSide::kRight, "topology: the rightmost lane, which ends with a main lane on its left"};
  }
  return std::nullopt;
}

// The main lanes from the one the ramp joins outwards, away from the ramp.
std::vector<std::size_t> main_lane_order(const Chains& ch, const RampChoice& rc, const LaneletMap& by_id) {
  std::vector<std::size_t> order{rc.joins};
  const bool outwards_left = rc.side == RampSide::kRight;
  while (const auto n = neighbour(ch, order.back(), outwards_left, by_id)) {
    if (*n == rc.ramp || std::find(order.begin(), order.end(), *n) != order.end()) break;
    order.push_back(*n);
  }
  return order;
}

bool any_type(const std::vector<int>& ids, const LaneletMap& by_id, std::initializer_list<const char*> types) {
  for (const int id : ids) {
    for (const char* t : types) {
      if (has_type(*by_id.at(id), t)) return true;
    }
  }
  return false;
}

bool has_tag(const Recording& r, const char* tag) {
  return std::find(r.scenario_tags.begin(), r.scenario_tags.end(), tag) != r.scenario_tags.end();
}

// How far (along the reference line) the ramp's centre runs within 1.6 lane widths of the
// joined lane's centre: a ramp's acceleration lane or taper runs beside it, a turn at a
// junction meets it within a few metres.
double alongside_m(const RoadLayout& road) {
  double along = 0.0;
  const Lane& main = road.main_lanes.front();
  const auto& pts = road.ramp.centre_sd;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const bool beside = std::abs(pts[i].d_m - main.centre_d_at(pts[i].s_m)) <= 1.6 * road.lane_width_m && main.covers(pts[i].s_m);
    if (beside) along += std::max(0.0, pts[i].s_m - pts[i - 1].s_m);
  }
  return along;
}

std::string num1(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

// The speed limit the lanelets give the ramp and the lane it joins (the lowest), 0 for none.
double join_speed_limit_mps(const std::vector<int>& ids, const LaneletMap& by_id) {
  double lowest = 0.0;
  for (const int id : ids) {
    const auto& l = by_id.at(id)->speed_limit_mps;
    if (l && (lowest == 0.0 || *l < lowest)) lowest = *l;
  }
  return lowest;
}

void classify_join(const Recording& r, const std::vector<int>& ramp_ids, const std::vector<int>& main_ids, const LaneletMap& by_id,
                   RoadLayout& road) {
  std::vector<int> both = ramp_ids;
  both.insert(both.end(), main_ids.begin(), main_ids.end());
  const auto set = [&](bool yes, std::string basis) {
    road.highway_on_ramp = yes;
    road.on_ramp_basis = std::move(basis);
  };
  if (any_type(ramp_ids, by_id, {"accessRamp"})) return set(true, "laneletType accessRamp");
  if (any_type(both, by_id, {"highway", "interstate", "mainCarriageWay"})) return set(true, "laneletType highway, interstate or mainCarriageWay");
  if (any_type(ramp_ids, by_id, {"intersection"})) return set(false, "the joining lanelet is typed intersection");
  for (const char* tag : {"interstate", "highway"}) {
    if (has_tag(r, tag)) return set(true, std::string("scenario tag ") + tag + (r.version == "2018b" ? " (2018b tags)" : " (2020a scenarioTags)"));
  }
  const double along_m = alongside_m(road);
  const double limit_mps = join_speed_limit_mps(both, by_id);
  const std::string measured = "the joining lane runs beside the main lane for " + num1(along_m) + " m" +
                               (limit_mps > 0 ? ", speed limit " + num1(limit_mps * 3.6) + " km/h" : ", no speed limit given");
  if (along_m >= kRampMinAlongsideM && (limit_mps == 0.0 || limit_mps >= kRampMinSpeedLimitMps)) {
    return set(true, "geometry and speed limit of a ramp: " + measured);
  }
  set(false, "no map attribute says highway, and not the geometry or speed limit of a ramp: " + measured);
}

}  // namespace

std::vector<Point2> lanelet_centre(const Lanelet& l) {
  const std::size_t n = std::max(l.left_bound.size(), l.right_bound.size());
  const double left_len = polyline_length_m(l.left_bound), right_len = polyline_length_m(l.right_bound);
  const auto a = resample_polyline(l.left_bound, std::max(left_len, 1e-3) / (n - 1));
  const auto b = resample_polyline(l.right_bound, std::max(right_len, 1e-3) / (n - 1));
  std::vector<Point2> c;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) c.push_back({0.5 * (a[i].x_m + b[i].x_m), 0.5 * (a[i].y_m + b[i].y_m)});
  return c;
}

double Lane::centre_d_at(double s_m) const {
  if (s_m <= centre_sd.front().s_m) return centre_sd.front().d_m;
  if (s_m >= centre_sd.back().s_m) return centre_sd.back().d_m;
  const auto it = std::lower_bound(centre_sd.begin(), centre_sd.end(), s_m, [](const FrenetPoint& p, double s) { return p.s_m < s; });
  const FrenetPoint& b = *it;
  const FrenetPoint& a = *(it - 1);
  const double t = b.s_m > a.s_m ? (s_m - a.s_m) / (b.s_m - a.s_m) : 0.0;
  return a.d_m + t * (b.d_m - a.d_m);
}

std::string Lane::name() const {
  std::string s = lanelet_ids.size() == 1 ? "lanelet " : "lanelets ";
  for (std::size_t i = 0; i < lanelet_ids.size(); ++i) s += (i ? "-" : "") + std::to_string(lanelet_ids[i]);
  return s;
}

std::optional<RoadLayout> find_road_layout(const Recording& r) {
  LaneletMap by_id;
  for (const Lanelet& l : r.lanelets) by_id[l.id] = &l;
  Chains ch;
  ch.lanes = lane_chains(r, by_id);
  for (std::size_t c = 0; c < ch.lanes.size(); ++c) {
    for (const int id : ch.lanes[c]) ch.chain_of[id] = c;
  }
  std::optional<RampChoice> rc = ramp_by_type(ch, by_id);
  if (!rc) rc = ramp_by_topology(ch, by_id);
  if (!rc) return std::nullopt;
  const std::vector<std::size_t> order = main_lane_order(ch, *rc, by_id);
  RoadLayout road{ReferenceLine(make_lane(ch.lanes[rc->joins], by_id, r.source).centre), {}, make_lane(ch.lanes[rc->ramp], by_id, r.source), rc->side, 0, 0, 0, rc->found_by, true, ""};
  double width = 0.0;
  for (const std::size_t c : order) {
    road.main_lanes.push_back(make_lane(ch.lanes[c], by_id, r.source));
    locate_lane(road.main_lanes.back(), road.reference);
    width += road.main_lanes.back().mean_width_m / order.size();
  }
  locate_lane(road.ramp, road.reference);
  if (width < 2.0 || width > 6.0) {
    throw InputError(r.source, "lanelet " + std::to_string(ch.lanes[rc->joins].front()), "mean main lane width " + std::to_string(width) + " m outside [2, 6]");
  }
  road.lane_width_m = width;
  road.ramp_end_s_m = road.ramp.end_s_m;
  for (const Lanelet& l : r.lanelets) {
    if (l.speed_limit_mps) road.speed_limit_mps = std::max(road.speed_limit_mps, *l.speed_limit_mps);
  }
  classify_join(r, ch.lanes[rc->ramp], ch.lanes[rc->joins], by_id, road);
  return road;
}

RoadLayout build_road_layout(const Recording& r) {
  std::optional<RoadLayout> road = find_road_layout(r);
  if (!road) throw InputError(r.source, "lanelets", "no ramp found (no accessRamp lanelet, no lane joining another, no rightmost lane ending beside a main lane)");
  return std::move(*road);
}

}  // namespace mg
