// Trace loading (issue #15; figures in docs/performance.md, "Trace loading (issue 15)"): parse
// and strictly load a 10-vehicle, 60 s, 50 Hz trace (3,001 steps, 180,060 numbers of state)
// from its text, as `mergeguard check-trace` does with a file. The text is built once.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "core/observed_trace_json.h"

namespace {

mg::ObservedTrace trace_10veh_60s_50hz() {
  mg::ObservedTrace t;
  t.name = "bench_10veh_60s_50hz";
  t.source = "bench/trace_bench.cpp";
  for (int k = 0; k < 10; ++k) {
    mg::VehicleDeclaration d;
    d.id = k;
    d.v2v_capable = k % 2 == 0;
    t.vehicles.push_back(d);
  }
  const double step_s = 0.02;
  for (int i = 0; i <= 3000; ++i) {
    mg::ObservedStep s;
    s.time_s = i * step_s;
    for (int k = 0; k < 10; ++k) {
      // Smooth motion with full-precision doubles, as a simulator writes them.
      const double v = 20.0 + 0.1 * k + std::sin(0.05 * i + k);
      const double y = k == 0 ? -3.5 + 3.5 / (1.0 + std::exp(-(s.time_s - 30.0))) : 0.0;
      s.vehicles.push_back({-100.0 + 15.0 * k + v * s.time_s, y, 0.01 * std::cos(0.1 * i), v, 0.0, 0.05 * std::cos(0.05 * i + k)});
    }
    t.steps.push_back(std::move(s));
  }
  for (int i = 0; i < 20; ++i) {
    mg::ChannelEvent e;
    e.time_s = 10.0 + i;
    e.kind = i % 2 == 0 ? mg::ChannelEventKind::kSent : mg::ChannelEventKind::kDelivered;
    e.message.to_id = 2;
    e.message.sent_time_s = 10.0 + i - i % 2;
    e.message.pc_m = 250.0;
    if (i % 2 == 1) e.message.delivered_time_s = e.time_s;
    t.channel.push_back(e);
  }
  t.planner_annotations = {{"decisions", {{"t_s", 10.0}, {"mode", "merge"}}}};
  return t;
}

void BM_LoadTrace_10veh_60s_50Hz(benchmark::State& state) {
  const std::string text = mg::observed_trace_to_text(trace_10veh_60s_50hz());
  for (auto _ : state) {
    const mg::ObservedTrace t = mg::observed_trace_from_text(text, "bench.json");
    benchmark::DoNotOptimize(t.steps.back().vehicles.back().x_m);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
  state.counters["text_MB"] = static_cast<double>(text.size()) / 1e6;
}
BENCHMARK(BM_LoadTrace_10veh_60s_50Hz)->Unit(benchmark::kMillisecond);

// The share of the strict reading alone: the same text already parsed into a JSON value.
void BM_LoadTraceFromJsonValue_10veh_60s_50Hz(benchmark::State& state) {
  const nlohmann::json j = nlohmann::json::parse(mg::observed_trace_to_text(trace_10veh_60s_50hz()));
  for (auto _ : state) {
    const mg::ObservedTrace t = mg::observed_trace_from_json(j, "bench.json");
    benchmark::DoNotOptimize(t.steps.back().vehicles.back().x_m);
  }
}
BENCHMARK(BM_LoadTraceFromJsonValue_10veh_60s_50Hz)->Unit(benchmark::kMillisecond);

// The JSON parse alone, without the repeated-key check the loader asks for (its cost is the
// difference to BM_LoadTrace minus BM_LoadTraceFromJsonValue).
void BM_ParseTraceTextOnly_10veh_60s_50Hz(benchmark::State& state) {
  const std::string text = mg::observed_trace_to_text(trace_10veh_60s_50hz());
  for (auto _ : state) benchmark::DoNotOptimize(nlohmann::json::parse(text).size());
}
BENCHMARK(BM_ParseTraceTextOnly_10veh_60s_50Hz)->Unit(benchmark::kMillisecond);

}  // namespace
