#include "fuzz/guided_search.h"

#include <algorithm>
#include <atomic>
#include <numeric>
#include <random>
#include <set>
#include <thread>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "fuzz/scenario_gen.h"
#include "fuzz/shrink.h"

namespace mg::fuzz {
namespace {

ScenarioSpec spec_of_seed(std::uint64_t seed) { return generate_spec(seed, GenConfig{}).value(); }

RC_GTEST_PROP(GuidedSearch, APerturbedSpecStaysInsideEveryKnobRangeAndAssemblesToALoadableScenario,
              (std::uint64_t spec_seed, std::uint64_t step_seed)) {
  const ScenarioSpec parent = spec_of_seed(spec_seed);
  const Perturbation steps = draw_perturbation(parent, rc::Random(step_seed));
  RC_ASSERT(steps.size() >= 1u);
  RC_ASSERT(steps.size() <= 3u);
  const ScenarioSpec child = apply_perturbation(parent, steps);
  const auto table = knobs();
  int changed = 0;
  for (std::size_t k = 0; k < table.size(); ++k) {
    for (std::size_t v = 0; v < (table[k].per_vehicle ? child.vehicles.size() : 1); ++v) {
      const double before = *knob_value(parent, static_cast<int>(k), v);
      const double after = *knob_value(child, static_cast<int>(k), v);
      if (after == before) continue;
      ++changed;
      RC_ASSERT(after >= table[k].range.lo);
      RC_ASSERT(after <= table[k].range.hi);
    }
  }
  RC_ASSERT(changed <= static_cast<int>(steps.size()));
  RC_ASSERT(is_loadable(assemble_scenario(child)));
}

TEST(GuidedSearch, AStepIsSmallRelativeToTheKnobRange) {
  // Steps are 1 %, 3 % or 10 % of the range (Gaussian): over many draws, none moves a knob by
  // more than half of its range, and most (over 70 %) move it by less than a tenth.
  const auto table = knobs();
  int small = 0, total = 0;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    for (const KnobStep& step : draw_perturbation(spec_of_seed(seed), rc::Random(seed * 7919))) {
      const RealRange& r = table.at(static_cast<std::size_t>(step.knob)).range;
      EXPECT_LE(std::abs(step.delta), 0.5 * (r.hi - r.lo)) << table[static_cast<std::size_t>(step.knob)].name;
      small += std::abs(step.delta) < 0.1 * (r.hi - r.lo) ? 1 : 0;
      ++total;
    }
  }
  EXPECT_GT(small, total * 7 / 10);
}

TEST(GuidedSearch, AStepOnAVehicleThatShrinkingRemovedIsIgnored) {
  ScenarioSpec spec = spec_of_seed(3);
  spec.vehicles.clear();
  const Perturbation steps = {{static_cast<int>(knobs().size()) - 1, 2, 1.0}};
  EXPECT_EQ(apply_perturbation(spec, steps).vehicles.size(), 0u);
}

Elite elite(double margin, std::uint64_t run) {
  const auto spec = generate_spec(run, GenConfig{});
  return {margin, run, std::make_shared<const Candidate>(Candidate{spec.value(), spec})};
}

TEST(ElitePool, KeepsTheLowestMarginsPerRuleWithTiesToTheLowerRun) {
  ElitePool pool(2);
  pool.offer("a", elite(3.0, 1));
  pool.offer("a", elite(1.0, 5));
  pool.offer("a", elite(1.0, 2));
  pool.offer("a", elite(2.0, 3));
  pool.offer("b", elite(9.0, 4));
  const auto& a = pool.by_rule().at("a");
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].run, 2u);
  EXPECT_EQ(a[1].run, 5u);
  EXPECT_EQ(pool.by_rule().at("b").size(), 1u);
}

TEST(ElitePool, PickCanReachEveryRuleAndEveryElite) {
  ElitePool pool(2);
  pool.offer("a", elite(1.0, 1));
  pool.offer("a", elite(2.0, 2));
  pool.offer("b", elite(1.0, 3));
  std::set<std::uint64_t> picked;
  rc::Random random(42);
  for (int n = 0; n < 200; ++n) picked.insert(pool.pick(random).run);
  EXPECT_EQ(picked, (std::set<std::uint64_t>{1, 2, 3}));
}

// Batches of 4 runs, lag 2: run j of batch k reads the pool after batches 0..k-2.
//   batch:   0         1         2         3
//   runs:  0 1 2 3 | 4 5 6 7 | 8 ...    | 12 ...
//   run 12 (batch 3) sees the offers of runs 0..7, never of 8..11, whatever the order.
TEST(PoolHistory, AGuidedRunSeesExactlyTheBatchesBeforeItsLagInAnyCompletionOrder) {
  const GuidedParams params{0.5, 16, 4, 2};
  for (unsigned shuffle_seed = 1; shuffle_seed <= 5; ++shuffle_seed) {
    PoolHistory history(params);
    std::vector<std::uint64_t> order(12);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(shuffle_seed));
    std::shared_ptr<const ElitePool> seen;
    std::thread waiter([&] { seen = history.pool_for(12, [] { return false; }); });
    for (std::uint64_t j : order) history.complete(j, {{"r", elite(static_cast<double>(j), j)}});
    waiter.join();
    ASSERT_NE(seen, nullptr);
    std::vector<std::uint64_t> runs;
    for (const Elite& e : seen->by_rule().at("r")) runs.push_back(e.run);
    EXPECT_EQ(runs, (std::vector<std::uint64_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  }
}

TEST(PoolHistory, AWaitingRunGivesUpWhenTheCampaignAborts) {
  PoolHistory history(GuidedParams{0.5, 4, 4, 2});
  std::atomic<bool> abort{false};
  std::shared_ptr<const ElitePool> seen = std::make_shared<const ElitePool>();
  std::thread waiter([&] { seen = history.pool_for(100, [&] { return abort.load(); }); });
  history.complete(0, {});
  abort = true;
  history.wake();
  waiter.join();
  EXPECT_EQ(seen, nullptr);
}

TEST(GuidedSearch, WarmUpRunsAreNeverGuidedAndAboutTheShareOfTheRestAre) {
  const GuidedParams params{0.5, 4, 64, 2};
  int guided = 0;
  for (std::uint64_t i = 0; i < 128; ++i) EXPECT_FALSE(is_guided_run(7, i, i, params));
  for (std::uint64_t i = 128; i < 10128; ++i) guided += is_guided_run(7, i, i, params) ? 1 : 0;
  EXPECT_NEAR(guided, 5000, 250);
}

}  // namespace
}  // namespace mg::fuzz
