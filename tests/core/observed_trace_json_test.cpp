// Trace format (docs/trace_format.md): the writer's output always loads and gives back
// the same trace bit for bit (NaN message fields and annotations included); every defect is
// rejected with one line naming the file and the JSON path; the schema lists exactly the keys
// the format has.
#include "core/observed_trace_json.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <set>
#include <sstream>

#include <unistd.h>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/input_error.h"
#include "core/json_reader.h"
#include "input_error_cases.h"

namespace mg {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Bit equality: NaN equals NaN and -0.0 differs from 0.0, unlike ==.
bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

bool same(const ObservedState& a, const ObservedState& b) {
  return same(a.x_m, b.x_m) && same(a.y_m, b.y_m) && same(a.yaw_rad, b.yaw_rad) && same(a.vx_mps, b.vx_mps) &&
         same(a.vy_mps, b.vy_mps) && same(a.accel_mps2, b.accel_mps2);
}

bool same(const V2vMessage& a, const V2vMessage& b) {
  return a.type == b.type && a.from_id == b.from_id && a.to_id == b.to_id && same(a.sent_time_s, b.sent_time_s) &&
         a.coop_case == b.coop_case && same(a.pc_m, b.pc_m) && same(a.d_lon_star_m, b.d_lon_star_m) &&
         same(a.target_speed_mps, b.target_speed_mps) && same(a.delivered_time_s, b.delivered_time_s);
}

// Road, declarations and parameters hold no NaN, so == is bit equality there up to the sign of
// zero, which the generator never draws for them.
bool same(const ObservedTrace& a, const ObservedTrace& b) {
  if (a.name != b.name || a.source != b.source || !(a.road == b.road) || !(a.vehicles == b.vehicles) ||
      !(a.params == b.params) || a.planner_annotations != b.planner_annotations || a.steps.size() != b.steps.size() ||
      a.channel.size() != b.channel.size())
    return false;
  for (std::size_t i = 0; i < a.steps.size(); ++i) {
    if (!same(a.steps[i].time_s, b.steps[i].time_s) || a.steps[i].vehicles.size() != b.steps[i].vehicles.size())
      return false;
    for (std::size_t k = 0; k < a.steps[i].vehicles.size(); ++k)
      if (!same(a.steps[i].vehicles[k], b.steps[i].vehicles[k])) return false;
  }
  for (std::size_t i = 0; i < a.channel.size(); ++i)
    if (!same(a.channel[i].time_s, b.channel[i].time_s) || a.channel[i].kind != b.channel[i].kind ||
        !same(a.channel[i].message, b.channel[i].message))
      return false;
  return true;
}

// A double in [lo, hi] with all 53 bits of mantissa random (what a simulator writes), or now and
// then an edge value of the interval.
double any_in(double lo, double hi) {
  switch (*rc::gen::inRange(0, 20)) {
    case 0: return lo;
    case 1: return hi;
    default: break;
  }
  const auto u = *rc::gen::arbitrary<std::uint64_t>();
  return std::min(hi, lo + (hi - lo) * (static_cast<double>(u >> 11) * 0x1p-53));
}

// Positive (for the exclusive lower bounds of the scenario's ranges).
double any_positive(double hi) { return std::max(1e-9, any_in(0.0, hi)); }

double maybe_nan(double lo, double hi) { return *rc::gen::inRange(0, 3) == 0 ? kNaN : any_in(lo, hi); }

// JSON strings are Unicode: names and sources are UTF-8 text (quotes, escapes, control and
// multi-byte characters included); the writer refuses other bytes (nlohmann type_error 316).
std::string any_text() {
  static const std::vector<std::string> pieces = {"a", "Z", "0", " ", "\"", "\\", "/", "\n", "\t", "\x01",
                                                  "\xc3\xa9", "\xe2\x86\x92", "\xf0\x9f\x9a\x97", "rcpp-coop"};
  std::string text;
  for (const auto& i : *rc::gen::container<std::vector<std::size_t>>(rc::gen::inRange<std::size_t>(0, pieces.size())))
    text += pieces[i];
  return text;
}

json any_annotations() {
  switch (*rc::gen::inRange(0, 4)) {
    case 0: return nullptr;
    case 1: return {{"decision", "merge"}, {"gap", *rc::gen::inRange(0, 9)}, {"reasons", {"def1.1", any_in(-1, 1)}}};
    case 2: return any_text();
    default: return json::array({any_in(-1e9, 1e9), true, nullptr});
  }
}

ObservedTrace any_trace() {
  ObservedTrace t;
  t.name = any_text();
  t.source = any_text();
  t.road.lane_width_m = any_in(2.0, 6.0);
  t.road.main_lanes = *rc::gen::inRange(1, 5);
  t.road.side_lane_start_x_m = any_in(-1e5, 1e5 - 10.0);
  t.road.side_lane_end_x_m = any_in(t.road.side_lane_start_x_m + 10.0, 1e5);
  t.road.speed_limit_mps = any_positive(100.0);
  const int n = *rc::gen::inRange(1, 7);
  int id = 0;
  for (int k = 0; k < n; ++k) {
    VehicleDeclaration d;
    d.id = id;
    id += *rc::gen::inRange(1, 1000);
    d.size = {any_positive(30.0), any_positive(5.0), any_positive(6.0)};
    d.limits.accel_max_mps2 = any_in(0.0, 15.0);
    d.limits.brake_max_mps2 = any_positive(15.0);
    d.limits.brake_min_mps2 = std::max(1e-9, any_in(0.0, d.limits.brake_max_mps2));
    d.limits.lat_accel_max_mps2 = any_in(0.0, 10.0);
    d.limits.lat_brake_min_mps2 = any_positive(10.0);
    d.v2v_capable = *rc::gen::arbitrary<bool>();
    t.vehicles.push_back(d);
  }
  t.params.rss.response_time_s = any_in(0.0, 5.0);
  t.params.rss.fluctuation_margin_m = any_in(0.0, 5.0);
  t.params.rules.merge_duration_s = any_in(0.5, 20.0);
  t.params.rules.accel_tolerance_mps2 = any_in(0.0, 0.2);
  t.params.rules.max_lat_speed_sign_changes_per_merge = *rc::gen::inRange(0, 5);
  double time = any_in(0.0, 100.0);
  const int steps = *rc::gen::inRange(1, 16);
  for (int i = 0; i < steps; ++i) {
    ObservedStep s;
    s.time_s = time;
    time = std::nextafter(time, 1e9) + any_in(0.0, 1.0);
    for (int k = 0; k < n; ++k)
      s.vehicles.push_back({any_in(-1e6, 1e6), any_in(-1e6, 1e6), any_in(-2 * std::numbers::pi, 2 * std::numbers::pi),
                            any_in(-150, 150), any_in(-150, 150), any_in(-100, 100)});
    t.steps.push_back(s);
  }
  double channel_time = 0.0;
  const int events = *rc::gen::inRange(0, 6);
  for (int i = 0; i < events; ++i) {
    ChannelEvent e;
    channel_time += *rc::gen::inRange(0, 2) == 0 ? 0.0 : any_in(0.0, 2.0);  // equal times are allowed
    e.time_s = channel_time;
    e.kind = *rc::gen::element(ChannelEventKind::kSent, ChannelEventKind::kDelivered, ChannelEventKind::kLost);
    e.message.type = *rc::gen::element(MessageType::kRequest, MessageType::kAccept, MessageType::kRefuse);
    e.message.from_id = t.vehicles[*rc::gen::inRange<std::size_t>(0, t.vehicles.size())].id;
    e.message.to_id = t.vehicles[*rc::gen::inRange<std::size_t>(0, t.vehicles.size())].id;
    e.message.sent_time_s = any_in(0.0, 1e6);
    e.message.coop_case = *rc::gen::element(CoopCase::kEgoAhead, CoopCase::kEgoBehind);
    // A request carries every number (an answer may omit them: null).
    const bool request = e.message.type == MessageType::kRequest;
    e.message.pc_m = request ? any_in(-1e6, 1e6) : maybe_nan(-1e6, 1e6);
    e.message.d_lon_star_m = request ? any_in(-1e6, 1e6) : maybe_nan(-1e6, 1e6);
    e.message.target_speed_mps = request ? any_in(-150, 150) : maybe_nan(-150, 150);
    e.message.delivered_time_s = maybe_nan(0.0, 1e6);
    t.channel.push_back(e);
  }
  t.planner_annotations = any_annotations();
  return t;
}

RC_GTEST_PROP(ObservedTraceJson, WriterOutputAlwaysLoadsAndGivesBackTheSameTraceBitForBit, ()) {
  const ObservedTrace t = any_trace();
  const ObservedTrace from_text = observed_trace_from_text(observed_trace_to_text(t), "trace.json");
  RC_ASSERT(same(from_text, t));
  const ObservedTrace from_json = observed_trace_from_json(observed_trace_to_json(t), "trace.json");
  RC_ASSERT(same(from_json, t));
}

// The control trace every in-memory defect below is made from (also tests/hostile/traces/valid.json).
fs::path hostile_dir() { return fs::path(MG_SOURCE_DIR) / "tests" / "hostile" / "traces"; }

json valid_trace() {
  std::ifstream in(hostile_dir() / "valid.json");
  return json::parse(in);
}

std::string trace_load_error(const json& j) {
  return test_support::input_error_of([&] { observed_trace_from_json(j, "trace.json"); });
}

TEST(ObservedTraceJson, ControlTraceLoadsWithItsDeclarationsAndNaNFields) {
  const ObservedTrace t = load_observed_trace((hostile_dir() / "valid.json").string());
  ASSERT_EQ(t.vehicle_count(), 3u);
  EXPECT_EQ(t.vehicles[2].id, 3);
  EXPECT_DOUBLE_EQ(t.vehicles[2].size.length_m, 4.8);  // scenario defaults for omitted keys
  EXPECT_TRUE(t.vehicles[1].v2v_capable);
  EXPECT_FALSE(t.vehicles[2].v2v_capable);
  ASSERT_EQ(t.steps.size(), 3u);
  EXPECT_DOUBLE_EQ(t.steps[2].vehicles[2].x_m, 60.84);
  ASSERT_EQ(t.channel.size(), 3u);
  EXPECT_TRUE(std::isnan(t.channel[0].message.delivered_time_s));
  EXPECT_DOUBLE_EQ(t.channel[1].message.delivered_time_s, 0.02);
  EXPECT_TRUE(std::isnan(t.channel[2].message.pc_m));
  EXPECT_EQ(t.channel[2].message.type, MessageType::kAccept);
  EXPECT_EQ(t.planner_annotations.at("decision"), "merge ahead of 1");
}

TEST(ObservedTraceJson, WriteThenLoadGivesTheSameTraceAndTheFileIsCompact) {
  ObservedTrace t = observed_trace_from_json(valid_trace(), "valid.json");
  t.planner_annotations = nullptr;  // absent from the file, null once loaded
  const auto path = fs::temp_directory_path() / ("mg_trace_roundtrip_" + std::to_string(::getpid()) + ".json");
  write_observed_trace(t, path.string());
  EXPECT_TRUE(same(load_observed_trace(path.string()), t));
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str().find("planner_annotations"), std::string::npos);
  EXPECT_NE(text.str().find("[20.4,-3.5,0.0,20.0,0.0,0.0]"), std::string::npos) << "states are compact rows";
  fs::remove(path);
}

