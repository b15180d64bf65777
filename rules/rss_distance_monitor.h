// RSS safe distances with proper response (RCPP eq. 1, 2; RSS Def. 1, 4, 5; spec §3, §8).
// A pair is dangerous when both its longitudinal and lateral distances are unsafe; an unsafe
// state is a violation only of the party that did not respond properly (see rules/catalog.json).
#pragma once

#include <cstddef>

#include "rules/monitor.h"
#include "rules/pair_geometry.h"

namespace mg {

MonitorOutput monitor_rss_longitudinal(const MonitorContext& ctx);
MonitorOutput monitor_rss_lateral(const MonitorContext& ctx);

}  // namespace mg
