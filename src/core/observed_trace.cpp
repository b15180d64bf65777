#include "core/observed_trace.h"

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

}  // namespace mg
