#include "sim/trace.h"

#include <bit>
#include <cstdio>

namespace mg {
namespace {

class Fnv1a64 {
 public:
  // FNV-1a over whole 64-bit words (one multiply per field instead of eight), with an
  // xor-shift fold so that the high bits of a word also reach the low bits of the digest.
  void add_bytes(std::uint64_t v) {
    hash_ ^= v;
    hash_ *= 0x100000001B3ull;
    hash_ ^= hash_ >> 29;
  }
  void add(double v) { add_bytes(std::bit_cast<std::uint64_t>(v)); }
  void add(const VehicleState& s) {
    for (double v : {s.x_m, s.y_m, s.yaw_rad, s.vx_mps, s.vy_mps, s.yaw_rate_radps, s.accel_mps2, s.steer_rad}) add(v);
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xCBF29CE484222325ull;
};

nlohmann::json state_to_json(const VehicleState& s) {
  return {{"x_m", s.x_m},       {"y_m", s.y_m},   {"yaw_rad", s.yaw_rad}, {"vx_mps", s.vx_mps}, {"vy_mps", s.vy_mps},
          {"yaw_rate_radps", s.yaw_rate_radps}, {"accel_mps2", s.accel_mps2}, {"steer_rad", s.steer_rad}};
}

nlohmann::json message_to_json(const V2vMessage& m) {
  return {{"type", to_string(m.type)},   {"from_id", m.from_id},          {"to_id", m.to_id},
          {"sent_time_s", m.sent_time_s}, {"coop_case", to_string(m.coop_case)}, {"pc_m", m.pc_m},
          {"d_lon_star_m", m.d_lon_star_m}, {"target_speed_mps", m.target_speed_mps}};
}

}  // namespace

std::string to_string(EventKind k) {
  switch (k) {
    case EventKind::kDecision: return "decision";
    case EventKind::kMessageSent: return "message_sent";
    case EventKind::kMessageLost: return "message_lost";
    case EventKind::kMessageDelivered: return "message_delivered";
    case EventKind::kMergeStart: return "merge_start";
    case EventKind::kMergeMidpoint: return "merge_midpoint";
    case EventKind::kMergeComplete: return "merge_complete";
    case EventKind::kHalt: return "halt";
    case EventKind::kResume: return "resume";
    case EventKind::kNonCompliance: return "non_compliance";
  }
  return "unknown";
}

std::uint64_t compute_digest(const Trace& t) {
  Fnv1a64 h;
  for (const TraceStep& s : t.steps) {
    h.add(s.time_s);
    h.add(s.ego);
    for (const VehicleState& o : s.others) h.add(o);
    for (const char c : s.ego_mode) h.add_bytes(static_cast<std::uint64_t>(static_cast<unsigned char>(c)));
    h.add_bytes(s.ego_proper_response ? 1u : 0u);
  }
  return h.value();
}

std::string digest_hex(std::uint64_t digest) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(digest));
  return buf;
}

nlohmann::json trace_to_json(const Trace& t) {
  nlohmann::json steps = nlohmann::json::array();
  for (const TraceStep& s : t.steps) {
    nlohmann::json others = nlohmann::json::array();
    for (const VehicleState& o : s.others) others.push_back(state_to_json(o));
    steps.push_back({{"time_s", s.time_s},
                     {"ego", state_to_json(s.ego)},
                     {"others", std::move(others)},
                     {"ego_mode", s.ego_mode},
                     {"ego_proper_response", s.ego_proper_response}});
  }
  nlohmann::json decisions = nlohmann::json::array();
  for (const PlanRecord& d : t.decisions) decisions.push_back(plan_record_to_json(d));
  nlohmann::json events = nlohmann::json::array();
  for (const TraceEvent& e : t.events) {
    nlohmann::json j = {{"time_s", e.time_s}, {"kind", to_string(e.kind)}, {"vehicle_id", e.vehicle_id},
                        {"detail", e.detail}};
    if (e.message) j["message"] = message_to_json(*e.message);
    events.push_back(std::move(j));
  }
  return {{"planner", t.planner},
          {"digest", digest_hex(compute_digest(t))},
          {"steps", std::move(steps)},
          {"decisions", std::move(decisions)},
          {"events", std::move(events)}};
}

}  // namespace mg
