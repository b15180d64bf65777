#include "fuzz/shrink.h"

#include <chrono>

#include "core/input_error.h"

namespace mg::fuzz {

bool is_loadable(const Scenario& s) {
  try {
    scenario_from_json(scenario_to_json(s), "shrink candidate");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

ShrinkOutcome shrink_scenario(const rc::Shrinkable<Scenario>& start,
                              const std::function<bool(const Scenario&)>& keeps_failure,
                              const ShrinkBudget& budget) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(budget.max_seconds);
  auto out_of_budget = [&](int attempts) {
    return attempts >= budget.max_attempts || Clock::now() >= deadline ||
           (budget.stop != nullptr && budget.stop->load());
  };
  rc::Shrinkable<Scenario> current = start;
  Scenario current_value = current.value();
  ShrinkOutcome outcome;
  bool improved = true;
  while (improved && !out_of_budget(outcome.attempts)) {
    improved = false;
    auto shrinks = current.shrinks();
    while (auto candidate = shrinks.next()) {
      if (out_of_budget(outcome.attempts)) break;
      const Scenario value = candidate->value();
      if (value == current_value || !is_loadable(value)) continue;
      ++outcome.attempts;
      if (keeps_failure(value)) {
        current = *candidate;
        current_value = value;
        ++outcome.steps;
        improved = true;
        break;
      }
    }
    if (!improved && !out_of_budget(outcome.attempts)) outcome.minimal = true;
  }
  outcome.scenario = current_value;
  return outcome;
}

}  // namespace mg::fuzz