TEST(ObservedTraceJson, EveryDefectIsRejectedWithItsJsonPath) {
  const std::vector<test_support::MutationCase> cases = {
      {"unknown top-level key", [](json& j) { j["colour"] = 1; }, "trace.json: /colour: unknown key"},
      {"unknown vehicle key", [](json& j) { j["vehicles"][1]["lane"] = 0; }, "/vehicles/1/lane: unknown key"},
      {"unknown message key", [](json& j) { j["channel"][0]["message"]["ttl"] = 1; }, "/channel/0/message/ttl: unknown key"},
      {"wrong format", [](json& j) { j["format"] = "x"; }, "/format: must be \"mergeguard-trace\", got \"x\""},
      {"missing format", [](json& j) { j.erase("format"); }, "/format: missing required key"},
      {"future version", [](json& j) { j["version"] = 7; }, "/version: unsupported trace format version 7 (this build reads version 1)"},
      {"version as string", [](json& j) { j["version"] = "1"; }, "/version: must be an integer"},
      {"no vehicles", [](json& j) { j["vehicles"] = json::array(); }, "/vehicles: at least one vehicle"},
      {"ego not first", [](json& j) { std::swap(j["vehicles"][0], j["vehicles"][1]); }, "/vehicles/0/id: vehicles[0] must be the ego (id 0), got id 1"},
      {"second ego", [](json& j) { j["vehicles"][2]["id"] = 0; }, "/vehicles/2/id: only vehicles[0] may be the ego"},
      {"duplicate id", [](json& j) { j["vehicles"][2]["id"] = 1; }, "/vehicles/2/id: duplicate vehicle id 1"},
      {"too many vehicles", [](json& j) { for (int k = 0; k < 70; ++k) j["vehicles"].push_back({{"id", 10 + k}, {"size", json::object()}, {"limits", json::object()}}); }, "/vehicles: at most 64 vehicles, got 73"},
      {"negative length", [](json& j) { j["vehicles"][1]["size"]["length_m"] = -4; }, "/vehicles/1/size/length_m: must be > 0"},
      {"absurd width", [](json& j) { j["vehicles"][1]["size"]["width_m"] = 50; }, "/vehicles/1/size/width_m: must be in"},
      {"size missing", [](json& j) { j["vehicles"][1].erase("size"); }, "/vehicles/1/size: missing required key"},
      {"brake_min above brake_max", [](json& j) { j["vehicles"][0]["limits"]["brake_min_mps2"] = 9; }, "/vehicles/0/limits/brake_min_mps2: must be <= brake_max_mps2"},
      {"unknown limits key", [](json& j) { j["vehicles"][0]["limits"]["jerk"] = 9; }, "/vehicles/0/limits/jerk: unknown key"},
      {"road inverted", [](json& j) { j["road"]["side_lane_end_x_m"] = -50; }, "/road/side_lane_end_x_m: the side lane must end"},
      {"rule param out of range", [](json& j) { j["params"] = {{"rules", {{"merge_duration_s", 0}}}}; }, "/params/rules/merge_duration_s: must be in [0.5, 20]"},
      {"planner params in a trace", [](json& j) { j["params"] = {{"planner", json::object()}}; }, "/params/planner: unknown key"},
      {"state columns reordered", [](json& j) { std::swap(j["state_columns"][0], j["state_columns"][1]); }, "/state_columns: must be [\"x_m\""},
      {"no steps", [](json& j) { j["steps"] = json::array(); }, "/steps: at least one step"},
      {"equal step times", [](json& j) { j["steps"][2]["time_s"] = 0.02; }, "/steps/2/time_s: times must increase strictly (0.02 after 0.02)"},
      {"negative step time", [](json& j) { j["steps"][0]["time_s"] = -1; }, "/steps/0/time_s: must be in [0, 1000000]"},
      {"vehicle missing from a step", [](json& j) { j["steps"][1]["states"].erase(2); }, "/steps/1/states: 2 states for 3 declared vehicles (vehicle 3 missing)"},
      {"extra state in a step", [](json& j) { j["steps"][1]["states"].push_back(j["steps"][1]["states"][0]); }, "/steps/1/states: 4 states for 3 declared vehicles (1 extra)"},
      {"short state row", [](json& j) { j["steps"][1]["states"][1].erase(5); }, "/steps/1/states/1: must be an array of 6 numbers [x_m, y_m, yaw_rad, vx_mps, vy_mps, accel_mps2], got 5 elements"},
      {"state row as object", [](json& j) { j["steps"][1]["states"][1] = json::object(); }, "/steps/1/states/1: must be an array of 6 numbers [x_m, y_m, yaw_rad, vx_mps, vy_mps, accel_mps2], got an object"},
      {"null in a state", [](json& j) { j["steps"][1]["states"][1][2] = nullptr; }, "/steps/1/states/1/2: yaw_rad must be a number, got null"},
      {"NaN in a state", [](json& j) { j["steps"][1]["states"][1][0] = kNaN; }, "/steps/1/states/1/0: x_m must be finite"},
      {"absurd position", [](json& j) { j["steps"][0]["states"][0][1] = 2e6; }, "/steps/0/states/0/1: y_m must be in [-1000000.0, 1000000.0], got 2000000.0"},
      {"absurd speed", [](json& j) { j["steps"][0]["states"][2][3] = -3e8; }, "/steps/0/states/2/3: vx_mps must be in [-150.0, 150.0]"},
      {"absurd acceleration", [](json& j) { j["steps"][0]["states"][2][5] = 101; }, "/steps/0/states/2/5: accel_mps2 must be in [-100.0, 100.0]"},
      {"absurd yaw", [](json& j) { j["steps"][0]["states"][2][2] = 7; }, "/steps/0/states/2/2: yaw_rad must be in"},
      {"channel time decreasing", [](json& j) { j["channel"][2]["time_s"] = 0.01; }, "/channel/2/time_s: times must not decrease (0.01 after 0.02)"},
      {"unknown event kind", [](json& j) { j["channel"][0]["kind"] = "dropped"; }, "/channel/0/kind: unknown channel event kind 'dropped' (expected sent, delivered or lost)"},
      {"undeclared sender", [](json& j) { j["channel"][2]["message"]["from_id"] = 7; }, "/channel/2/message/from_id: vehicle id 7 is not declared in /vehicles"},
      {"undeclared receiver", [](json& j) { j["channel"][0]["message"]["to_id"] = 2; }, "/channel/0/message/to_id: vehicle id 2 is not declared"},
      {"unknown message type", [](json& j) { j["channel"][0]["message"]["type"] = "nudge"; }, "/channel/0/message/type: unknown message type 'nudge'"},
      {"null sent time", [](json& j) { j["channel"][0]["message"]["sent_time_s"] = nullptr; }, "/channel/0/message/sent_time_s: must be a number"},
      {"missing pc_m", [](json& j) { j["channel"][0]["message"].erase("pc_m"); }, "/channel/0/message/pc_m: missing required key"},
      {"pc_m as string", [](json& j) { j["channel"][0]["message"]["pc_m"] = "80"; }, "/channel/0/message/pc_m: must be a number, got a string"},
      {"request without v_o*", [](json& j) { j["channel"][1]["message"]["target_speed_mps"] = nullptr; }, "/channel/1/message/target_speed_mps: a request must carry a number, got null"},
      {"negative delivery time", [](json& j) { j["channel"][1]["message"]["delivered_time_s"] = -1; }, "/channel/1/message/delivered_time_s: must be >= 0"},
      {"not an object", [](json& j) { j = json::array(); }, "trace.json: /: must be a JSON object"},
  };
  test_support::expect_input_errors(valid_trace(), cases, [](const json& j) { observed_trace_from_json(j, "trace.json"); });
  EXPECT_EQ(trace_load_error(valid_trace()), "");
}

