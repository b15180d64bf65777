// def2_request_truthful (rules/definition2_inequalities.h): what a request says about the road,
// against what was observed. Definition 2's clause and inequality follow from the request's case
// (2.1 ego ahead, ineq. (3); 2.2 ego behind, ineq. (4)), and the responder's duty from its P_c:
// a request that names the wrong order, or a P_c the ego then does not keep to, moves onto the
// responder a risk it never accepted.
#include <cmath>
#include <sstream>

#include "rules/definition2_inequalities.h"

namespace mg {
namespace {

// The request's case against the order observed at its send, for every request.
void judge_order(const MonitorContext& ctx, const CoopExchange& x, MarginAccumulator& acc) {
  if (!std::isfinite(x.order_margin_m)) return;  // a responder that is no declared vehicle
  const std::size_t i = step_at(ctx.trace, x.sent_time_s);
  const bool ahead = x.request->coop_case == CoopCase::kEgoAhead;
  if (acc.record(i, x.sent_time_s, x.order_margin_m, Party::ego(), 0.0, x.order_margin_m)) {
    const std::size_t k = static_cast<std::size_t>(ctx.trace.index_of(x.request->to_id));
    const double lead_m = ego_of(ctx.trace.steps[i]).x_m - state_of(ctx.trace.steps[i], k).x_m;
    std::ostringstream os;
    os << "the request to " << party_name(Party::from_vehicle_id(x.request->to_id)) << " at t = " << x.sent_time_s << " s says the ego is "
       << (ahead ? "ahead of" : "behind") << " it (Def. 2." << (ahead ? "1" : "2") << "), but the ego's body was "
       << "wholly " << (ahead ? "behind" : "ahead of") << " it then (centres " << std::abs(lead_m) << " m apart)";
    acc.set_detail(os.str());
  }
}

// P_c against the ego's crossing of the lane line, where the ego merged on the acceptance.
void judge_pc(const MonitorContext& ctx, const PcCheck& c, MarginAccumulator& acc) {
  const CoopExchange& x = ctx.exchanges[c.exchange];
  const bool ahead = x.request->coop_case == CoopCase::kEgoAhead;
  const double required = ahead ? c.pc_m - c.tolerance_m : c.pc_m + c.tolerance_m;
  if (acc.record(step_at(ctx.trace, c.crossing_time_s), c.crossing_time_s, c.margin_m, Party::ego(), required,
                 c.crossing_x_m)) {
    std::ostringstream os;
    os << "the ego crossed the lane line at X = " << c.crossing_x_m << " m (t = " << c.crossing_time_s << " s), "
       << std::abs(c.crossing_x_m - c.pc_m) << " m " << (ahead ? "behind" : "ahead of") << " the P_c = " << c.pc_m
       << " m its request to " << party_name(Party::from_vehicle_id(x.request->to_id)) << " of t = " << x.sent_time_s
       << " s stated (tolerance " << c.tolerance_m << " m): nearer " << party_name(Party::from_vehicle_id(x.request->to_id))
       << " than its acceptance counted on";
    acc.set_detail(os.str());
  }
}

}  // namespace

MonitorOutput monitor_def2_request_truthful(const MonitorContext& ctx) {
  MarginAccumulator acc("def2_request_truthful", ctx.trace.steps.size());
  if (ctx.trace.steps.empty()) return acc.finish();
  for (const CoopExchange& x : ctx.exchanges) judge_order(ctx, x, acc);
  for (const MergeAttempt& a : ctx.attempts.attempts)
    for (const PcCheck& c : a.pc_checks) judge_pc(ctx, c, acc);
  return acc.finish();
}

}  // namespace mg
