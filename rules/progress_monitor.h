// Progress (RCPP Def. 1.3: halt only while space is insufficient): the ego must not stay
// halted, or keep braking to a halt, in the side lane for longer than progress_grace_s while a
// Definition 1 gap stays feasible by progress_gap_margin_m.
#pragma once

#include "rules/monitor.h"

namespace mg {

// Whether some gap of the rightmost main lane satisfies ineq. (1) and (2) with `margin_m` for a
// v_e* in [0, speed_limit], judged by the planner's own Definition 1 margins
// (planner/definition1.h: the paper's literal form and the bounded-rate form of DESIGN §4 must
// both hold), with the merge midpoint before the side lane end.
// The midpoint must also lie at least min_midpoint_ahead_m ahead of the ego (the shortest lane
// change the sideslip rule allows).
bool def1_gap_feasible(const Scenario& s, const TraceStep& step, double rho_m_s, double margin_m,
                       double min_midpoint_ahead_m);

MonitorOutput monitor_progress(const MonitorContext& ctx);

}  // namespace mg
