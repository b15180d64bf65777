// Auditing a recording (docs/audit.md "Performance"): read, validate, rebuild the road of and
// audit the largest public recording, USA_US101-4_1_T-1 (607 KB, 22 vehicles), and the zipper
// recording (its two judged merges each get a compliance frontier and a sensitivity sweep), as
// `mergeguard audit` does without writing reports; and the compliance frontier of the cut-in of
// USA_US101-3_3_T-1 (undetermined, so the audit gives it none; its trace has the most vehicles
// of the public merges) as if it were judged: the frontier's bisections are most of a judged
// merge's cost. Target: under 2 s and 100 MB peak RSS for the large recording.
#include <benchmark/benchmark.h>

#include <string>

#include "audit/censoring.h"
#include "audit/compliance_frontier.h"
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

void BM_FrontierUS101_3_3(benchmark::State& state) {
  const mg::Recording r = mg::load_recording(public_recording("USA_US101-3_3_T-1.xml"));
  const mg::RoadLayout road = mg::build_road_layout(r);
  const mg::RecordingAudit a = mg::audit_recording(r, road, mg::default_audit_profile());
  const mg::ObservedTrace& trace = a.merges.at(0).merge.trace;
  const mg::JudgeAt judge = [&](double rho_s, double scale) {
    const mg::CheckResult c = mg::check_observed(mg::with_profile_variation(trace, rho_s, scale));
    mg::VariedJudgement j;
    j.holds = c.holds;
    if (const mg::RuleResult* d = mg::deciding_rule(c)) j.first_rule = d->rule_id;
    return j;
  };
  for (auto _ : state) {
    const mg::ComplianceFrontier f = mg::compliance_frontier(judge, 1.0, 4.0, {0.75, 1.0, 1.25});
    benchmark::DoNotOptimize(f.words.data());
  }
  state.counters["vehicles"] = static_cast<double>(trace.vehicles.size());
}

}  // namespace

BENCHMARK(BM_AuditUS101_4_1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AuditZipper)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrontierUS101_3_3)->Unit(benchmark::kMillisecond);
