#include "rules/coop_exchange.h"

#include "rules/check.h"

namespace mg {
namespace {

CoopExchange* latest_request_to(std::vector<CoopExchange>& out, int responder_id) {
  for (auto it = out.rbegin(); it != out.rend(); ++it)
    if (it->request->to_id == responder_id) return &*it;
  return nullptr;
}

}  // namespace

std::vector<CoopExchange> coop_exchanges(const ObservedTrace& t) {
  std::vector<CoopExchange> out;
  for (const ChannelEvent& e : t.channel) {
    const V2vMessage& m = e.message;
    if (m.type == MessageType::kRequest && Party::from_vehicle_id(m.from_id).is_ego()) {
      if (e.kind == ChannelEventKind::kSent) out.push_back({&m, e.time_s});
      continue;
    }
    if (!Party::from_vehicle_id(m.to_id).is_ego() || (m.type != MessageType::kAccept && m.type != MessageType::kRefuse)) continue;
    CoopExchange* x = latest_request_to(out, m.from_id);
    if (x == nullptr) continue;
    if (m.type == MessageType::kAccept && e.kind == ChannelEventKind::kSent && x->accept_time_s < 0.0)
      x->accept_time_s = e.time_s;
    if (e.kind != ChannelEventKind::kDelivered) continue;
    double& delivered = m.type == MessageType::kAccept ? x->accept_delivered_time_s : x->refuse_delivered_time_s;
    if (delivered < 0.0) delivered = e.time_s;
  }
  return out;
}

double acceptance_time(const ObservedTrace& t, int partner_id, double time_s) {
  double when = -1.0;
  for (const ChannelEvent& e : t.channel) {
    if (e.time_s > time_s + 1e-9) break;
    if (e.kind == ChannelEventKind::kDelivered && e.message.type == MessageType::kAccept &&
        e.message.from_id == partner_id && Party::from_vehicle_id(e.message.to_id).is_ego())
      when = e.time_s;
  }
  return when;
}

}  // namespace mg
