// mergeguard_bench (docs/performance.md; bench/figures.sh writes the figures): the standard std-4
// scenario end to end (simulation, planner, every monitor including FCL) as scenarios per
// second on one thread, plus the pieces: RSS distances, one FCL collision check, scenario
// generation, and shrinking a planted failure.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "check/checked_run.h"
#include "core/collision.h"
#include "core/rss.h"
#include "core/scenario.h"
#include "fuzz/properties.h"
#include "fuzz/scenario_gen.h"
#include "fuzz/shrink.h"
#include "rules/check.h"
#include "tests/support/std4_scenario.h"  // the benchmarks' scenario, shared with the tests

namespace {

void BM_Std4Scenario(benchmark::State& state, const std::string& planner) {
  const mg::Scenario& s = mg::test::std4();
  for (auto _ : state) {
    mg::CheckResult r = mg::check_scenario(s, planner);
    benchmark::DoNotOptimize(r.trace_digest);
  }
  state.SetItemsProcessed(state.iterations());  // items_per_second = std-4 scenarios per second
}
BENCHMARK_CAPTURE(BM_Std4Scenario, rcpp, std::string("rcpp"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Std4Scenario, rcpp_coop, std::string("rcpp-coop"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Std4Scenario, tripfield, std::string("tripfield"))->Unit(benchmark::kMillisecond);

// A fuzz-campaign run: generate run i's scenario, check it with rcpp, evaluate the properties.
void BM_FuzzRun(benchmark::State& state) {
  std::uint64_t i = 0;
  const mg::fuzz::CheckFn check = [](const mg::Scenario& s) { return mg::check_scenario(s, "rcpp"); };
  for (auto _ : state) {
    const mg::Scenario s = mg::fuzz::generate_scenario(mg::fuzz::run_seed(1, i++), {}).value();
    benchmark::DoNotOptimize(mg::fuzz::run_properties(s, check, "rcpp", false).failures.size());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FuzzRun)->Unit(benchmark::kMillisecond);

void BM_RssLongitudinal(benchmark::State& state) {
  mg::LongitudinalInput in{13.89, 13.89, 0.0, 0.0, 2.0, 2.0, 4.0, 8.0};
  for (auto _ : state) {
    in.rear_speed_mps += 1e-9;  // defeat constant folding
    benchmark::DoNotOptimize(mg::rss_longitudinal_m(in));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RssLongitudinal);

void BM_RssLateral(benchmark::State& state) {
  mg::LateralInput in{0.0, 0.0, 0.0, 0.0, 2.0, 0.2, 0.8, 0.1};
  for (auto _ : state) {
    in.left_lat_speed_mps -= 1e-9;
    benchmark::DoNotOptimize(mg::rss_lateral_m(in));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RssLateral);

// One pre-filtered pair check between two steps where the boxes are close (FCL runs).
void BM_CollisionCheck(benchmark::State& state) {
  const mg::BoxPose a0{0.0, -1.6, 0.05, 4.8, 1.9, 1.5}, a1{0.4, -1.55, 0.05, 4.8, 1.9, 1.5};
  const mg::BoxPose b0{3.0, 0.0, 0.0, 4.8, 1.9, 1.5}, b1{3.4, 0.0, 0.0, 4.8, 1.9, 1.5};
  for (auto _ : state) benchmark::DoNotOptimize(mg::check_box_pair(a0, a1, b0, b1).margin_m);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CollisionCheck);

void BM_GenerateScenario(benchmark::State& state) {
  std::uint64_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(mg::fuzz::generate_scenario(mg::fuzz::run_seed(1, i++), {}).value());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_GenerateScenario);

// Shrinking a planted failure (a main-lane vehicle starting within 30 m of the ego) from a
// generated scenario with 6 vehicles down to the one-vehicle minimum; the planted check is
// instantaneous, so this measures the shrinker itself (tree walk, loader validation).
void BM_ShrinkPlantedFailure(benchmark::State& state) {
  auto planted = [](const mg::Scenario& s) {
    for (const mg::MainVehicle& v : s.vehicles)
      if (std::abs(v.x_m - s.ego.x_m) < 30.0) return true;
    return false;
  };
  std::uint64_t i = 0;
  auto start = mg::fuzz::generate_scenario(mg::fuzz::run_seed(1, i), {});
  while (start.value().vehicles.size() < 6 || !planted(start.value()))
    start = mg::fuzz::generate_scenario(mg::fuzz::run_seed(1, ++i), {});
  int steps = 0;
  for (auto _ : state) steps = mg::fuzz::shrink_scenario(start, planted, {}).steps;
  state.counters["shrink_steps"] = steps;
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ShrinkPlantedFailure)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
