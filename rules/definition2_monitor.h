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

}  // namespace mg
