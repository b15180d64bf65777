#include "core/observed_trace.h"

#include <bit>

namespace mg {

int ObservedTrace::index_of(int id) const {
  for (std::size_t k = 0; k < vehicles.size(); ++k) {
    if (vehicles[k].id == id) return static_cast<int>(k);
  }
  return -1;
}

std::string to_string(ChannelEventKind k) {
  switch (k) {
    case ChannelEventKind::kSent: return "sent";
    case ChannelEventKind::kDelivered: return "delivered";
    case ChannelEventKind::kLost: return "lost";
  }
  return "unknown";
}

std::uint64_t trace_digest(const ObservedTrace& t) {
  std::uint64_t h = 1469598103934665603ULL;
  // FNV-1a over whole 64-bit words: one multiply per number (byte-wise FNV cost a campaign 6-8 %
  // of its time), still a function of every bit of every value.
  const auto mix = [&h](double v) { h = (h ^ std::bit_cast<std::uint64_t>(v)) * 1099511628211ULL; };
  for (const ObservedStep& s : t.steps) {
    mix(s.time_s);
    for (const ObservedState& v : s.vehicles) {
      for (const double x : {v.x_m, v.y_m, v.yaw_rad, v.vx_mps, v.vy_mps, v.accel_mps2}) mix(x);
    }
  }
  return h;
}

}  // namespace mg
