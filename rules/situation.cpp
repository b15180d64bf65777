#include "rules/situation.h"

namespace mg {

Situation observe_situation(const ObservedTrace& t, const RuleParams& p) {
  Situation s;
  s.phases = observe_merge_phases(t, p);
  s.exchanges = coop_exchanges(t, p);
  s.around.reserve(t.steps.size());
  for (std::size_t i = 0; i < t.steps.size(); ++i) s.around.push_back(gap_around_ego(t, i));
  s.attempts = observe_merge_attempts(t, p, s.phases, s.exchanges, s.around);
  s.row = compute_right_of_way(t, s.attempts);
  return s;
}

}  // namespace mg
