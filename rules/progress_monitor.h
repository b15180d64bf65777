// Progress (RCPP Def. 1.3: halt only while space is insufficient): the ego must not stay
// halted, or keep braking to a halt, in the side lane for longer than progress_grace_s while a
// Definition 1 gap stays feasible by progress_gap_margin_m.
#pragma once

#include "rules/monitor.h"

namespace mg {

// Whether some gap of the rightmost main lane satisfies ineq. (1) and (2) with `margin_m`
// (ineq. (2) at both rho/2 and rho) for a v_e* the ego can reach from its current speed (the ego's position is predicted while
// it changes speed at a_accel^max / b_min, not as if it already drove v_e*), with the merge
// midpoint before the side lane end. Exact up to bisection: ineq. (1) is monotone increasing
// and ineq. (2) decreasing in v_e*.
bool def1_gap_feasible(const Scenario& s, const TraceStep& step, double rho_m_s, double margin_m);

MonitorOutput monitor_progress(const MonitorContext& ctx);

}  // namespace mg
