#include "core/scenario.h"

#include <cmath>
#include <set>

#include "core/atomic_file.h"
#include "core/json_reader.h"

namespace mg {
namespace {

constexpr double kMaxPositionM = 1e5;      // |X| bound of any initial position
constexpr double kMaxSpeedMps = 100.0;     // 360 km/h: beyond any road vehicle
constexpr std::int64_t kMaxSeed = 9007199254740991;  // 2^53 - 1, exact in every JSON reader

struct NamedBehaviour {
  BehaviourType type;
  const char* name;
};
constexpr NamedBehaviour kBehaviours[] = {
    {BehaviourType::kConstantSpeed, "constant_speed"}, {BehaviourType::kIdm, "idm"},
    {BehaviourType::kRssFollower, "rss_follower"},     {BehaviourType::kBoundedRandom, "bounded_random"},
    {BehaviourType::kCooperative, "cooperative"},      {BehaviourType::kNonResponsive, "non_responsive"},
};

struct NamedNonCompliance {
  NonComplianceType type;
  const char* name;
};
constexpr NamedNonCompliance kNonCompliances[] = {
    {NonComplianceType::kNone, "none"},
    {NonComplianceType::kExceedAccel, "exceed_accel"},
    {NonComplianceType::kExceedBrake, "exceed_brake"},
    {NonComplianceType::kRenege, "renege"},
};

Road read_road(const ObjectReader& r) {
  r.only_keys({"lane_width_m", "main_lanes", "side_lane_start_x_m", "side_lane_end_x_m", "speed_limit_mps"});
  Road road;
  road.lane_width_m = r.number_or("lane_width_m", road.lane_width_m, 2.0, 6.0);
  road.main_lanes = static_cast<int>(r.integer_or("main_lanes", road.main_lanes, 1, 4));
  road.side_lane_start_x_m = r.number_or("side_lane_start_x_m", road.side_lane_start_x_m, -kMaxPositionM, kMaxPositionM);
  road.side_lane_end_x_m = r.number_or("side_lane_end_x_m", road.side_lane_end_x_m, -kMaxPositionM, kMaxPositionM);
  if (road.side_lane_end_x_m < road.side_lane_start_x_m + 10.0)
    r.fail("side_lane_end_x_m", "the side lane must end at least 10 m after it starts (side_lane_start_x_m = " +
                                    std::to_string(road.side_lane_start_x_m) + ")");
  road.speed_limit_mps = r.positive_or("speed_limit_mps", road.speed_limit_mps, kMaxSpeedMps);
  return road;
}

VehicleSize read_size(const ObjectReader& r, VehicleSize size) {
  size.length_m = r.positive_or("length_m", size.length_m, 30.0);
  size.width_m = r.positive_or("width_m", size.width_m, 5.0);
  size.height_m = r.positive_or("height_m", size.height_m, 6.0);
  return size;
}

Limits read_limits(const ObjectReader& r) {
  r.only_keys({"accel_max_mps2", "brake_min_mps2", "brake_max_mps2", "lat_accel_max_mps2", "lat_brake_min_mps2"});
  Limits l;
  l.accel_max_mps2 = r.number_or("accel_max_mps2", l.accel_max_mps2, 0.0, 15.0);
  l.brake_max_mps2 = r.positive_or("brake_max_mps2", l.brake_max_mps2, 15.0);
  l.brake_min_mps2 = r.positive_or("brake_min_mps2", l.brake_min_mps2, 15.0);
  if (l.brake_min_mps2 > l.brake_max_mps2)
    r.fail("brake_min_mps2", "must be <= brake_max_mps2 (" + std::to_string(l.brake_max_mps2) + ")");
  l.lat_accel_max_mps2 = r.number_or("lat_accel_max_mps2", l.lat_accel_max_mps2, 0.0, 10.0);
  l.lat_brake_min_mps2 = r.positive_or("lat_brake_min_mps2", l.lat_brake_min_mps2, 10.0);
  return l;
}

V2v read_v2v(const ObjectReader& r) {
  r.only_keys({"capable", "latency_s", "loss_prob"});
  V2v v;
  v.capable = r.boolean_or("capable", v.capable);
  v.latency_s = r.number_or("latency_s", v.latency_s, 0.0, 10.0);
  v.loss_prob = r.number_or("loss_prob", v.loss_prob, 0.0, 1.0);
  return v;
}

Behaviour read_behaviour(const ObjectReader& r) {
  r.only_keys({"type", "desired_speed_mps", "time_headway_s", "min_gap_m", "comfort_brake_mps2", "seed", "segment_s"});
  Behaviour b;
  const std::string name = r.string("type");
  bool known = false;
  std::string names;
  for (const auto& nb : kBehaviours) {
    names += std::string(names.empty() ? "" : ", ") + nb.name;
    if (name == nb.name) {
      b.type = nb.type;
      known = true;
    }
  }
  if (!known) r.fail("type", "unknown behaviour '" + name + "' (expected one of " + names + ")");
  b.desired_speed_mps = r.number_or("desired_speed_mps", b.desired_speed_mps, 0.0, kMaxSpeedMps);
  b.time_headway_s = r.number_or("time_headway_s", b.time_headway_s, 0.0, 10.0);
  b.min_gap_m = r.number_or("min_gap_m", b.min_gap_m, 0.0, 100.0);
  b.comfort_brake_mps2 = r.positive_or("comfort_brake_mps2", b.comfort_brake_mps2, 15.0);
  b.seed = static_cast<std::uint64_t>(r.integer_or("seed", static_cast<long long>(b.seed), 0, kMaxSeed));
  b.segment_s = r.number_or("segment_s", b.segment_s, 0.1, 100.0);
  return b;
}

NonCompliance read_noncompliance(const ObjectReader& r) {
  r.only_keys({"type", "start_time_s", "duration_s", "accel_mps2"});
  NonCompliance n;
  const std::string name = r.string("type");
  bool known = false;
  for (const auto& nn : kNonCompliances) {
    if (name == nn.name) {
      n.type = nn.type;
      known = true;
    }
  }
  if (!known) r.fail("type", "unknown non-compliance '" + name + "' (expected none, exceed_accel, exceed_brake or renege)");
  n.start_time_s = r.number_or("start_time_s", n.start_time_s, 0.0, 3600.0);
  n.duration_s = r.positive_or("duration_s", n.duration_s, 1e9);
  n.accel_mps2 = r.number_or("accel_mps2", n.accel_mps2, 0.0, 30.0);
  return n;
}

EgoDynamics read_dynamics(const ObjectReader& r) {
  r.only_keys({"mass_kg", "yaw_inertia_kgm2", "cg_to_front_m", "cg_to_rear_m", "cornering_front_npr",
               "cornering_rear_npr", "steer_max_rad", "steer_rate_max_radps"});
  EgoDynamics d;
  d.mass_kg = r.number_or("mass_kg", d.mass_kg, 100.0, 50000.0);
  d.yaw_inertia_kgm2 = r.number_or("yaw_inertia_kgm2", d.yaw_inertia_kgm2, 10.0, 1e6);
  d.cg_to_front_m = r.positive_or("cg_to_front_m", d.cg_to_front_m, 10.0);
  d.cg_to_rear_m = r.positive_or("cg_to_rear_m", d.cg_to_rear_m, 10.0);
  d.cornering_front_npr = r.positive_or("cornering_front_npr", d.cornering_front_npr, 1e7);
  d.cornering_rear_npr = r.positive_or("cornering_rear_npr", d.cornering_rear_npr, 1e7);
  d.steer_max_rad = r.positive_or("steer_max_rad", d.steer_max_rad, 1.5);
  d.steer_rate_max_radps = r.positive_or("steer_rate_max_radps", d.steer_rate_max_radps, 10.0);
  return d;
}

Ego read_ego(const ObjectReader& r, const Road& road) {
  r.only_keys({"x_m", "y_m", "speed_mps", "length_m", "width_m", "height_m", "limits", "v2v", "dynamics"});
  Ego e;
  e.x_m = r.number("x_m", -kMaxPositionM, kMaxPositionM);
  const double w = road.lane_width_m;
  e.y_m = r.number_or("y_m", -w, -1.5 * w, (road.main_lanes - 0.5) * w);
  e.speed_mps = r.number("speed_mps", 0.0, kMaxSpeedMps);
  e.size = read_size(r, e.size);
  if (r.has("limits")) e.limits = read_limits(r.object("limits"));
  if (r.has("v2v")) e.v2v = read_v2v(r.object("v2v"));
  if (r.has("dynamics")) e.dynamics = read_dynamics(r.object("dynamics"));
  if (e.y_m < -0.5 * w && (e.x_m < road.side_lane_start_x_m || e.x_m >= road.side_lane_end_x_m))
    r.fail("x_m", "the ego starts in the side lane but outside [side_lane_start_x_m, side_lane_end_x_m)");
  return e;
}

MainVehicle read_vehicle(const ObjectReader& r, const Road& road) {
  r.only_keys({"id", "lane", "x_m", "speed_mps", "length_m", "width_m", "height_m", "limits", "behaviour", "v2v",
               "noncompliance"});
  MainVehicle v;
  v.id = static_cast<int>(r.integer("id", 1, 1000000));
  v.lane = static_cast<int>(r.integer_or("lane", 0, 0, road.main_lanes - 1));
  v.x_m = r.number("x_m", -kMaxPositionM, kMaxPositionM);
  v.speed_mps = r.number("speed_mps", 0.0, kMaxSpeedMps);
  v.size = read_size(r, v.size);
  if (r.has("limits")) v.limits = read_limits(r.object("limits"));
  if (r.has("behaviour")) v.behaviour = read_behaviour(r.object("behaviour"));
  if (r.has("v2v")) v.v2v = read_v2v(r.object("v2v"));
  if (r.has("noncompliance")) v.noncompliance = read_noncompliance(r.object("noncompliance"));
  return v;
}

// Two vehicles in the same lane whose boxes overlap at t = 0 make no sense as a scenario.
void check_no_initial_overlap(const Scenario& s, const ObjectReader& root) {
  for (std::size_t i = 0; i < s.vehicles.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      const auto& a = s.vehicles[i];
      const auto& b = s.vehicles[k];
      if (a.lane == b.lane && std::abs(a.x_m - b.x_m) < 0.5 * (a.size.length_m + b.size.length_m))
        throw InputError(root.source(), "/vehicles/" + std::to_string(i) + "/x_m",
                         "overlaps vehicle id " + std::to_string(b.id) + " at t = 0");
    }
  }
  const double w = s.road.lane_width_m;
  for (std::size_t i = 0; i < s.vehicles.size(); ++i) {
    const auto& v = s.vehicles[i];
    const bool same_lateral = std::abs(s.ego.y_m - v.lane * w) < 0.5 * (s.ego.size.width_m + v.size.width_m);
    if (same_lateral && std::abs(s.ego.x_m - v.x_m) < 0.5 * (s.ego.size.length_m + v.size.length_m))
      throw InputError(root.source(), "/vehicles/" + std::to_string(i) + "/x_m", "overlaps the ego at t = 0");
  }
}

nlohmann::json v2v_to_json(const V2v& v) {
  return {{"capable", v.capable}, {"latency_s", v.latency_s}, {"loss_prob", v.loss_prob}};
}

nlohmann::json behaviour_to_json(const Behaviour& b) {
  nlohmann::json j = {{"type", to_string(b.type)},     {"time_headway_s", b.time_headway_s},
                      {"min_gap_m", b.min_gap_m},      {"comfort_brake_mps2", b.comfort_brake_mps2},
                      {"seed", b.seed},                {"segment_s", b.segment_s}};
  if (b.desired_speed_mps >= 0.0) j["desired_speed_mps"] = b.desired_speed_mps;
  return j;
}

}  // namespace

