// Auditing a recording (docs/audit.md, docs/performance.md; figures by bench/figures.sh):
// read, validate, rebuild the road of, and audit the public 607 KB NGSIM recording
// USA_US101-4_1_T-1 (22 vehicles), and the zipper recording whose three merges are all violated
// (so each is also judged 12 more times by the sensitivity sweep), as `mergeguard audit` does
// without writing reports. Target: under 2 s on one core for the 600 KB recording.
#include <benchmark/benchmark.h>

#include <string>

#include "audit/recording_audit.h"
#include "recording/commonroad_reader.h"
#include "recording/road_layout.h"

namespace {

std::string public_recording(const char* file) { return std::string(MG_SOURCE_DIR) + "/tests/data/commonroad/" + file; }

void audit_file(benchmark::State& state, const char* file) {
  const std::string path = public_recording(file);
  std::size_t merges = 0;
  for (auto _ : state) {
    const mg::Recording r = mg::load_recording(path);
    const mg::RoadLayout road = mg::build_road_layout(r);
    const mg::RecordingAudit a = mg::audit_recording(r, road, mg::default_audit_profile());
    merges = a.merges.size();
    benchmark::DoNotOptimize(a.merges.data());
  }
  state.counters["merges"] = static_cast<double>(merges);
}

void BM_AuditUS101_4_1(benchmark::State& state) { audit_file(state, "USA_US101-4_1_T-1.xml"); }
void BM_AuditZipper(benchmark::State& state) { audit_file(state, "ZAM_Zip-1_56_T-1.xml"); }

}  // namespace

BENCHMARK(BM_AuditUS101_4_1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AuditZipper)->Unit(benchmark::kMillisecond);