TEST(ObservedTraceJson, TotalSizeIsBounded) {
  // Both bounds are checked before any step is read, so null steps are enough to reach them.
  json j = valid_trace();
  j["steps"].get_ref<json::array_t&>().assign(kMaxTraceSteps + 1, nullptr);
  EXPECT_NE(trace_load_error(j).find("/steps: at most 1000000 steps, got 1000001"), std::string::npos)
      << trace_load_error(j);
  for (int k = 3; k < 64; ++k) j["vehicles"].push_back({{"id", 10 + k}, {"size", json::object()}, {"limits", json::object()}});
  j["steps"].get_ref<json::array_t&>().assign(kMaxTraceStates / 64 + 1, nullptr);
  EXPECT_NE(trace_load_error(j).find("/steps: at most 20000000 states (steps x vehicles), got 312501 x 64"),
            std::string::npos)
      << trace_load_error(j);
}

TEST(ObservedTraceJson, RepeatedKeysInTheTextAreRejected) {
  try {
    observed_trace_from_text(R"({"format": "mergeguard-trace", "steps": [{"time_s": 0, "states": [], "time_s": 1}]})",
                             "trace.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("trace.json: /steps/0/time_s: duplicate key 'time_s'"), std::string::npos)
        << e.what();
  }
  // Other loaders keep their behaviour (the last value wins).
  EXPECT_EQ(parse_json_text(R"({"a": 1, "a": 2})", "a.json").at("a"), 2);
}

// tests/hostile/traces/: one file per defect (tests/hostile/README.md); each must be rejected with
// a message naming the file and the JSON path of the defect.
TEST(ObservedTraceJson, HostileTraceFilesNameTheFileAndTheJsonPath) {
  const std::vector<std::pair<std::string, std::string>> files = {
      {"unknown_key.json", ": /steps/1/turbo: unknown key"},
      {"nan_literal.json", ": /: malformed JSON"},
      {"non_increasing_time.json", ": /steps/2/time_s: times must increase strictly (0.02 after 0.02)"},
      {"vehicle_missing_from_step.json", ": /steps/1/states: 2 states for 3 declared vehicles (vehicle 3 missing)"},
      {"negative_length.json", ": /vehicles/1/size/length_m: must be > 0, got -4.8"},
      {"absurd_size.json", ": /vehicles/2/size/length_m: must be in"},
      {"absurd_speed.json", ": /steps/1/states/0/3: vx_mps must be in [-150.0, 150.0], got 310000000.0"},
      {"future_version.json", ": /version: unsupported trace format version 2 (this build reads version 1)"},
      {"wrong_format.json", ": /format: must be \"mergeguard-trace\", got \"mergeguard-scenario\""},
      {"undeclared_message_id.json", ": /channel/2/message/from_id: vehicle id 7 is not declared in /vehicles"},
      {"truncated.json", ": /: malformed JSON"},
      {"duplicate_key.json", ": /steps/1/time_s: duplicate key 'time_s'"},
      {"empty.json", ": /: empty input"},
      {"infinity_literal.json", ": /: malformed JSON"},
      {"number_overflow.json", ": /: number out of range of a double"},
      {"decreasing_time.json", ": /steps/1/time_s: times must increase strictly (0.01 after 0.02)"},
      {"extra_state_row.json", ": /steps/2/states: 4 states for 3 declared vehicles (1 extra)"},
      {"zero_length.json", ": /vehicles/0/size/length_m: must be > 0, got 0"},
      {"zero_width.json", ": /vehicles/1/size/width_m: must be > 0, got 0"},
      {"huge_width.json", ": /vehicles/0/size/width_m: must be in (0, 5], got 50"},
      {"absurd_limits.json", ": /vehicles/0/limits/brake_max_mps2: must be in (0, 15], got 1000000000"},
      {"negative_limit.json", ": /vehicles/2/limits/accel_max_mps2: must be in [0, 15], got -2"},
      {"inconsistent_limits.json", ": /vehicles/0/limits/brake_min_mps2: must be <= brake_max_mps2"},
      {"request_without_pc.json", ": /channel/0/message/pc_m: a request must carry a number, got null"},
  };
  std::set<std::string> listed;
  for (const auto& [file, expected] : files) {
    listed.insert(file);
    const std::string path = (hostile_dir() / file).string();
    try {
      load_observed_trace(path);
      ADD_FAILURE() << file << " loaded";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(path + expected, 0), 0u) << file << ": got '" << message << "'";
      EXPECT_EQ(message.find('\n'), std::string::npos) << file;
    }
  }
  // Every file of the directory is in the table (valid.json is the control they are made from).
  for (const auto& entry : fs::directory_iterator(hostile_dir())) {
    if (entry.path().filename() != "valid.json") {
      EXPECT_TRUE(listed.count(entry.path().filename().string())) << entry.path() << " is not checked";
    }
  }
}