std::string to_string(BehaviourType t) {
  for (const auto& nb : kBehaviours)
    if (nb.type == t) return nb.name;
  return "unknown";
}

std::string to_string(NonComplianceType t) {
  for (const auto& nn : kNonCompliances)
    if (nn.type == t) return nn.name;
  return "unknown";
}

int Scenario::index_of(int id) const {
  for (std::size_t i = 0; i < vehicles.size(); ++i)
    if (vehicles[i].id == id) return static_cast<int>(i);
  return -1;
}

Scenario scenario_from_json(const nlohmann::json& j, const std::string& source) {
  ObjectReader r(j, source, "");
  r.only_keys({"format_version", "name", "description", "road", "ego", "vehicles", "params"});
  const auto version = r.integer("format_version", 0, 1000000);
  if (version != kScenarioFormatVersion)
    r.fail("format_version", "unsupported scenario format version " + std::to_string(version) +
                                 " (this build reads version " + std::to_string(kScenarioFormatVersion) + ")");
  Scenario s;
  s.name = r.string_or("name", s.name);
  s.description = r.string_or("description", "");
  if (r.has("road")) s.road = read_road(r.object("road"));
  s.ego = read_ego(r.object("ego"), s.road);
  if (r.has("vehicles")) {
    const auto& list = r.array("vehicles");
    if (list.size() > kMaxVehicles)
      r.fail("vehicles", "at most " + std::to_string(kMaxVehicles) + " vehicles, got " + std::to_string(list.size()));
    std::set<int> ids;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string path = "/vehicles/" + std::to_string(i);
      s.vehicles.push_back(read_vehicle(ObjectReader(list[i], source, path), s.road));
      if (!ids.insert(s.vehicles.back().id).second)
        throw InputError(source, path + "/id", "duplicate vehicle id " + std::to_string(s.vehicles.back().id));
    }
  }
  if (r.has("params")) s.params = params_from_json(r.value().at("params"), source, "/params");
  check_no_initial_overlap(s, r);
  return s;
}

