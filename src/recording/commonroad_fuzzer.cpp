// libFuzzer target for CommonRoad XML recordings (docs/fuzzing.md "Coverage-guided fuzzing"):
// every input goes the way `mergeguard audit` reads a recording: the strict XML adapter and the
// CommonRoad reader, the road reconstruction from the lanelet network and, when both accept it,
// the whole audit (merges found, each judged with its sensitivity sweep) and its index report. A
// rejected input (InputError) is fine; anything else escaping, a crash or a sanitizer report is a
// bug. An executable beside the reader, not part of mg_recording: only it links the audit.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "audit/audit_profile.h"
#include "audit/audit_report.h"
#include "audit/recording_audit.h"
#include "core/input_error.h"
#include "recording/commonroad_reader.h"
#include "recording/road_layout.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const mg::AuditProfile profile = mg::default_audit_profile();
  try {
    const mg::Recording r = mg::parse_recording(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz input");
    const std::optional<mg::RoadLayout> road = mg::find_road_layout(r);
    const mg::RecordingAudit audit = road ? mg::audit_recording(r, *road, profile) : mg::audit_recording_without_lane_join(r, profile);
    // The index carries the recording's own strings (benchmark id, obstacle types) into JSON and
    // Markdown.
    static_cast<void>(mg::audit_index_json(audit).dump());
    static_cast<void>(mg::audit_index_markdown(audit));
  } catch (const mg::InputError&) {
  }
  return 0;
}
