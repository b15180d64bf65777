#include "core/observed_trace_json.h"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <string_view>
#include <utility>

#include "core/atomic_file.h"
#include "core/json_reader.h"

namespace mg {
namespace {

using nlohmann::json;

constexpr double kMaxTimeS = 1e6;       // times are relative to the start of the recording
constexpr long long kMaxVehicleId = 1000000;  // as in scenarios

// The columns of a state row, in order, with the bound on their magnitude: values beyond these
// are no road vehicle's, and a recording that holds them is broken (docs/trace_format.md).
struct Column {
  const char* name;
  double max_abs;
};
constexpr std::array<Column, 6> kColumns = {{
    {"x_m", 1e6},
    {"y_m", 1e6},
    {"yaw_rad", 2.0 * std::numbers::pi},
    {"vx_mps", kMaxTraceSpeedMps},
    {"vy_mps", kMaxTraceSpeedMps},
    {"accel_mps2", 100.0},
}};

constexpr ChannelEventKind kKinds[] = {ChannelEventKind::kSent, ChannelEventKind::kDelivered, ChannelEventKind::kLost};
constexpr MessageType kMessageTypes[] = {MessageType::kRequest, MessageType::kAccept, MessageType::kRefuse};
constexpr CoopCase kCoopCases[] = {CoopCase::kEgoAhead, CoopCase::kEgoBehind};

// Shortest text that reads back as the same double ("12.0", "0.1"), for messages.
std::string num(double x) { return json(x).dump(); }

json state_columns_json() {
  json c = json::array();
  for (const auto& col : kColumns) c.push_back(col.name);
  return c;
}

// NaN stands for "no value" in a message (a refusal has no P_c); JSON has no NaN, so null.
json nullable(double x) { return std::isnan(x) ? json(nullptr) : json(x); }

double nullable_number(const ObjectReader& r, std::string_view key, double max_abs, bool required) {
  if (!r.has(key)) return required ? r.number(key, -max_abs, max_abs) : std::numeric_limits<double>::quiet_NaN();
  if (r.value().at(std::string(key)).is_null()) return std::numeric_limits<double>::quiet_NaN();
  return r.number(key, -max_abs, max_abs);
}

// Reads a string naming one of `values` (spelled by to_string).
template <typename Enum, std::size_t N>
Enum read_enum(const ObjectReader& r, std::string_view key, const Enum (&values)[N], const char* what) {
  const std::string name = r.string(key);
  std::string names;
  for (std::size_t k = 0; k < N; ++k) {
    if (name == to_string(values[k])) return values[k];
    names += (k == 0 ? "" : (k + 1 == N ? " or " : ", ")) + to_string(values[k]);
  }
  r.fail(key, "unknown " + std::string(what) + " '" + name + "' (expected " + names + ")");
}

VehicleDeclaration read_declaration(const ObjectReader& r, std::size_t index) {
  r.only_keys({"id", "size", "limits", "v2v_capable"});
  VehicleDeclaration d;
  d.id = static_cast<int>(r.integer("id", 0, kMaxVehicleId));
  if (index == 0 && d.id != 0) r.fail("id", "vehicles[0] must be the ego (id 0), got id " + std::to_string(d.id));
  if (index != 0 && d.id == 0) r.fail("id", "only vehicles[0] may be the ego (id 0)");
  d.size = vehicle_size_from_json(r.object("size").value(), r.source(), r.path_of("size"));
  d.limits = limits_from_json(r.object("limits").value(), r.source(), r.path_of("limits"));
  d.v2v_capable = r.boolean_or("v2v_capable", d.v2v_capable);
  return d;
}

void read_vehicles(const ObjectReader& r, ObservedTrace& t) {
  const json& list = r.array("vehicles");
  if (list.empty()) r.fail("vehicles", "at least one vehicle (the ego, id 0) must be declared");
  if (list.size() > kMaxVehicles)
    r.fail("vehicles", "at most " + std::to_string(kMaxVehicles) + " vehicles, got " + std::to_string(list.size()));
  std::set<int> ids;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const ObjectReader v(list[i], r.source(), "/vehicles/" + std::to_string(i));
    t.vehicles.push_back(read_declaration(v, i));
    if (!ids.insert(t.vehicles.back().id).second)
      v.fail("id", "duplicate vehicle id " + std::to_string(t.vehicles.back().id));
  }
}

JudgeParams read_params(const ObjectReader& r) {
  r.only_keys({"rss", "rules"});
  JudgeParams p;
  if (r.has("rss")) p.rss = rss_params_from_json(r.value().at("rss"), r.source(), r.path_of("rss"));
  if (r.has("rules")) p.rules = rule_params_from_json(r.value().at("rules"), r.source(), r.path_of("rules"));
  return p;
}

// The per-step rows are most of a trace (10 vehicles for 60 s at 50 Hz: 180,000 numbers), so
// they are read straight from the JSON array rather than through ObjectReader.
ObservedState read_state(const json& row, const std::string& source, const std::string& path) {
  if (!row.is_array() || row.size() != kColumns.size())
    throw InputError(source, path,
                     "must be an array of 6 numbers [x_m, y_m, yaw_rad, vx_mps, vy_mps, accel_mps2], got " +
                         (row.is_array()    ? std::to_string(row.size()) + " elements"
                          : row.is_object() ? std::string("an object")
                                            : std::string("a ") + row.type_name()));
  std::array<double, kColumns.size()> v{};
  for (std::size_t c = 0; c < kColumns.size(); ++c) {
    const json& x = row[c];
    if (!x.is_number())
      throw InputError(source, path + "/" + std::to_string(c),
                       std::string(kColumns[c].name) + " must be a number, got " + (x.is_null() ? "null" : x.type_name()));
    v[c] = x.get<double>();
    if (!std::isfinite(v[c]))
      throw InputError(source, path + "/" + std::to_string(c), std::string(kColumns[c].name) + " must be finite");
    if (std::abs(v[c]) > kColumns[c].max_abs)
      throw InputError(source, path + "/" + std::to_string(c),
                       std::string(kColumns[c].name) + " must be in [-" + num(kColumns[c].max_abs) + ", " +
                           num(kColumns[c].max_abs) + "], got " + num(v[c]));
  }
  return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

void read_steps(const ObjectReader& r, ObservedTrace& t) {
  const json& list = r.array("steps");
  if (list.empty()) r.fail("steps", "at least one step");
  if (list.size() > kMaxTraceSteps)
    r.fail("steps", "at most " + std::to_string(kMaxTraceSteps) + " steps, got " + std::to_string(list.size()));
  if (list.size() * t.vehicles.size() > kMaxTraceStates)
    r.fail("steps", "at most " + std::to_string(kMaxTraceStates) + " states (steps x vehicles), got " +
                        std::to_string(list.size()) + " x " + std::to_string(t.vehicles.size()));
  const std::size_t n = t.vehicles.size();
  t.steps.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    const ObjectReader s(list[i], r.source(), "/steps/" + std::to_string(i));
    s.only_keys({"time_s", "states"});
    ObservedStep step;
    step.time_s = s.number("time_s", 0.0, kMaxTimeS);
    if (!t.steps.empty() && !(step.time_s > t.steps.back().time_s))
      s.fail("time_s", "times must increase strictly (" + num(step.time_s) + " after " + num(t.steps.back().time_s) + ")");
    const json& states = s.array("states");
    if (states.size() != n) {
      const std::string count = std::to_string(states.size()) + " states for " + std::to_string(n) + " declared vehicles";
      if (states.size() < n)
        s.fail("states", count + " (vehicle " + std::to_string(t.vehicles[states.size()].id) + " missing)");
      s.fail("states", count + " (" + std::to_string(states.size() - n) + " extra)");
    }
    step.vehicles.reserve(n);
    const std::string states_path = s.path_of("states") + "/";
    for (std::size_t k = 0; k < n; ++k) step.vehicles.push_back(read_state(states[k], r.source(), states_path + std::to_string(k)));
    t.steps.push_back(std::move(step));
  }
}

V2vMessage read_message(const ObjectReader& r, const ObservedTrace& t) {
  r.only_keys({"type", "from_id", "to_id", "sent_time_s", "coop_case", "pc_m", "d_lon_star_m", "target_speed_mps",
               "delivered_time_s"});
  V2vMessage m;
  m.type = read_enum(r, "type", kMessageTypes, "message type");
  const auto declared_id = [&](std::string_view key) {
    const int id = static_cast<int>(r.integer(key, 0, kMaxVehicleId));
    if (t.index_of(id) < 0) r.fail(key, "vehicle id " + std::to_string(id) + " is not declared in /vehicles");
    return id;
  };
  m.from_id = declared_id("from_id");
  m.to_id = declared_id("to_id");
  m.sent_time_s = r.number("sent_time_s", 0.0, kMaxTimeS);
  m.coop_case = read_enum(r, "coop_case", kCoopCases, "coop_case");
  m.pc_m = nullable_number(r, "pc_m", 1e6, true);
  m.d_lon_star_m = nullable_number(r, "d_lon_star_m", 1e6, true);
  m.target_speed_mps = nullable_number(r, "target_speed_mps", kMaxTraceSpeedMps, true);
  // A request is what Definition 2 judges and what an acceptance grants on: every number of it
  // must be there (null stands for "no value" only in an answer, which repeats or omits them).
  if (m.type == MessageType::kRequest)
    for (const auto& [key, v] : {std::pair{"pc_m", m.pc_m}, std::pair{"d_lon_star_m", m.d_lon_star_m},
                                 std::pair{"target_speed_mps", m.target_speed_mps}})
      if (std::isnan(v)) r.fail(key, "a request must carry a number, got null");
  m.delivered_time_s = nullable_number(r, "delivered_time_s", kMaxTimeS, false);
  if (m.delivered_time_s < 0.0) r.fail("delivered_time_s", "must be >= 0, got " + num(m.delivered_time_s));
  return m;
}

void read_channel(const ObjectReader& r, ObservedTrace& t) {
  const json& list = r.array("channel");
  if (list.size() > kMaxChannelEvents)
    r.fail("channel", "at most " + std::to_string(kMaxChannelEvents) + " events, got " + std::to_string(list.size()));
  for (std::size_t i = 0; i < list.size(); ++i) {
    const ObjectReader e(list[i], r.source(), "/channel/" + std::to_string(i));
    e.only_keys({"time_s", "kind", "message"});
    ChannelEvent ev;
    ev.time_s = e.number("time_s", 0.0, kMaxTimeS);
    if (!t.channel.empty() && ev.time_s < t.channel.back().time_s)
      e.fail("time_s", "times must not decrease (" + num(ev.time_s) + " after " + num(t.channel.back().time_s) + ")");
    ev.kind = read_enum(e, "kind", kKinds, "channel event kind");
    ev.message = read_message(e.object("message"), t);
    t.channel.push_back(ev);
  }
}

json message_to_json(const V2vMessage& m) {
  json j = {{"type", to_string(m.type)},
            {"from_id", m.from_id},
            {"to_id", m.to_id},
            {"sent_time_s", m.sent_time_s},
            {"coop_case", to_string(m.coop_case)},
            {"pc_m", nullable(m.pc_m)},
            {"d_lon_star_m", nullable(m.d_lon_star_m)},
            {"target_speed_mps", nullable(m.target_speed_mps)}};
  if (!std::isnan(m.delivered_time_s)) j["delivered_time_s"] = m.delivered_time_s;
  return j;
}

}  // namespace

