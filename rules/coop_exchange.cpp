#include "rules/coop_exchange.h"

#include <cmath>
#include <optional>

#include "core/demand.h"
#include "rules/check.h"
#include "rules/monitor.h"

namespace mg {

bool CoopExchange::complete() const {
  return std::isfinite(request->pc_m) && std::isfinite(request->d_lon_star_m) &&
         std::isfinite(request->target_speed_mps);
}

bool CoopExchange::accepted_in_time(double rho_c_s) const {
  return accept_delivered_time_s >= 0.0 && accept_delivered_time_s <= request_time_s + rho_c_s + kTieS;
}

namespace {

// The same message as it went through the channel: a send, then its delivery or its loss.
bool same_message(const V2vMessage& a, const V2vMessage& b) {
  return a.type == b.type && a.from_id == b.from_id && a.to_id == b.to_id && a.sent_time_s == b.sent_time_s;
}

struct RequestFate {
  std::optional<double> delivered_s;  // to the responder
  bool lost = false;
};

RequestFate fate_of(const ObservedTrace& t, const V2vMessage& request) {
  RequestFate f;
  for (const ChannelEvent& e : t.channel) {
    if (!same_message(e.message, request)) continue;
    if (e.kind == ChannelEventKind::kLost) f.lost = true;
    if (e.kind == ChannelEventKind::kDelivered && !f.delivered_s) f.delivered_s = e.time_s;
  }
  return f;
}

// The request an answer sent at answer_sent_s by `responder` answers: the latest one the
// responder had received by then (index into `out`), or none.
std::optional<std::size_t> answered_request(const std::vector<CoopExchange>& out, const std::vector<RequestFate>& fates,
                                            int responder, double answer_sent_s) {
  std::optional<std::size_t> found;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i].request->to_id != responder || out[i].sent_time_s > answer_sent_s + kTieS || fates[i].lost) continue;
    if (fates[i].delivered_s && *fates[i].delivered_s > answer_sent_s + kTieS) continue;  // not received yet
    found = i;
  }
  return found;
}

bool is_answer_to_ego(const V2vMessage& m) {
  return Party::from_vehicle_id(m.to_id).is_ego() && (m.type == MessageType::kAccept || m.type == MessageType::kRefuse);
}

// Whether `responder` delivered an answer to the ego in (from_s, to_s].
bool answer_delivered_within(const ObservedTrace& t, int responder, double from_s, double to_s) {
  for (const ChannelEvent& e : t.channel)
    if (e.kind == ChannelEventKind::kDelivered && is_answer_to_ego(e.message) && e.message.from_id == responder &&
        e.time_s > from_s && e.time_s <= to_s + kTieS)
      return true;
  return false;
}

// t_r of every request: the send of the first request of its series (coop_exchange.h).
void assign_series(const ObservedTrace& t, const RuleParams& p, const std::vector<RequestFate>& fates,
                   std::vector<CoopExchange>& out) {
  for (std::size_t i = 0; i < out.size(); ++i) {
    const int k = out[i].request->to_id;
    std::optional<std::size_t> previous;
    for (std::size_t j = i; j-- > 0;)
      if (out[j].request->to_id == k) {
        previous = j;
        break;
      }
    out[i].request_time_s = out[i].sent_time_s;
    if (!previous) continue;
    const double start_s = out[*previous].request_time_s;
    bool all_lost = true;
    for (std::size_t j = 0; j < i; ++j)
      if (out[j].request->to_id == k && out[j].request_time_s == start_s) all_lost = all_lost && fates[j].lost;
    const bool expired = out[i].sent_time_s > start_s + p.comm_threshold_s + kTieS;
    if (!all_lost && !expired && !answer_delivered_within(t, k, start_s, out[i].sent_time_s))
      out[i].request_time_s = start_s;
  }
}

void assign_order(const ObservedTrace& t, CoopExchange& x) {
  const int k = t.index_of(x.request->to_id);
  if (k < 1 || t.steps.empty()) return;
  const ObservedStep& st = t.steps[step_at(t, x.sent_time_s)];
  const double ahead_m = st.vehicles[0].x_m - st.vehicles[static_cast<std::size_t>(k)].x_m;
  const double alongside_m = 0.5 * (t.vehicles[0].size.length_m + t.vehicles[static_cast<std::size_t>(k)].size.length_m);
  x.order_margin_m = (x.request->coop_case == CoopCase::kEgoAhead ? ahead_m : -ahead_m) + alongside_m;
}

}  // namespace

std::vector<CoopExchange> coop_exchanges(const ObservedTrace& t, const RuleParams& p) {
  std::vector<CoopExchange> out;
  std::vector<RequestFate> fates;
  for (const ChannelEvent& e : t.channel) {
    if (e.kind != ChannelEventKind::kSent || e.message.type != MessageType::kRequest || !Party::from_vehicle_id(e.message.from_id).is_ego())
      continue;
    CoopExchange x;
    x.request = &e.message;
    x.sent_time_s = e.time_s;
    out.push_back(x);
    fates.push_back(fate_of(t, e.message));
  }
  assign_series(t, p, fates, out);
  for (CoopExchange& x : out) {
    // A series begins at or before each of its requests: rho_c never runs from a later send.
    MG_DEMAND(x.request_time_s <= x.sent_time_s);
    assign_order(t, x);
  }
  for (const ChannelEvent& e : t.channel) {
    const V2vMessage& m = e.message;
    if (!is_answer_to_ego(m) || e.kind == ChannelEventKind::kLost) continue;
    const std::optional<std::size_t> i = answered_request(out, fates, m.from_id, m.sent_time_s);
    if (!i) continue;
    CoopExchange& x = out[*i];
    if (m.type == MessageType::kAccept && e.kind == ChannelEventKind::kSent && x.accept_time_s < 0.0)
      x.accept_time_s = e.time_s;
    if (e.kind != ChannelEventKind::kDelivered) continue;
    double& delivered = m.type == MessageType::kAccept ? x.accept_delivered_time_s : x.refuse_delivered_time_s;
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
