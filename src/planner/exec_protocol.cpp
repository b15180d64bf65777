#include "planner/exec_protocol.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

namespace mg {
namespace {

using nlohmann::json;

constexpr std::size_t kMaxPathPoints = 100000;
constexpr std::size_t kMaxOutbox = 64;

// The start of an offending reply, for a one-line finding.
std::string excerpt(const std::string& line) {
  std::string e = line.substr(0, 80);
  for (char& c : e)
    if (c == '\n' || c == '\r' || static_cast<unsigned char>(c) < 0x20) c = ' ';
  return "'" + e + (line.size() > 80 ? "...'" : "'");
}

json parse_reply(const std::string& line, std::string_view expected_type) {
  json j = json::parse(line, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) throw ProtocolError("reply is not JSON: " + excerpt(line));
  if (!j.is_object()) throw ProtocolError("reply is not a JSON object: " + excerpt(line));
  const auto type = j.find("type");
  if (type == j.end() || !type->is_string() || *type != expected_type)
    throw ProtocolError("expected a reply of type \"" + std::string(expected_type) + "\", got " + excerpt(line));
  return j;
}

const json& member(const json& j, const char* key, const char* where) {
  const auto it = j.find(key);
  if (it == j.end()) throw ProtocolError(std::string(where) + " lacks \"" + key + "\"");
  return *it;
}

double finite_number(const json& v, const std::string& where) {
  if (!v.is_number()) throw ProtocolError(where + " is not a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw ProtocolError(where + " is not finite");
  return x;
}

std::string text(const json& j, const char* key) {
  const json& v = member(j, key, "hello reply");
  if (!v.is_string()) throw ProtocolError(std::string("hello reply: \"") + key + "\" is not a string");
  return v.get<std::string>();
}

std::vector<PathPoint> path_of(const json& command) {
  const json& path = member(command, "path", "command");
  if (!path.is_array() || path.size() < 2) throw ProtocolError("command: \"path\" must be an array of at least two points");
  if (path.size() > kMaxPathPoints) throw ProtocolError("command: \"path\" has more than 100000 points");
  std::vector<PathPoint> out;
  out.reserve(path.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    // Named only when something is wrong: a reply is read on every planner cycle.
    const auto where = [i] { return "command: path[" + std::to_string(i) + "]"; };
    const json& point = path[i];
    if (!point.is_array() || point.size() != 2) throw ProtocolError(where() + " is not an [x_m, y_m] pair");
    const auto coordinate = [&](std::size_t k) {
      const json& v = point[k];
      if (v.is_number() && std::isfinite(v.get<double>())) return v.get<double>();
      return finite_number(v, where() + "[" + std::to_string(k) + "]");  // throws, saying why
    };
    const PathPoint p{coordinate(0), coordinate(1)};
    if (!out.empty() && !(p.x_m > out.back().x_m)) throw ProtocolError(where() + ": x does not increase");
    out.push_back(p);
  }
  return out;
}

V2vMessage message_of(const json& m, const WorldSnapshot& world, const std::string& where) {
  if (!m.is_object()) throw ProtocolError(where + " is not an object");
  V2vMessage out;
  const json& type = member(m, "type", where.c_str());
  if (type == "request") out.type = MessageType::kRequest;
  else if (type == "accept") out.type = MessageType::kAccept;
  else if (type == "refuse") out.type = MessageType::kRefuse;
  else throw ProtocolError(where + ": \"type\" must be \"request\", \"accept\" or \"refuse\"");
  const json& to = member(m, "to_id", where.c_str());
  const auto observed = [&](int id) {
    return std::any_of(world.others.begin(), world.others.end(), [&](const ObservedVehicle& o) { return o.id == id; });
  };
  if (!to.is_number_integer() || !observed(to.get<int>()))
    throw ProtocolError(where + ": \"to_id\" is not the id of a vehicle the planner observes");
  out.to_id = to.get<int>();
  const auto coop = m.find("coop_case");
  if (coop != m.end() && *coop != "ego_ahead" && *coop != "ego_behind")
    throw ProtocolError(where + ": \"coop_case\" must be \"ego_ahead\" or \"ego_behind\"");
  out.coop_case = coop != m.end() && *coop == "ego_behind" ? CoopCase::kEgoBehind : CoopCase::kEgoAhead;
  for (auto [key, field] : {std::pair{"pc_m", &out.pc_m}, std::pair{"d_lon_star_m", &out.d_lon_star_m},
                            std::pair{"target_speed_mps", &out.target_speed_mps}})
    if (m.contains(key)) *field = finite_number(m.at(key), where + "." + key);
  return out;
}

// The observe request is written on every planner cycle (some 45,000 times per second of a
// campaign through a fast planner): written directly, in the shortest text that reads back to the
// same double (std::to_chars), at a fifth of the cost of building it as a nlohmann::json.
class LineWriter {
 public:
  LineWriter& raw(std::string_view text) {
    out_ += text;
    return *this;
  }
  LineWriter& number(std::string_view key, double v) {
    raw(key);
    if (!std::isfinite(v)) return raw("null");
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
    out_.append(buf, end);
    return *this;
  }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

void write_ego(LineWriter& w, const VehicleState& e) {
  w.number("\"ego\":{\"x_m\":", e.x_m).number(",\"y_m\":", e.y_m).number(",\"yaw_rad\":", e.yaw_rad);
  w.number(",\"speed_mps\":", e.vx_mps).number(",\"lat_speed_mps\":", e.vy_mps).number(",\"accel_mps2\":", e.accel_mps2);
  w.number(",\"yaw_rate_radps\":", e.yaw_rate_radps).number(",\"steer_rad\":", e.steer_rad).raw("}");
}

// The keys of limits_to_json (core/scenario.h), which the protocol test holds this to.
void write_other(LineWriter& w, const ObservedVehicle& o) {
  w.number("{\"id\":", o.id).number(",\"x_m\":", o.state.x_m).number(",\"y_m\":", o.state.y_m);
  w.number(",\"yaw_rad\":", o.state.yaw_rad).number(",\"speed_mps\":", o.state.vx_mps);
  w.number(",\"accel_mps2\":", o.state.accel_mps2).number(",\"length_m\":", o.size.length_m);
  w.number(",\"width_m\":", o.size.width_m);
  const Limits& l = o.limits;
  w.number(",\"limits\":{\"accel_max_mps2\":", l.accel_max_mps2).number(",\"brake_min_mps2\":", l.brake_min_mps2);
  w.number(",\"brake_max_mps2\":", l.brake_max_mps2).number(",\"lat_accel_max_mps2\":", l.lat_accel_max_mps2);
  w.number(",\"lat_brake_min_mps2\":", l.lat_brake_min_mps2).raw("},\"v2v_capable\":");
  w.raw(o.v2v_capable ? "true}" : "false}");
}

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json message_json(const V2vMessage& m) {
  const char* type = m.type == MessageType::kRequest ? "request" : m.type == MessageType::kAccept ? "accept" : "refuse";
  return {{"type", type},
          {"from_id", m.from_id},
          {"to_id", m.to_id},
          {"sent_time_s", m.sent_time_s},
          {"delivered_time_s", finite_or_null(m.delivered_time_s)},
          {"coop_case", m.coop_case == CoopCase::kEgoAhead ? "ego_ahead" : "ego_behind"},
          {"pc_m", finite_or_null(m.pc_m)},
          {"d_lon_star_m", finite_or_null(m.d_lon_star_m)},
          {"target_speed_mps", finite_or_null(m.target_speed_mps)}};
}

}  // namespace

std::string hello_request() { return json{{"type", "hello"}, {"protocol", kPlannerProtocol}}.dump(); }

std::string reset_request(const PlannerSetup& setup) {
  Scenario keys;  // the scenario format's own keys for the road, the ego and the parameters
  static_cast<PlannerSetup&>(keys) = setup;
  const json s = scenario_to_json(keys);
  return json{{"type", "reset"}, {"road", s.at("road")}, {"ego", s.at("ego")}, {"params", s.at("params")}}.dump();
}

std::string observe_request(const WorldSnapshot& world) {
  LineWriter w;
  w.number("{\"type\":\"observe\",\"time_s\":", world.time_s).raw(",");
  write_ego(w, world.ego);
  w.raw(",\"others\":[");
  for (std::size_t i = 0; i < world.others.size(); ++i) {
    if (i > 0) w.raw(",");
    write_other(w, world.others[i]);
  }
  json inbox = json::array();  // rare (V2V replies only): as JSON
  for (const V2vMessage& m : world.inbox) inbox.push_back(message_json(m));
  return w.raw("],\"inbox\":").raw(inbox.dump()).raw("}").take();
}

std::string bye_request() { return R"({"type":"bye"})"; }

PlannerIdentity parse_hello_reply(const std::string& line) {
  const json j = parse_reply(line, "hello");
  return {text(j, "name"), text(j, "version")};
}

void parse_ready_reply(const std::string& line) { parse_reply(line, "ready"); }

PlanOutput parse_command_reply(const std::string& line, const WorldSnapshot& world) {
  json j = parse_reply(line, "command");
  PlanOutput out;
  out.path = path_of(j);
  out.target_speed_mps = finite_number(member(j, "target_speed_mps", "command"), "command: target_speed_mps");
  out.accel_limit_mps2 = finite_number(member(j, "accel_limit_mps2", "command"), "command: accel_limit_mps2");
  if (out.target_speed_mps < 0.0 || out.accel_limit_mps2 < 0.0)
    throw ProtocolError("command: target_speed_mps and accel_limit_mps2 must be >= 0");
  if (const auto outbox = j.find("outbox"); outbox != j.end()) {
    if (!outbox->is_array() || outbox->size() > kMaxOutbox) throw ProtocolError("command: \"outbox\" must be an array of at most 64 messages");
    for (std::size_t i = 0; i < outbox->size(); ++i)
      out.outbox.push_back(message_of((*outbox)[i], world, "command: outbox[" + std::to_string(i) + "]"));
  }
  if (const auto annotation = j.find("annotation"); annotation != j.end()) {
    if (!annotation->is_object()) throw ProtocolError("command: \"annotation\" must be an object");
    // Its "mode" and "reason", when they are strings, are what the trace's events and reports show.
    if (const auto mode = annotation->find("mode"); mode != annotation->end() && mode->is_string())
      out.mode = mode->get<std::string>();
    if (const auto reason = annotation->find("reason"); reason != annotation->end() && reason->is_string())
      out.reason = reason->get<std::string>();
    out.annotation = std::make_shared<const JsonAnnotation>(std::move(*annotation));
  }
  return out;
}

}  // namespace mg