Scenario load_scenario(const std::string& path) { return scenario_from_json(parse_json_file(path), path); }

nlohmann::json scenario_to_json(const Scenario& s) {
  nlohmann::json vehicles = nlohmann::json::array();
  for (const auto& v : s.vehicles) {
    vehicles.push_back({{"id", v.id},
                        {"lane", v.lane},
                        {"x_m", v.x_m},
                        {"speed_mps", v.speed_mps},
                        {"length_m", v.size.length_m},
                        {"width_m", v.size.width_m},
                        {"height_m", v.size.height_m},
                        {"limits", limits_to_json(v.limits)},
                        {"behaviour", behaviour_to_json(v.behaviour)},
                        {"v2v", v2v_to_json(v.v2v)},
                        {"noncompliance",
                         {{"type", to_string(v.noncompliance.type)},
                          {"start_time_s", v.noncompliance.start_time_s},
                          {"duration_s", v.noncompliance.duration_s},
                          {"accel_mps2", v.noncompliance.accel_mps2}}}});
  }
  const auto& d = s.ego.dynamics;
  return {
      {"format_version", kScenarioFormatVersion},
      {"name", s.name},
      {"description", s.description},
      {"road", road_to_json(s.road)},
      {"ego",
       {{"x_m", s.ego.x_m},
        {"y_m", s.ego.y_m},
        {"speed_mps", s.ego.speed_mps},
        {"length_m", s.ego.size.length_m},
        {"width_m", s.ego.size.width_m},
        {"height_m", s.ego.size.height_m},
        {"limits", limits_to_json(s.ego.limits)},
        {"v2v", v2v_to_json(s.ego.v2v)},
        {"dynamics",
         {{"mass_kg", d.mass_kg},
          {"yaw_inertia_kgm2", d.yaw_inertia_kgm2},
          {"cg_to_front_m", d.cg_to_front_m},
          {"cg_to_rear_m", d.cg_to_rear_m},
          {"cornering_front_npr", d.cornering_front_npr},
          {"cornering_rear_npr", d.cornering_rear_npr},
          {"steer_max_rad", d.steer_max_rad},
          {"steer_rate_max_radps", d.steer_rate_max_radps}}}}},
      {"vehicles", vehicles},
      {"params", params_to_json(s.params)},
  };
}