json observed_trace_to_json(const ObservedTrace& t) {
  json vehicles = json::array();
  for (const auto& v : t.vehicles)
    vehicles.push_back({{"id", v.id},
                        {"size", vehicle_size_to_json(v.size)},
                        {"limits", limits_to_json(v.limits)},
                        {"v2v_capable", v.v2v_capable}});
  json steps = json::array();
  for (const auto& s : t.steps) {
    json states = json::array();
    for (const auto& v : s.vehicles) states.push_back({v.x_m, v.y_m, v.yaw_rad, v.vx_mps, v.vy_mps, v.accel_mps2});
    steps.push_back({{"time_s", s.time_s}, {"states", std::move(states)}});
  }
  json channel = json::array();
  for (const auto& e : t.channel)
    channel.push_back({{"time_s", e.time_s}, {"kind", to_string(e.kind)}, {"message", message_to_json(e.message)}});
  json j = {{"format", kTraceFormatName},
            {"version", kTraceFormatVersion},
            {"name", t.name},
            {"source", t.source},
            {"road", road_to_json(t.road)},
            {"vehicles", std::move(vehicles)},
            {"params", {{"rss", rss_params_to_json(t.params.rss)}, {"rules", rule_params_to_json(t.params.rules)}}},
            {"state_columns", state_columns_json()},
            {"steps", std::move(steps)},
            {"channel", std::move(channel)}};
  if (!t.planner_annotations.is_null()) j["planner_annotations"] = t.planner_annotations;
  return j;
}

