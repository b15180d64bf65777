#include "sim/v2v_channel.h"

#include <algorithm>
#include <cstdio>

namespace mg {
namespace {

std::uint64_t channel_seed(const Scenario& s) {
  std::uint64_t seed = 0x6D65726765677561ull;  // "mergegua"
  for (const MainVehicle& v : s.vehicles) {
    SplitMix64 mix(seed ^ (v.behaviour.seed + 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(v.id)));
    seed = mix.next();
  }
  return seed;
}

}  // namespace

std::string describe(const V2vMessage& m) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s %d->%d (%s, P_c %.2f m, D*_lon %.2f m, v_o* %.2f m/s)", to_string(m.type).c_str(),
                m.from_id, m.to_id, to_string(m.coop_case).c_str(), m.pc_m, m.d_lon_star_m, m.target_speed_mps);
  return buf;
}

V2vChannel::V2vChannel(const Scenario& s) : scenario_(s), rng_(channel_seed(s)) {}

const V2v* V2vChannel::link_of(int id) const {
  if (id == 0) return &scenario_.ego.v2v;
  const int index = scenario_.index_of(id);
  return index < 0 ? nullptr : &scenario_.vehicles[static_cast<std::size_t>(index)].v2v;
}

void V2vChannel::send(const V2vMessage& m, double time_s, std::vector<TraceEvent>& events) {
  events.push_back({time_s, EventKind::kMessageSent, m.from_id, describe(m), m});
  const V2v* from = link_of(m.from_id);
  const V2v* to = link_of(m.to_id);
  // One draw per message, used or not, so that the loss sequence does not depend on capability.
  const double draw = rng_.uniform01();
  const char* lost_because = nullptr;
  if (from == nullptr || !from->capable) lost_because = "sender has no V2V";
  else if (to == nullptr || !to->capable) lost_because = "receiver has no V2V";
  else if (draw < from->loss_prob) lost_because = "dropped by the channel";
  if (lost_because != nullptr) {
    events.push_back({time_s, EventKind::kMessageLost, m.from_id, describe(m) + ": " + lost_because, m});
    return;
  }
  in_flight_.push_back({time_s + from->latency_s, sequence_++, m});
}

std::vector<V2vMessage> V2vChannel::deliver_due(double time_s, std::vector<TraceEvent>& events) {
  constexpr double kTimeEpsS = 1e-9;
  std::vector<InFlight> due;
  auto split = std::stable_partition(in_flight_.begin(), in_flight_.end(),
                                     [&](const InFlight& f) { return f.deliver_time_s > time_s + kTimeEpsS; });
  due.assign(split, in_flight_.end());
  in_flight_.erase(split, in_flight_.end());
  std::sort(due.begin(), due.end(), [](const InFlight& a, const InFlight& b) {
    return a.deliver_time_s != b.deliver_time_s ? a.deliver_time_s < b.deliver_time_s : a.sequence < b.sequence;
  });
  std::vector<V2vMessage> out;
  for (const InFlight& f : due) {
    V2vMessage m = f.message;
    m.delivered_time_s = time_s;
    events.push_back({time_s, EventKind::kMessageDelivered, m.to_id, describe(m), m});
    out.push_back(m);
  }
  return out;
}

}  // namespace mg