// docs/trace.schema.json must list exactly the keys of the format. The writer writes every key
// (delivered_time_s and planner_annotations when they have a value) and the loader rejects any
// other (the defects above), so comparing the schema with the writer's keys ties all three.
std::set<std::string> keys_of(const json& object) {
  std::set<std::string> keys;
  for (const auto& item : object.items()) keys.insert(item.key());
  return keys;
}

TEST(ObservedTraceJson, SchemaListsExactlyTheKeysOfTheFormat) {
  std::ifstream in(fs::path(MG_SOURCE_DIR) / "docs" / "trace.schema.json");
  ASSERT_TRUE(in) << "docs/trace.schema.json";
  const json schema = json::parse(in);
  const json written = observed_trace_to_json(observed_trace_from_json(valid_trace(), "valid.json"));
  const json& p = schema.at("properties");
  const json& defs = schema.at("$defs");
  EXPECT_EQ(keys_of(p), keys_of(written));
  EXPECT_EQ(keys_of(p.at("road").at("properties")), keys_of(written.at("road")));
  EXPECT_EQ(keys_of(defs.at("vehicle").at("properties")), keys_of(written.at("vehicles")[0]));
  EXPECT_EQ(keys_of(defs.at("size").at("properties")), keys_of(written.at("vehicles")[0].at("size")));
  EXPECT_EQ(keys_of(defs.at("limits").at("properties")), keys_of(written.at("vehicles")[0].at("limits")));
  EXPECT_EQ(keys_of(p.at("params").at("properties")), keys_of(written.at("params")));
  EXPECT_EQ(keys_of(p.at("params").at("properties").at("rss").at("properties")), keys_of(written.at("params").at("rss")));
  EXPECT_EQ(keys_of(p.at("params").at("properties").at("rules").at("properties")),
            keys_of(written.at("params").at("rules")));
  EXPECT_EQ(keys_of(defs.at("step").at("properties")), keys_of(written.at("steps")[0]));
  EXPECT_EQ(keys_of(defs.at("channel_event").at("properties")), keys_of(written.at("channel")[1]));
  EXPECT_EQ(keys_of(defs.at("message").at("properties")), keys_of(written.at("channel")[1].at("message")));
  EXPECT_EQ(p.at("state_columns").at("const"), written.at("state_columns"));
  EXPECT_EQ(p.at("version").at("const"), kTraceFormatVersion);
  EXPECT_EQ(p.at("format").at("const"), kTraceFormatName);
}

}  // namespace
}  // namespace mg