ObservedTrace observed_trace_from_json(const json& j, const std::string& source) {
  const ObjectReader r(j, source, "");
  // Format and version first: a newer file should be told so, not that its new keys are unknown.
  if (const std::string format = r.string("format"); format != kTraceFormatName)
    r.fail("format", "must be \"" + std::string(kTraceFormatName) + "\", got \"" + format + "\"");
  if (const long long version = r.integer("version", 0, 1000000); version != kTraceFormatVersion)
    r.fail("version", "unsupported trace format version " + std::to_string(version) + " (this build reads version " +
                          std::to_string(kTraceFormatVersion) + ")");
  r.only_keys({"format", "version", "name", "source", "road", "vehicles", "params", "state_columns", "steps", "channel",
               "planner_annotations"});
  ObservedTrace t;
  t.name = r.string_or("name", t.name);
  t.source = r.string_or("source", t.source);
  if (r.has("road")) t.road = road_from_json(j.at("road"), source, "/road");
  read_vehicles(r, t);
  if (r.has("params")) t.params = read_params(r.object("params"));
  if (r.has("state_columns") && j.at("state_columns") != state_columns_json())
    r.fail("state_columns", "must be " + state_columns_json().dump() + " (the column order of version 1)");
  read_steps(r, t);
  if (r.has("channel")) read_channel(r, t);
  if (r.has("planner_annotations")) t.planner_annotations = j.at("planner_annotations");
  return t;
}

