// The versioned JSON format of an observable trace (docs/trace_format.md, schema
// docs/trace.schema.json): one writer and one strict loader. Everything is validated here, once;
// the rule monitors may trust a loaded ObservedTrace (declared ids, sizes and limits in the
// scenario's ranges, strictly increasing step times, one state per declared vehicle per step,
// non-decreasing channel times, messages between declared vehicles).
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "core/observed_trace.h"

namespace mg {

inline constexpr const char* kTraceFormatName = "mergeguard-trace";
// Hostile-input bounds (documented in docs/trace_format.md): what one trace may cost to load.
inline constexpr std::size_t kMaxTraceSteps = 1000000;          // as the simulator's step bound
inline constexpr std::size_t kMaxTraceStates = 20000000;        // steps x vehicles
inline constexpr std::size_t kMaxChannelEvents = 1000000;
// The largest speed (either axis, and a request's v_o*) a trace may hold: no road vehicle's is
// higher, and a trace that holds one is broken. The simulator keeps below it (sim/behaviour.h).
inline constexpr double kMaxTraceSpeedMps = 150.0;

// Serialises every field; NaN message fields (e.g. the pc_m of an accept, the delivered_time_s
// of a message not delivered) are written as null. Doubles round-trip bit-exactly.
nlohmann::json observed_trace_to_json(const ObservedTrace& t);
// Strict reading: unknown keys, wrong types, non-finite or out-of-range numbers, an unsupported
// format or version, inconsistent steps or channel events raise InputError("<source>",
// "/json/path", what).
ObservedTrace observed_trace_from_json(const nlohmann::json& j, const std::string& source);
// Text form: one line per vehicle, step and channel event (compact, diffable).
std::string observed_trace_to_text(const ObservedTrace& t);
// Parses the text (NaN/Infinity literals, repeated keys, nesting and size bounds rejected as for
// every input) and loads it; `source` names it in errors.
ObservedTrace observed_trace_from_text(const std::string& text, const std::string& source);
ObservedTrace load_observed_trace(const std::string& path);
// Writes atomically (core/atomic_file.h).
void write_observed_trace(const ObservedTrace& t, const std::string& path);

}  // namespace mg
