// The exec planner protocol's cost (docs/performance.md; figures by bench/figures.sh): one
// planner call through the trivial C++ planner process (tests/planner/exec_helpers/, mode echo),
// the pieces of that call on mergeguard's side (writing the observe request, checking the
// command), and std-4 scenarios per second through it on one thread.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <ctime>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "check/checked_run.h"
#include "core/scenario.h"
#include "planner/exec_planner.h"
#include "planner/exec_protocol.h"
#include "tests/support/std4_scenario.h"  // the benchmarks' scenario, shared with the tests

#ifdef MG_FAKE_EXEC_PLANNER
namespace {

const std::string kEcho = std::string("exec:") + MG_FAKE_EXEC_PLANNER + " echo";

void BM_ExecPlannerCall(benchmark::State& state) {
  const mg::WorldSnapshot world = mg::initial_snapshot(mg::test::std4());
  auto planner = mg::make_exec_planner(kEcho);
  benchmark::DoNotOptimize(planner->plan(world).path.size());  // reset outside the timing
  for (auto _ : state) benchmark::DoNotOptimize(planner->plan(world).path.size());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ExecPlannerCall)->Unit(benchmark::kMicrosecond);

void BM_ExecObserveRequest(benchmark::State& state) {
  const mg::WorldSnapshot world = mg::initial_snapshot(mg::test::std4());
  for (auto _ : state) benchmark::DoNotOptimize(mg::observe_request(world).size());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ExecObserveRequest)->Unit(benchmark::kMicrosecond);

void BM_ExecParseCommand(benchmark::State& state) {
  const std::string reply =
      R"({"type":"command","path":[[20.0,-3.5],[120.0,-3.5]],"target_speed_mps":20.0,"accel_limit_mps2":2.0,"annotation":{"mode":"echo","pid":4242}})";
  for (auto _ : state)
    benchmark::DoNotOptimize(mg::parse_command_reply(reply, mg::initial_snapshot(mg::test::std4())).path.size());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ExecParseCommand)->Unit(benchmark::kMicrosecond);

// CPU seconds (user + system) a process has used so far, from /proc (clock ticks).
double process_cpu_s(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::istringstream rest(stat.substr(stat.rfind(')') + 2));
  std::string field;
  for (int k = 3; k < 14; ++k) rest >> field;  // state ... cmajflt: fields 3 to 13
  double utime = 0.0, stime = 0.0;
  rest >> utime >> stime;
  return (utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

// items_per_second counts this process's CPU time only; the planner process's CPU per scenario
// is the counter planner_cpu_ms, so that one core runs 1000 / (CPU ms + planner_cpu_ms)
// scenarios per second (the counter one_core_per_s).
void BM_Std4ScenarioExec(benchmark::State& state) {
  const mg::PlanOutput out = mg::make_exec_planner(kEcho)->plan(mg::initial_snapshot(mg::test::std4()));
  const long pid = out.annotation->to_json().at("pid").get<long>();
  const double planner_start_s = process_cpu_s(pid);
  const auto own_start = std::clock();
  for (auto _ : state) benchmark::DoNotOptimize(mg::check_scenario(mg::test::std4(), kEcho).trace_digest);
  const double n = static_cast<double>(state.iterations());
  const double planner_ms = 1e3 * (process_cpu_s(pid) - planner_start_s) / n;
  const double own_ms = 1e3 * static_cast<double>(std::clock() - own_start) / CLOCKS_PER_SEC / n;
  state.counters["planner_cpu_ms"] = planner_ms;
  state.counters["one_core_per_s"] = 1e3 / (own_ms + planner_ms);
  state.SetItemsProcessed(state.iterations());  // items_per_second = std-4 scenarios per second
}
BENCHMARK(BM_Std4ScenarioExec)->Unit(benchmark::kMillisecond);

}  // namespace
#endif
