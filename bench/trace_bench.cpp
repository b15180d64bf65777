// Trace loading and judging (docs/performance.md; figures by bench/figures.sh): parse and
// strictly load a 10-vehicle, 60 s, 50 Hz trace (3,001 steps, 180,060 numbers of state) from its
// text, and load it from a file and judge it by every rule, as `mergeguard check-trace` does. The
// trace is built once.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/observed_trace_json.h"
#include "rules/check.h"

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

// A merge as check-trace sees one: the ego drives 60 s in a 1.5 km side lane beside nine main-lane
// vehicles 40 m apart (speeds and positions consistent, full-precision doubles) and moves over
// into the gap between vehicles 4 and 5 from t = 20 s (a logistic lateral profile of about 4 s),
// after a V2V request and its acceptance.
mg::ObservedTrace merging_trace_10veh_60s_50hz() {
  mg::ObservedTrace t;
  t.name = "bench_merge_10veh_60s_50hz";
  t.source = "bench/trace_bench.cpp";
  t.road.side_lane_end_x_m = 1500.0;
  for (int k = 0; k < 10; ++k) {
    mg::VehicleDeclaration d;
    d.id = k;
    d.v2v_capable = true;
    t.vehicles.push_back(d);
  }
  const double w = t.road.lane_width_m;
  for (int i = 0; i <= 3000; ++i) {
    mg::ObservedStep s;
    s.time_s = i * 0.02;
    const double tt = s.time_s;
    // Ego: 22 m/s, lateral logistic from -W to 0 centred at t = 22 s.
    const double e = std::exp(-2.0 * (tt - 22.0));
    const double y = -w + w / (1.0 + e);
    const double vy = w * 2.0 * e / ((1.0 + e) * (1.0 + e));
    s.vehicles.push_back({-10.0 + 22.0 * tt, y, std::atan2(vy, 22.0), 22.0, vy, 0.0});
    for (int k = 1; k < 10; ++k) {
      const double phase = 0.3 * tt + k;
      const double v = 22.0 + 0.3 * std::sin(phase);
      const double x = 40.0 * (k - 5) + 10.0 + 22.0 * tt - std::cos(phase) + std::cos(static_cast<double>(k));
      s.vehicles.push_back({x, 0.0, 0.0, v, 0.0, 0.09 * std::cos(phase)});
    }
    t.steps.push_back(std::move(s));
  }
  mg::V2vMessage request;
  request.from_id = 0;
  request.to_id = 4;
  request.sent_time_s = 18.0;
  request.pc_m = 470.0;
  request.d_lon_star_m = 15.0;
  request.target_speed_mps = 21.0;
  t.channel.push_back({18.0, mg::ChannelEventKind::kSent, request});
  request.delivered_time_s = 18.1;
  t.channel.push_back({18.1, mg::ChannelEventKind::kDelivered, request});
  mg::V2vMessage accept;
  accept.type = mg::MessageType::kAccept;
  accept.from_id = 4;
  accept.to_id = 0;
  accept.sent_time_s = 18.2;
  t.channel.push_back({18.2, mg::ChannelEventKind::kSent, accept});
  accept.delivered_time_s = 18.3;
  t.channel.push_back({18.3, mg::ChannelEventKind::kDelivered, accept});
  t.planner_annotations = {{"planner", "bench"},
                           {"decisions", nlohmann::json::array({{{"time_s", 18.0}, {"mode", "def2_request"}}})}};
  return t;
}

// What `mergeguard check-trace TRACE.json --json` costs without process start-up and printing:
// read the file (parse, strict load) and judge it by every rule. The file is written once.
void BM_ReadAndCheckTrace_10veh_60s_50Hz(benchmark::State& state) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("mg_bench_trace_" + std::to_string(::getpid()) + ".json");
  const mg::ObservedTrace written = merging_trace_10veh_60s_50hz();
  mg::write_observed_trace(written, path.string());
  std::size_t violated = 0;
  for (auto _ : state) {
    const mg::CheckResult r = mg::check_observed(mg::load_observed_trace(path.string()));
    violated = 0;
    for (const mg::RuleResult& rule : r.rules) violated += rule.holds ? 0 : 1;
    benchmark::DoNotOptimize(r.holds);
  }
  state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  state.counters["rules_violated"] = static_cast<double>(violated);
  std::filesystem::remove(path);
}
BENCHMARK(BM_ReadAndCheckTrace_10veh_60s_50Hz)->Unit(benchmark::kMillisecond);

// The judgement alone, on the loaded trace.
void BM_CheckTraceOnly_10veh_60s_50Hz(benchmark::State& state) {
  const mg::ObservedTrace t = mg::observed_trace_from_text(mg::observed_trace_to_text(merging_trace_10veh_60s_50hz()), "bench.json");
  for (auto _ : state) benchmark::DoNotOptimize(mg::check_observed(t).holds);
}
BENCHMARK(BM_CheckTraceOnly_10veh_60s_50Hz)->Unit(benchmark::kMillisecond);

}  // namespace
