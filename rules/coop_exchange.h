// The Definition 2 exchanges as the V2V channel saw them (spec §5): each request the ego sent,
// and its responder's answer, read from the observable trace's channel events and, for what a
// request claims about the road (the order of the ego and its responder), the observed states at
// its send.
//
// Which request an answer answers, and from when its rho_c runs (docs/spec.md §5, "Exchanges"):
//   - an answer sent by vehicle k at t_s answers the latest request to k that k had received by
//     t_s (delivered to it at or before t_s; a request the channel lost was never received; one
//     with no delivery or loss recorded counts from its send);
//   - a request belongs to a series, and its window t_r is the send of that series' first
//     request: a new series begins with a request to k sent once an answer of k was delivered to
//     the ego since the series began, or more than rho_c after the series began (Def. 2.3 has
//     then sent the ego back to Definition 1), or when every request of the series so far was
//     lost (k never heard it). Re-sending within an open window moves nothing: T_dec is the
//     decision to ask, and ineq. (3)/(4) budget rho_c from it.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "core/observed_trace.h"

namespace mg {

struct CoopExchange {
  const V2vMessage* request = nullptr;
  double sent_time_s = 0.0;               // this request's send
  double request_time_s = 0.0;            // t_r: the send of the first request of its series
  double accept_time_s = -1.0;            // when the responder sent its acceptance; < 0 when none
  double accept_delivered_time_s = -1.0;  // when the channel delivered it to the ego; < 0 when none
  double refuse_delivered_time_s = -1.0;  // the same for a refusal
  // What the request says against what was observed at its send (NaN when the responder is not
  // a declared vehicle): ego ahead, X_e - X_o + (l_e + l_o)/2; ego behind, X_o - X_e + (l_e +
  // l_o)/2. >= 0: the case fits the order. While the two bodies overlap along the road they are
  // alongside, neither ahead, and either case fits (the inequality of the case decides whether
  // the request is sound, def2_request_sound); a case names the wrong order only when the ego's
  // body is wholly on the other side.
  double order_margin_m = std::numeric_limits<double>::quiet_NaN();

  // Whether P_c, D*_lon and v_o* are all numbers: a request without one asks for nothing the
  // rules can judge, and its acceptance grants nothing.
  bool complete() const;
  bool accepted_in_time(double rho_c_s) const;
};

// In the order the requests were sent.
std::vector<CoopExchange> coop_exchanges(const ObservedTrace& t, const RuleParams& p);

// Time an acceptance from `partner_id` was delivered to the ego at or before `time_s` (the
// latest such), or a negative value when none was.
double acceptance_time(const ObservedTrace& t, int partner_id, double time_s);

}  // namespace mg
