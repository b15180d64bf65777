#include "recording/commonroad_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <set>

#include "core/input_error.h"
#include "recording/reference_line.h"

namespace mg {
namespace {

// One element being read, with the path that errors name ("obstacle 363/trajectory/state 4").
struct Node {
  const XmlElement& e;
  std::string path;
  const std::string& source;

  [[noreturn]] void fail(const std::string& what) const { throw InputError(source, path, what); }
  Node child(std::string_view name) const {
    const XmlElement* c = e.first(name);
    if (c == nullptr) fail("missing <" + std::string(name) + ">");
    return {*c, path + "/" + std::string(name), source};
  }
  std::optional<Node> optional_child(std::string_view name) const {
    const XmlElement* c = e.first(name);
    if (c == nullptr) return std::nullopt;
    return Node{*c, path + "/" + std::string(name), source};
  }
  double number(double lo, double hi) const {
    const char* begin = e.text.c_str();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(begin, &end);
    if (e.text.empty() || end != begin + e.text.size()) fail("not a number: \"" + e.text.substr(0, 40) + "\"");
    if (errno == ERANGE || !std::isfinite(v)) fail("non-finite or out-of-range number \"" + e.text.substr(0, 40) + "\"");
    if (v < lo || v > hi) fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + e.text);
    return v;
  }
  int integer_attribute(std::string_view key, long lo, long hi) const {
    const std::string* s = e.attribute(key);
    if (s == nullptr) fail("missing attribute " + std::string(key));
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(s->c_str(), &end, 10);
    if (s->empty() || end != s->c_str() + s->size() || errno == ERANGE || v < lo || v > hi) {
      fail("attribute " + std::string(key) + " must be an integer in [" + std::to_string(lo) + ", " +
           std::to_string(hi) + "], got \"" + s->substr(0, 40) + "\"");
    }
    return static_cast<int>(v);
  }
};

Point2 read_point(const Node& n) {
  return {n.child("x").number(-kMaxRecordingCoordinateM, kMaxRecordingCoordinateM),
          n.child("y").number(-kMaxRecordingCoordinateM, kMaxRecordingCoordinateM)};
}

std::vector<Point2> read_bound(const Node& bound) {
  std::vector<Point2> pts;
  int i = 0;
  for (const XmlElement* p : bound.e.all("point")) pts.push_back(read_point({*p, bound.path + "/point " + std::to_string(i++), bound.source}));
  if (pts.size() < 2) bound.fail("a bound needs at least 2 points, got " + std::to_string(pts.size()));
  // The road is rebuilt by resampling every bound at a spacing in proportion to its length.
  if (!(polyline_length_m(pts) > 0.0)) bound.fail("a bound of zero length (all its points coincide)");
  return pts;
}

std::vector<int> refs(const Node& n, std::string_view name) {
  std::vector<int> out;
  for (const XmlElement* r : n.e.all(name)) {
    out.push_back(Node{*r, n.path + "/" + std::string(name), n.source}.integer_attribute("ref", 0, 2'000'000'000));
  }
  return out;
}

std::optional<int> adjacent(const Node& n, std::string_view name) {
  const auto c = n.optional_child(name);
  if (!c) return std::nullopt;
  const std::string* dir = c->e.attribute("drivingDir");
  if (dir == nullptr) c->fail("missing attribute drivingDir");
  if (*dir != "same" && *dir != "opposite") c->fail("drivingDir must be same or opposite, got \"" + dir->substr(0, 40) + "\"");
  const int ref = c->integer_attribute("ref", 0, 2'000'000'000);
  if (*dir == "opposite") return std::nullopt;  // oncoming lanes take no part in a merge
  return ref;
}

Lanelet read_lanelet(const XmlElement& e, const std::string& source) {
  Lanelet l;
  l.id = Node{e, "lanelet", source}.integer_attribute("id", 0, 2'000'000'000);
  const Node n{e, "lanelet " + std::to_string(l.id), source};
  l.left_bound = read_bound(n.child("leftBound"));
  l.right_bound = read_bound(n.child("rightBound"));
  l.predecessors = refs(n, "predecessor");
  l.successors = refs(n, "successor");
  l.adjacent_left = adjacent(n, "adjacentLeft");
  l.adjacent_right = adjacent(n, "adjacentRight");
  for (const XmlElement* t : e.all("laneletType")) l.types.push_back(t->text);
  if (const auto s = n.optional_child("speedLimit")) l.speed_limit_mps = s->number(0.0, kMaxRecordingSpeedMps);
  return l;
}

// A scalar given exactly or as an interval (read as its centre).
double read_scalar(const Node& n, double lo, double hi, bool& set_valued) {
  if (const auto exact = n.optional_child("exact")) return exact->number(lo, hi);
  const auto start = n.optional_child("intervalStart");
  const auto end = n.optional_child("intervalEnd");
  if (!start || !end) n.fail("neither <exact> nor <intervalStart>/<intervalEnd>");
  const double a = start->number(lo, hi);
  const double b = end->number(lo, hi);
  if (a > b) n.fail("interval start " + start->e.text + " after its end " + end->e.text);
  set_valued = true;
  return 0.5 * (a + b);
}

// A position: a point, or a set (rectangle, circle, polygon) read as its centre.
Point2 read_position(const Node& pos, bool& set_valued) {
  if (const auto p = pos.optional_child("point")) return read_point(*p);
  for (const char* shape : {"rectangle", "circle"}) {
    if (const auto s = pos.optional_child(shape)) {
      set_valued = true;
      return read_point(s->child("center"));
    }
  }
  if (const auto poly = pos.optional_child("polygon")) {
    const std::vector<Point2> pts = read_bound(*poly);
    Point2 c;
    for (const Point2& q : pts) c = {c.x_m + q.x_m / pts.size(), c.y_m + q.y_m / pts.size()};
    set_valued = true;
    return c;
  }
  pos.fail("a position must be a point, rectangle, circle or polygon (a lanelet reference is not supported)");
}

RecordedState read_state(const Node& n) {
  RecordedState s;
  const Node time = n.child("time");
  if (!time.optional_child("exact")) time.fail("a time must be exact (an interval of times is not supported)");
  const double t = time.child("exact").number(0, kMaxRecordingTimeSteps);
  if (t != std::floor(t)) time.fail("a time step must be a whole number, got " + time.child("exact").e.text);
  s.time_step = static_cast<int>(t);
  const Point2 p = read_position(n.child("position"), s.set_valued);
  s.x_m = p.x_m;
  s.y_m = p.y_m;
  if (const auto o = n.optional_child("orientation")) s.orientation_rad = read_scalar(*o, -20.0, 20.0, s.set_valued);
  if (const auto v = n.optional_child("velocity")) s.speed_mps = read_scalar(*v, -kMaxRecordingSpeedMps, kMaxRecordingSpeedMps, s.set_valued);
  if (const auto a = n.optional_child("acceleration")) s.accel_mps2 = read_scalar(*a, -kMaxRecordingAccelMps2, kMaxRecordingAccelMps2, s.set_valued);
  return s;
}

void read_shape(const Node& n, RecordedVehicle& v) {
  const Node shape = n.child("shape");
  if (const auto r = shape.optional_child("rectangle")) {
    v.length_m = r->child("length").number(0.1, 30.0);
    v.width_m = r->child("width").number(0.1, 5.0);
  } else if (const auto c = shape.optional_child("circle")) {
    v.length_m = v.width_m = 2.0 * c->child("radius").number(0.05, 2.5);
  } else {
    shape.fail("a vehicle's shape must be a rectangle or a circle");
  }
}

// States in order: the initial state, then the trajectory's, one time step apart.
void read_states(const Node& n, RecordedVehicle& v) {
  v.states.push_back(read_state(n.child("initialState")));
  if (n.optional_child("occupancySet")) n.fail("occupancy sets are not supported (a trajectory is needed)");
  if (const auto traj = n.optional_child("trajectory")) {
    int i = 0;
    for (const XmlElement* s : traj->e.all("state")) {
      const Node sn{*s, traj->path + "/state " + std::to_string(i++), n.source};
      const RecordedState st = read_state(sn);
      const int prev = v.states.back().time_step;
      if (st.time_step <= prev) sn.fail("time goes backwards (step " + std::to_string(st.time_step) + " after " + std::to_string(prev) + ")");
      if (st.time_step != prev + 1) sn.fail("time gap (step " + std::to_string(st.time_step) + " after " + std::to_string(prev) + ")");
      v.states.push_back(st);
    }
  }
}

RecordedVehicle read_vehicle(const XmlElement& e, const std::string& tag, const std::string& source) {
  RecordedVehicle v;
  v.id = Node{e, tag, source}.integer_attribute("id", 0, 2'000'000'000);
  const Node n{e, tag + " " + std::to_string(v.id), source};
  v.type = n.child("type").e.text;
  if (v.type.empty()) n.child("type").fail("empty obstacle type");
  read_shape(n, v);
  read_states(n, v);
  return v;
}

void check_references(const Recording& r) {
  std::set<int> ids;
  for (const Lanelet& l : r.lanelets) {
    if (!ids.insert(l.id).second) throw InputError(r.source, "lanelet " + std::to_string(l.id), "duplicate lanelet id");
  }
  for (const Lanelet& l : r.lanelets) {
    std::vector<int> all = l.predecessors;
    all.insert(all.end(), l.successors.begin(), l.successors.end());
    if (l.adjacent_left) all.push_back(*l.adjacent_left);
    if (l.adjacent_right) all.push_back(*l.adjacent_right);
    for (const int ref : all) {
      if (ids.count(ref) == 0) {
        throw InputError(r.source, "lanelet " + std::to_string(l.id), "reference to lanelet " + std::to_string(ref) + ", which does not exist");
      }
    }
  }
}

// 2018b: a space-separated `tags` attribute on the root; 2020a: <scenarioTags> with one empty
// element per tag. Both are read in either version (a tag only informs, it is never refused).
void read_scenario_tags(const XmlElement& root, Recording& r) {
  if (const std::string* tags = root.attribute("tags")) {
    std::size_t i = 0;
    while (i < tags->size() && r.scenario_tags.size() < 64) {
      const std::size_t j = std::min(tags->find(' ', i), tags->size());
      if (j > i) r.scenario_tags.push_back(tags->substr(i, std::min<std::size_t>(j - i, 64)));
      i = j + 1;
    }
  }
  if (const XmlElement* tags = root.first("scenarioTags")) {
    for (const XmlElement& t : tags->children) {
      if (r.scenario_tags.size() < 64) r.scenario_tags.push_back(t.name.substr(0, 64));
    }
  }
}

void read_header(const XmlElement& root, Recording& r) {
  const Node n{root, "commonRoad", r.source};
  if (root.name != "commonRoad") n.fail("root element is <" + root.name.substr(0, 40) + ">, not <commonRoad>");
  const std::string* version = root.attribute("commonRoadVersion");
  if (version == nullptr) n.fail("missing attribute commonRoadVersion");
  if (*version != "2018b" && *version != "2020a") n.fail("unknown CommonRoad version \"" + version->substr(0, 40) + "\" (this build reads 2018b and 2020a)");
  r.version = *version;
  const std::string* dt = root.attribute("timeStepSize");
  if (dt == nullptr) n.fail("missing attribute timeStepSize");
  const XmlElement dt_text{"timeStepSize", {}, *dt, {}};
  r.time_step_s = Node{dt_text, "commonRoad/@timeStepSize", r.source}.number(1e-3, 10.0);
  const std::string* id = root.attribute("benchmarkID");
  r.benchmark_id = id != nullptr ? *id : std::string("unnamed");
  read_scenario_tags(root, r);
}

void read_obstacles(const XmlElement& root, Recording& r) {
  const bool v2018 = r.version == "2018b";
  const std::string other = v2018 ? "dynamicObstacle" : "obstacle";
  if (root.first(other) != nullptr) {
    throw InputError(r.source, other, "a <" + other + "> element in a version " + r.version + " file");
  }
  std::set<int> ids;
  for (const XmlElement& e : root.children) {
    const bool dynamic = v2018 ? (e.name == "obstacle" && e.first("role") != nullptr && e.first("role")->text == "dynamic")
                               : e.name == "dynamicObstacle";
    const bool is_static = v2018 ? (e.name == "obstacle" && !dynamic) : e.name == "staticObstacle";
    if (is_static) ++r.static_obstacles;
    if (!dynamic) continue;
    RecordedVehicle v = read_vehicle(e, e.name, r.source);
    if (!ids.insert(v.id).second) throw InputError(r.source, e.name + " " + std::to_string(v.id), "duplicate obstacle id");
    for (const RecordedState& s : v.states) r.set_valued_states += s.set_valued ? 1 : 0;
    r.vehicles.push_back(std::move(v));
    if (r.vehicles.size() > static_cast<std::size_t>(kMaxRecordingVehicles)) throw InputError(r.source, e.name, "too many obstacles");
  }
}

}  // namespace

const Lanelet* Recording::lanelet(int id) const {
  for (const Lanelet& l : lanelets) {
    if (l.id == id) return &l;
  }
  return nullptr;
}

Recording recording_from_xml(const XmlElement& root, const std::string& source) {
  Recording r;
  r.source = source;
  read_header(root, r);
  for (const XmlElement* l : root.all("lanelet")) r.lanelets.push_back(read_lanelet(*l, source));
  if (r.lanelets.empty()) throw InputError(source, "commonRoad", "no lanelets");
  check_references(r);
  read_obstacles(root, r);
  return r;
}

Recording load_recording(const std::string& path) { return recording_from_xml(load_xml_strict(path), path); }

Recording parse_recording(std::string_view xml_text, const std::string& source) {
  return recording_from_xml(parse_xml_strict(xml_text, source), source);
}

}  // namespace mg