std::string observed_trace_to_text(const ObservedTrace& t) {
  const json j = observed_trace_to_json(t);
  // Fixed key order, and one line per element of the long arrays: small diffs, still compact.
  static constexpr const char* kOrder[] = {"format", "version", "name",          "source", "road",
                                           "vehicles", "params", "state_columns", "steps",  "channel",
                                           "planner_annotations"};
  std::string out = "{";
  bool first = true;
  for (const char* key : kOrder) {
    const auto it = j.find(key);
    if (it == j.end()) continue;
    out += first ? "\n  " : ",\n  ";
    first = false;
    out += json(key).dump() + ": ";
    const std::string_view k = key;
    if (it->is_array() && !it->empty() && (k == "vehicles" || k == "steps" || k == "channel")) {
      out += "[";
      for (std::size_t i = 0; i < it->size(); ++i) out += (i == 0 ? "\n    " : ",\n    ") + (*it)[i].dump();
      out += "\n  ]";
    } else {
      out += it->dump();
    }
  }
  out += "\n}\n";
  return out;
}

ObservedTrace observed_trace_from_text(const std::string& text, const std::string& source) {
  return observed_trace_from_json(parse_json_text(text, source, DuplicateKeys::kReject), source);
}

ObservedTrace load_observed_trace(const std::string& path) {
  return observed_trace_from_json(parse_json_file(path, DuplicateKeys::kReject), path);
}

void write_observed_trace(const ObservedTrace& t, const std::string& path) {
  write_file_atomic(path, observed_trace_to_text(t));
}

}  // namespace mg