Road road_from_json(const nlohmann::json& j, const std::string& source, const std::string& path) {
  return read_road(ObjectReader(j, source, path));
}

Limits limits_from_json(const nlohmann::json& j, const std::string& source, const std::string& path) {
  return read_limits(ObjectReader(j, source, path));
}

VehicleSize vehicle_size_from_json(const nlohmann::json& j, const std::string& source, const std::string& path) {
  const ObjectReader r(j, source, path);
  r.only_keys({"length_m", "width_m", "height_m"});
  return read_size(r, VehicleSize{});
}

nlohmann::json road_to_json(const Road& road) {
  return {{"lane_width_m", road.lane_width_m},
          {"main_lanes", road.main_lanes},
          {"side_lane_start_x_m", road.side_lane_start_x_m},
          {"side_lane_end_x_m", road.side_lane_end_x_m},
          {"speed_limit_mps", road.speed_limit_mps}};
}

nlohmann::json limits_to_json(const Limits& l) {
  return {{"accel_max_mps2", l.accel_max_mps2},         {"brake_min_mps2", l.brake_min_mps2},
          {"brake_max_mps2", l.brake_max_mps2},         {"lat_accel_max_mps2", l.lat_accel_max_mps2},
          {"lat_brake_min_mps2", l.lat_brake_min_mps2}};
}

nlohmann::json vehicle_size_to_json(const VehicleSize& size) {
  return {{"length_m", size.length_m}, {"width_m", size.width_m}, {"height_m", size.height_m}};
}

void write_scenario(const Scenario& s, const std::string& path) {
  write_file_atomic(path, scenario_to_json(s).dump(2) + "\n");
}

}  // namespace mg
