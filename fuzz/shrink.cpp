#include "fuzz/shrink.h"

#include <chrono>
#include <optional>

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

namespace {

Scenario without(const Scenario& s, std::size_t i, std::optional<std::size_t> j = std::nullopt) {
  Scenario out = s;
  out.vehicles.clear();
  for (std::size_t k = 0; k < s.vehicles.size(); ++k)
    if (k != i && (!j || k != *j)) out.vehicles.push_back(s.vehicles[k]);
  return out;
}

// After the tree descent: a case that keeps three or more vehicles tries removing each vehicle,
// then each pair, directly (the others stay where they are, so every lane still starts
// RSS-safe); the tree's own removals go in list order and can miss a vehicle that only mattered
// together with one already gone. Returns true when no removal kept the failure.
template <typename OutOfBudget>
bool remove_vehicles(Scenario& current, const std::function<bool(const Scenario&)>& keeps_failure, ShrinkOutcome& outcome,
                     const OutOfBudget& out_of_budget) {
  auto try_candidate = [&](const Scenario& candidate) {
    if (out_of_budget(outcome.attempts) || !is_loadable(candidate)) return false;
    ++outcome.attempts;
    if (!keeps_failure(candidate)) return false;
    current = candidate;
    ++outcome.steps;
    return true;
  };
  bool removed = true;
  while (removed && current.vehicles.size() >= 3) {
    removed = false;
    const std::size_t n = current.vehicles.size();
    for (std::size_t i = 0; i < n && !removed; ++i) removed = try_candidate(without(current, i));
    for (std::size_t i = 0; i < n && !removed; ++i)
      for (std::size_t j = i + 1; j < n && !removed; ++j) removed = try_candidate(without(current, i, j));
    if (out_of_budget(outcome.attempts)) return false;
  }
  return true;
}

}  // namespace

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
  if (outcome.minimal) outcome.minimal = remove_vehicles(current_value, keeps_failure, outcome, out_of_budget);
  outcome.scenario = current_value;
  return outcome;
}

}  // namespace mg::fuzz
