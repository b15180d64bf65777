// Definition 2 of RCPP (cooperative merge over V2V; spec §5): the request's contents (2.1A),
// the ego's braking bound after a 2.2 request (2.2A), the responder's obligations once it
// accepted (2.1B, 2.2B) and the fallback when no acceptance arrived within rho_c (2.3).
#pragma once

#include <vector>

#include "rules/coop_exchange.h"
#include "rules/monitor.h"

namespace mg {

MonitorOutput monitor_def2_1a_request(const MonitorContext& ctx);
MonitorOutput monitor_def2_1b_responder(const MonitorContext& ctx);
MonitorOutput monitor_def2_2a_ego_brake(const MonitorContext& ctx);
MonitorOutput monitor_def2_2b_responder(const MonitorContext& ctx);
MonitorOutput monitor_def2_3_fallback(const MonitorContext& ctx);

// The ego's first merge midpoint after time_s (+inf when none): from then on the ego is in the
// lane and the RSS rules, not Definition 2, govern the pair.
double merge_midpoint_after(const MergePhases& phases, double time_s);
// When the ego's Def. 2.2A window [t_r, t_r + rho_c] ends early: at a refusal delivered to the
// ego (Def. 2.3 then sends it back to Definition 1), or at the first step at which the ego is the
// rear vehicle of an RSS-dangerous pair (the RSS proper response, braking at least b_min and up
// to b_max, then governs its speed; rss_longitudinal judges it).
double def2_2a_window_end_s(const MonitorContext& ctx, const CoopExchange& x);

}  // namespace mg
