// The V2V channel of Definition 2 (spec §5): each message is delayed by its sender's latency
// and dropped with its sender's loss probability, drawn from a seeded generator; messages to or
// from a vehicle without V2V are lost. Sending, loss and delivery are trace events.
#pragma once

#include <cstdint>
#include <vector>

#include "core/scenario.h"
#include "core/v2v_message.h"
#include "sim/splitmix64.h"
#include "sim/trace.h"

namespace mg {

class V2vChannel {
 public:
  // The loss generator is seeded from every vehicle's behaviour seed, so one scenario always
  // loses the same messages.
  explicit V2vChannel(const Scenario& s);

  // Emits kMessageSent, and kMessageLost when the message will not arrive.
  void send(const V2vMessage& m, double time_s, std::vector<TraceEvent>& events);

  // Messages whose delivery time is <= time_s, in order of delivery time then sending;
  // emits kMessageDelivered for each.
  std::vector<V2vMessage> deliver_due(double time_s, std::vector<TraceEvent>& events);

 private:
  struct InFlight {
    double deliver_time_s;
    std::uint64_t sequence;
    V2vMessage message;
  };
  const V2v* link_of(int id) const;  // nullptr for an unknown id

  const Scenario& scenario_;
  SplitMix64 rng_;
  std::uint64_t sequence_ = 0;
  std::vector<InFlight> in_flight_;
};

std::string describe(const V2vMessage& m);

}  // namespace mg
