// The Definition 2 exchanges as the V2V channel saw them (spec §5): each request the ego sent,
// and its responder's answer, read from the observable trace's channel events only.
#pragma once

#include <vector>

#include "core/observed_trace.h"

namespace mg {

struct CoopExchange {
  const V2vMessage* request = nullptr;
  double request_time_s = 0.0;
  double accept_time_s = -1.0;            // when the responder sent its acceptance; < 0 when none
  double accept_delivered_time_s = -1.0;  // when the channel delivered it to the ego; < 0 when none
  double refuse_delivered_time_s = -1.0;  // the same for a refusal
};

// In the order the requests were sent. An answer belongs to the latest earlier request to its
// sender.
std::vector<CoopExchange> coop_exchanges(const ObservedTrace& t);

// Time an acceptance from `partner_id` was delivered to the ego at or before `time_s` (the
// latest such), or a negative value when none was.
double acceptance_time(const ObservedTrace& t, int partner_id, double time_s);

}  // namespace mg
